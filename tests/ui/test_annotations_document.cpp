// The annotations document: one undo step per edit (a drag merged into one), saves that reload
// identically, a damaged file never written over, and recovery only onto the stream it belongs to.
#include "support/percept_kinds.h"
#include "support/test_suite.h"
#include "ui/document/editing_session.h"

#include "support/test_files.h"
#include "support/window_waits.h"

#include "visioncore/percepts/percept_set.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::ui;
using namespace fieldsight::test;

namespace {

/// The first kind drawn as `form` (the test names no kind: it takes them from the registry).
/// `frame` with one more object of `kind` drawn as `shape`.
FrameAnnotation withShape(FrameAnnotation frame, const PerceptKind& kind, const EditShape& shape)
{
    PerceptEntry& entry = frame.truth.entry(kind);
    std::vector<EditShape> shapes = entry.shapes();
    shapes.push_back(shape);
    entry.setShapes(shapes);
    frame.truth.markPresent(entry);
    return frame;
}

/// A copy of the sample stream (without annotations) in `dir`.
QString copyOfSample(const QTemporaryDir& dir, const QString& name)
{
    return test::copyFolderFiles(sampleStream(), dir.filePath(name), test::isNotAnnotations);
}

} // namespace

class TestAnnotationsDocument : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // The bundled streams are part of the project: a wrong path must fail, not skip.
        QVERIFY2(QFileInfo(sampleStream()).isDir(),
                 qPrintable("the bundled sample stream is missing: " + sampleStream()));
        m_a = copyOfSample(m_dir, "a");
        m_b = copyOfSample(m_dir, "b");
    }

    void editsUndoRedoAndADragIsOneStep()
    {
        EditingSession session;
        QVERIFY(session.open(m_a).ok());
        AnnotationsDocument& doc = session.annotations();
        QCOMPARE(doc.path(), QDir(m_a).filePath("annotations.json"));
        const PerceptKind* circle = test::kindOfForm(doc, ShapeForm::Circle);
        QVERIFY(circle);
        const std::string frame = session.stream().frameName(0).toStdString();

        QSignalSpy changed(&doc, &AnnotationsDocument::changed);
        QVERIFY(doc.editFrame(frame, withShape({}, *circle, {{{50, 60}}, 8}), "Add"));
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.last().at(0).toStringList(), QStringList{QString::fromStdString(frame)});
        QVERIFY(doc.modified());
        // The same content again is no edit.
        QVERIFY(!doc.editFrame(frame, *doc.frame(frame), "Nothing"));

        // A drag: three moves with one merge id are one undo step ending where the drag did.
        const int drag = doc.newMerge();
        for (double x : {55.0, 60.0, 65.0})
            QVERIFY(doc.editFrame(frame, withShape({}, *circle, {{{x, 60}}, 8}), "Move", drag));
        QCOMPARE(doc.undoStack().count(), 2);
        QCOMPARE(doc.frame(frame)->truth.find(*circle)->shapes().front().points.front().x, 65.0);
        doc.undoStack().undo();
        QCOMPARE(doc.frame(frame)->truth.find(*circle)->shapes().front().points.front().x, 50.0);
        doc.undoStack().undo();
        QVERIFY(doc.frame(frame) == nullptr);
        QVERIFY(!doc.modified());
        doc.undoStack().redo();
        doc.undoStack().redo();
        QCOMPARE(doc.frame(frame)->truth.find(*circle)->shapes().front().points.front().x, 65.0);

        // The frame worker draws the document's truth: the version follows every edit.
        const auto version = doc.version();
        QVERIFY(version->truth.count(frameStem(frame)));
        doc.undoStack().undo();
        QVERIFY(doc.version() != version);
    }

    void savesAtomicallyAndReloadsIdentically()
    {
        EditingSession session;
        QVERIFY(session.open(m_a).ok());
        AnnotationsDocument& doc = session.annotations();
        const std::string f0 = session.stream().frameName(0).toStdString();
        const std::string f1 = session.stream().frameName(1).toStdString();
        FrameAnnotation first;
        for (ShapeForm form :
             {ShapeForm::Circle, ShapeForm::Box, ShapeForm::Polyline, ShapeForm::Segment}) {
            const PerceptKind* kind = test::kindOfForm(doc, form);
            QVERIFY(kind);
            const EditShape shape = form == ShapeForm::Circle ? EditShape{{{40, 50}}, 6}
                                                              : EditShape{{{10, 20}, {30, 60}}, 0};
            first = withShape(first, *kind, shape);
        }
        first.done = true;
        first.setFlags(test::kindOfForm(doc, ShapeForm::Circle)->truth_key, 0,
                       ObjectFlags{true, 3, true, true, false});
        FrameAnnotation second;
        second.reviewed.insert(std::string(test::kindOfForm(doc, ShapeForm::Box)->truth_key));
        AnnotationsDocument::FrameEdits edits;
        edits.emplace(f0, first);
        edits.emplace(f1, second);
        QVERIFY(doc.edit("Two frames", edits));
        QVERIFY(doc.save().ok());
        QVERIFY(!doc.modified());

        EditingSession again;
        QVERIFY(again.open(m_a).ok());
        QVERIFY(again.annotations().loadProblem().isEmpty());
        QVERIFY(again.annotations().frame(f0) && *again.annotations().frame(f0) == first);
        QVERIFY(again.annotations().frame(f1) && *again.annotations().frame(f1) == second);
        QCOMPARE(again.annotations().annotations().toJson(again.annotations().kinds()),
                 doc.annotations().toJson(doc.kinds()));
        QFile::remove(QDir(m_a).filePath("annotations.json"));
    }

    void aDamagedFileIsNeverWrittenOver()
    {
        const QString path = QDir(m_b).filePath("annotations.json");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("{\"format\": \"fieldsight-annotations/1\", \"frames\": [");
        }
        const QByteArray damaged = fileBytes(path);
        EditingSession session;
        QVERIFY(session.open(m_b).ok());
        AnnotationsDocument& doc = session.annotations();
        QVERIFY(doc.loadProblem().contains("annotations.json"));
        const std::string f0 = session.stream().frameName(0).toStdString();
        FrameAnnotation done;
        done.done = true;
        QVERIFY(doc.editFrame(f0, done, "Done"));
        const Status saved = doc.save();
        QVERIFY(!saved.ok());
        QVERIFY(QString::fromStdString(saved.error().message).contains("annotations.json"));
        QCOMPARE(fileBytes(path), damaged);
        QVERIFY(doc.modified());
        const QString other = m_dir.filePath("fixed.json");
        QVERIFY(doc.saveAs(other).ok());
        QCOMPARE(fileBytes(path), damaged);
        QVERIFY(!doc.modified());
        QFile::remove(path);
    }

    void aRecoveryGoesBackOnlyToItsOwnStream()
    {
        const QString recovery = m_dir.filePath("recovery");
        std::string f0;
        {
            EditingSession session;
            session.annotations().setRecoveryDir(recovery);
            QVERIFY(session.open(m_a).ok());
            f0 = session.stream().frameName(0).toStdString();
            FrameAnnotation done;
            done.done = true;
            QVERIFY(session.annotations().editFrame(f0, done, "Done"));
            QVERIFY(session.annotations().writeRecovery().ok());
            // The session ends without saving (a crash keeps the recovery file).
        }
        EditingSession other;
        other.annotations().setRecoveryDir(recovery);
        QVERIFY(other.open(m_b).ok());
        QVERIFY(!other.annotations().findRecovery().has_value());
        const auto for_a = other.annotations().findRecovery(QFileInfo(m_a).absoluteFilePath());
        QVERIFY(for_a.has_value());
        QCOMPARE(for_a->frames, std::size_t(1));
        const Status refused = other.annotations().recover(*for_a);
        QVERIFY(!refused.ok());
        QVERIFY(other.annotations().frame(f0) == nullptr);

        EditingSession own;
        own.annotations().setRecoveryDir(recovery);
        QVERIFY(own.open(m_a).ok());
        const auto found = own.annotations().findRecovery();
        QVERIFY(found.has_value());
        QVERIFY(own.annotations().recover(*found).ok());
        QVERIFY(own.annotations().modified());
        QVERIFY(own.annotations().frame(f0) && own.annotations().frame(f0)->done);
        QVERIFY(own.annotations().save().ok());
        QVERIFY(!own.annotations().findRecovery().has_value());
        QFile::remove(QDir(m_a).filePath("annotations.json"));
    }

    void anEarlierSessionsRecoveryIsKeptUntilTheUserChooses()
    {
        const QString recovery = m_dir.filePath("recovery-kept");
        std::string f0;
        {
            EditingSession crashed;
            crashed.annotations().setRecoveryDir(recovery);
            QVERIFY(crashed.open(m_b).ok());
            f0 = crashed.stream().frameName(0).toStdString();
            FrameAnnotation done;
            done.done = true;
            QVERIFY(crashed.annotations().editFrame(f0, done, "Done"));
            QVERIFY(crashed.annotations().writeRecovery().ok());
        }
        EditingSession next;
        AnnotationsDocument& doc = next.annotations();
        doc.setRecoveryDir(recovery);
        QVERIFY(next.open(m_b).ok());
        const auto offered = doc.findRecovery();
        QVERIFY(offered.has_value());
        const QByteArray before = fileBytes(offered->file);
        // The user ignores the offer and edits: neither the autosave, nor an undo back to the
        // file, nor a save, replaces or removes the earlier session's edits.
        FrameAnnotation other;
        other.reviewed.insert("x");
        QVERIFY(doc.editFrame(f0, other, "Reviewed"));
        QVERIFY(doc.writeRecovery().ok());
        QCOMPARE(fileBytes(offered->file), before);
        doc.undoStack().undo();
        QCOMPARE(fileBytes(offered->file), before);
        doc.undoStack().redo();
        QVERIFY(doc.saveAs(m_dir.filePath("kept.json")).ok());
        QCOMPARE(fileBytes(offered->file), before);
        // Recovering it brings those edits back; then the file is this session's again.
        QVERIFY(doc.recover(*offered).ok());
        QVERIFY(doc.frame(f0) && doc.frame(f0)->done);
        QVERIFY(doc.writeRecovery().ok());
        doc.discardRecovery();
        QVERIFY(!doc.findRecovery().has_value());
    }

private:
    QTemporaryDir m_dir;
    QString m_a;
    QString m_b;
};

FIELDSIGHT_TEST_SUITE(TestAnnotationsDocument, Widgets)

#include "test_annotations_document.moc"
