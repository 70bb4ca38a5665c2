// The Annotate menu and the annotations file in the window, offscreen, with real key events: V
// copies the previous annotated frame, A takes the frame's detections, D marks it done and N /
// Shift+N find the frames not done, Ctrl+Alt+<n> says "reviewed, nothing here"; Ctrl+Alt+S and
// Ctrl+S save atomically, closing or opening another stream asks about unsaved annotations, a
// damaged file is never written over, and a recovery is offered only on its own stream. Each
// checks the document, the file on disk or what the window shows. The test names no percept
// kind: it takes them from the registry by their form.
#include "support/percept_kinds.h"
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/test_files.h"
#include "support/unsaved_ask.h"
#include "support/window_waits.h"
#include "ui/actions/annotations_file.h"
#include "ui/stream_navigator/annotation_strip.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/services/annotation_editing.h"

#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <unistd.h>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::AnnotationsDocument;
using fieldsight::ui::MainWindow;

namespace {

/// The kinds drawn by hand, in the order the menu lists them.
std::vector<const PerceptKind*> drawnKinds(const AnnotationsDocument& doc)
{
    std::vector<const PerceptKind*> kinds;
    for (const PerceptKind* kind : doc.kinds())
        if (kind->form != ShapeForm::None)
            kinds.push_back(kind);
    return kinds;
}

/// `frame` with objects of `kind` drawn as `shapes` (its list replaced).
FrameAnnotation withShapes(FrameAnnotation frame, const PerceptKind& kind,
                           const std::vector<EditShape>& shapes)
{
    PerceptEntry& entry = frame.truth.entry(kind);
    entry.setShapes(shapes);
    frame.truth.markPresent(entry);
    return frame;
}

/// `set` as truth JSON, its lists in key order (whatever order they were made in).
QString truthJson(const PerceptSet& set)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    set.toJson(j, PerceptNames::Truth);
    return QString::fromStdString(nlohmann::json::parse(j.dump()).dump());
}

QStringList temporaries(const QString& folder)
{
    return QDir(folder).entryList({QStringLiteral("*.tmp-*")}, QDir::Files | QDir::Hidden);
}

QString qstr(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

} // namespace

class TestAnnotateActions : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the first `frames` frames of the sample stream, without its annotations.
    QString copyStream(const QString& name, int frames = 6)
    {
        return copySampleFrames(m_dir.filePath(name), frames);
    }

    /// The window shown and active (shortcuts need it) on `stream`.
    static bool showOn(MainWindow& w, const QString& stream)
    {
        w.show();
        return QTest::qWaitForWindowActive(&w) && openAndWait(w, stream);
    }

    static bool go(MainWindow& w, std::size_t frame)
    {
        w.session().stream().setCurrentIndex(frame);
        return waitForFrame(w, frame);
    }

    static std::string name(MainWindow& w, std::size_t frame)
    {
        return w.session().stream().frameName(frame).toStdString();
    }

    static QAction* action(MainWindow& w, const QString& name)
    {
        return w.findChild<QAction*>(name);
    }

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_annotate_actions", m_dir), QString());
    }

    void init() { test::forgetEarlierTests(); }

    void vCopiesThePreviousAnnotatedFrame()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("copy")));
        AnnotationsDocument& doc = w.session().annotations();
        const PerceptKind* circle = test::kindOfForm(doc, ShapeForm::Circle);
        const PerceptKind* box = test::kindOfForm(doc, ShapeForm::Box);
        QVERIFY(circle && box);
        FrameAnnotation first = withShapes({}, *circle, {{{{120, 90}}, 7}});
        first = withShapes(first, *box, {{{{10, 20}, {30, 80}}, 0}, {{{200, 10}, {220, 70}}, 0}});
        first.done = true;
        first.setFlags(circle->truth_key, 0, ObjectFlags{true, 4, true, true, false});
        first.reviewed.emplace(circle->truth_key);
        QVERIFY(doc.editFrame(name(w, 1), first, "Frame 1"));

        // From frame 3 (frame 2 has none): frame 1's objects and flags, not done, not reviewed.
        QVERIFY(go(w, 3));
        const int steps = doc.undoStack().count();
        QTest::keyClick(&w, Qt::Key_V);
        QCOMPARE(doc.undoStack().count(), steps + 1);
        const FrameAnnotation* copy = doc.frame(name(w, 3));
        QVERIFY(copy);
        QCOMPARE(truthJson(copy->truth), truthJson(first.truth));
        QCOMPARE(copy->truth.find(*box)->size(), std::size_t(2));
        QCOMPARE(copy->flagsOf(circle->truth_key, 0).track, 4);
        QVERIFY(copy->flagsOf(circle->truth_key, 0).concealed);
        QVERIFY(!copy->done);
        QVERIFY(copy->reviewed.empty());
        QVERIFY(!doc.frame(name(w, 2)));
        QVERIFY(doc.frame(name(w, 1))->done); // the source is untouched

        // One undo step takes it away; on frame 0 there is nothing before to copy.
        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(!doc.frame(name(w, 3)));
        QVERIFY(go(w, 0));
        QTest::keyClick(&w, Qt::Key_V);
        QVERIFY(!doc.frame(name(w, 0)));
        QVERIFY2(w.lastMessage().contains("No frame before"), qPrintable(w.lastMessage()));
    }

    void aMakesTheDetectionsTheAnnotations()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("detections")));
        AnnotationsDocument& doc = w.session().annotations();
        QVERIFY(go(w, 2));
        // An object annotated before is replaced, and the frame is no longer done.
        const PerceptKind* circle = test::kindOfForm(doc, ShapeForm::Circle);
        FrameAnnotation before = withShapes({}, *circle, {{{{5, 5}}, 3}});
        before.done = true;
        QVERIFY(doc.editFrame(name(w, 2), before, "Before"));
        const int steps = doc.undoStack().count();

        QTest::keyClick(&w, Qt::Key_A);
        QCOMPARE(doc.undoStack().count(), steps + 1);
        const FrameAnnotation* truth = doc.frame(name(w, 2));
        QVERIFY(truth);
        QVERIFY(!truth->done);
        const PerceptSet& detected = w.session().stream().current()->result.percepts;
        std::size_t objects = 0;
        for (const PerceptKind* kind : drawnKinds(doc)) {
            const PerceptEntry* d = detected.find(*kind);
            if (!d || !d->present())
                continue;
            const PerceptEntry* t = truth->truth.find(*kind);
            QVERIFY2(t && t->present(), qPrintable(qstr(kind->title)));
            QVERIFY(t->shapes() == d->shapes());
            objects += d->size();
        }
        QVERIFY(objects > 0); // the frame has detections to take
        QCOMPARE(objectCount(*truth), objects);
        // Written as truth, the lists read back equal.
        Annotations saved;
        saved.frames[name(w, 2)] = *truth;
        auto read = Annotations::fromJson(saved.toJson(doc.kinds()), "x", doc.kinds());
        QVERIFY(read);
        QCOMPARE(truthJson(read.value().frames.begin()->second.truth), truthJson(truth->truth));

        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(*doc.frame(name(w, 2)) == before);
    }

    void dMarksDoneAndNFindsTheFramesNotDone()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("done")));
        AnnotationsDocument& doc = w.session().annotations();
        QAction* done = action(w, "annotate.done");
        QVERIFY(done);
        // Frames 0, 1 and 3 done with D; 4 annotated but not done; 2 and 5 not annotated.
        for (std::size_t f : {0, 1, 3}) {
            QVERIFY(go(w, f));
            QVERIFY(!done->isChecked());
            QTest::keyClick(&w, Qt::Key_D);
            QVERIFY(doc.frame(name(w, f)) && doc.frame(name(w, f))->done);
            QVERIFY(done->isChecked());
        }
        QVERIFY(doc.editFrame(
            name(w, 4), withShapes({}, *test::kindOfForm(doc, ShapeForm::Circle), {{{{9, 9}}, 4}}),
            "Frame 4"));
        const auto& states = w.timeline().annotationStrip().states();
        QCOMPARE(states.done, (std::vector<bool>{true, true, false, true, false, false}));
        QCOMPARE(states.annotated, (std::vector<bool>{true, true, false, true, true, false}));
        auto* status = w.statusBar()->findChild<QLabel*>("annotation_status");
        QVERIFY(status);
        QVERIFY2(status->text().contains("done") && status->text().contains("3 of 6"),
                 qPrintable(status->text()));

        // D again: not done, one undo step.
        const int steps = doc.undoStack().count();
        QTest::keyClick(&w, Qt::Key_D);
        QVERIFY(!doc.frame(name(w, 3))->done);
        QCOMPARE(doc.undoStack().count(), steps + 1);
        QVERIFY(!done->isChecked());
        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(doc.frame(name(w, 3))->done);

        // N: 2, 4, 5, then round to 2; Shift+N from 2 goes back round to 5.
        QVERIFY(go(w, 0));
        for (std::size_t expected : {2, 4, 5, 2}) {
            QTest::keyClick(&w, Qt::Key_N);
            QVERIFY(waitForFrame(w, expected));
        }
        QVERIFY2(w.statusBar()->currentMessage().contains("from the start"),
                 qPrintable(w.statusBar()->currentMessage()));
        QTest::keyClick(&w, Qt::Key_N, Qt::ShiftModifier);
        QVERIFY(waitForFrame(w, 5));
        QTest::keyClick(&w, Qt::Key_N, Qt::ShiftModifier);
        QVERIFY(waitForFrame(w, 4));

        // Every frame done: N stays and says so.
        for (std::size_t f : {2, 4, 5}) {
            QVERIFY(go(w, f));
            QTest::keyClick(&w, Qt::Key_D);
        }
        QTest::keyClick(&w, Qt::Key_N);
        QVERIFY(waitForFrame(w, 5));
        QVERIFY2(w.lastMessage().contains("Every frame is done"), qPrintable(w.lastMessage()));
    }

    void reviewedNothingHereEmptiesTheListAndIsSaved()
    {
        const QString stream = copyStream("reviewed");
        MainWindow w;
        QVERIFY(showOn(w, stream));
        AnnotationsDocument& doc = w.session().annotations();
        const std::vector<const PerceptKind*> kinds = drawnKinds(doc);
        QVERIFY(kinds.size() >= 2);
        // The second kind of the menu: Ctrl+Alt+2, its item named by its title.
        const PerceptKind& kind = *kinds[1];
        QAction* item = action(w, "annotate.reviewed." + qstr(kind.truth_key));
        QVERIFY(item);
        QVERIFY2(item->text().contains(qstr(kind.title)), qPrintable(item->text()));
        QCOMPARE(item->shortcut(), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_2));
        const EditShape shape = kind.form == ShapeForm::Circle ? EditShape{{{50, 50}}, 5}
                                                               : EditShape{{{10, 20}, {40, 60}}, 0};
        FrameAnnotation frame = withShapes({}, kind, {shape});
        frame = withShapes(frame, *kinds[0],
                           kinds[0]->form == ShapeForm::Circle
                               ? std::vector<EditShape>{{{{80, 80}}, 6}}
                               : std::vector<EditShape>{{{{1, 2}, {3, 4}}, 0}});
        QVERIFY(doc.editFrame(name(w, 0), frame, "Two kinds"));
        const int steps = doc.undoStack().count();

        QTest::keyClick(&w, Qt::Key_2, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(doc.undoStack().count(), steps + 1);
        const FrameAnnotation* after = doc.frame(name(w, 0));
        QVERIFY(after->truth.find(kind) && after->truth.find(kind)->present());
        QCOMPARE(after->truth.find(kind)->size(), std::size_t(0));
        QVERIFY(after->reviewed.count(kind.truth_key));
        QCOMPARE(after->truth.find(*kinds[0])->size(), std::size_t(1)); // the other kind stays
        QVERIFY(item->isChecked());

        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        QVERIFY(!doc.modified());
        auto saved = Annotations::load(toLocal(stream + "/annotations.json"), doc.kinds());
        QVERIFY(saved);
        const FrameAnnotation& read = saved.value().frames.at(name(w, 0));
        QVERIFY(read.reviewed.count(kind.truth_key));
        QVERIFY(read.truth.find(kind) && read.truth.find(kind)->present());
        QCOMPARE(read.truth.find(kind)->size(), std::size_t(0));
        QVERIFY(!read.done);
    }

    void ctrlAltSSavesAtomicallyAndCtrlSSavesModifiedAnnotations()
    {
        const QString stream = copyStream("atomic");
        const QString file = stream + "/annotations.json";
        QVERIFY(QFile::copy(sampleStream() + "/annotations.json", file));
        // A second name for the file as it is: an atomic save replaces the name's file and
        // leaves this one as it was; a write in place would change both.
        QCOMPARE(::link(QFile::encodeName(file), QFile::encodeName(stream + "/held.json")), 0);
        const QByteArray on_disk = fileBytes(file);
        ScriptedDialogs dialogs;
        MainWindow w;
        QVERIFY(showOn(w, stream));
        AnnotationsDocument& doc = w.session().annotations();
        QVERIFY(doc.frame(name(w, 0)) && doc.frame(name(w, 0))->done);
        QVERIFY(!w.isWindowModified());
        QTest::keyClick(&w, Qt::Key_D); // frame 0 not done
        QVERIFY(doc.modified());
        QVERIFY(w.isWindowModified());
        QVERIFY2(w.windowTitle().contains("annotations.json[*]"), qPrintable(w.windowTitle()));

        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        QVERIFY(!doc.modified());
        QVERIFY(!w.isWindowModified());
        QCOMPARE(fileBytes(file), QByteArray::fromStdString(doc.annotations().toJson(doc.kinds())));
        QVERIFY(fileBytes(file) != on_disk);
        QCOMPARE(fileBytes(stream + "/held.json"), on_disk);
        QVERIFY(temporaries(stream).isEmpty());
        QVERIFY(dialogs.asked.isEmpty() && dialogs.unanswered.isEmpty());

        // Ctrl+S saves modified annotations too, and asks nothing about the untouched table.
        const QByteArray lut = fileBytes(stream + "/default.lut");
        QTest::keyClick(&w, Qt::Key_D);
        QVERIFY(doc.modified());
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
        QVERIFY(!doc.modified());
        QVERIFY(doc.frame(name(w, 0))->done);
        auto read = Annotations::load(toLocal(file), doc.kinds());
        QVERIFY(read && read.value().frames.at(name(w, 0)).done);
        QCOMPARE(fileBytes(stream + "/default.lut"), lut);
        QVERIFY(dialogs.asked.isEmpty() && dialogs.unanswered.isEmpty());
        QVERIFY(temporaries(stream).isEmpty());
    }

    void unsavedAnnotationsAskSaveDiscardOrCancel_data() { addUnsavedAskRows(); }

    void unsavedAnnotationsAskSaveDiscardOrCancel()
    {
        QFETCH(QMessageBox::StandardButton, answer);
        QFETCH(bool, close);
        const QString tag = unsavedAskTag();
        const QString a = copyStream("ask_a_" + tag), b = copyStream("ask_b_" + tag, 3);
        const QString file = a + "/annotations.json";
        ScriptedDialogs dialogs;
        MainWindow w;
        QVERIFY(showOn(w, a));
        AnnotationsDocument& doc = w.session().annotations();
        QTest::keyClick(&w, Qt::Key_D);
        QVERIFY(doc.modified());
        const FrameAnnotation edited = *doc.frame(name(w, 0));
        QVERIFY(doc.writeRecovery().ok()); // as the autosave would

        UnsavedDocument annotations;
        annotations.question = QStringLiteral("Unsaved annotations");
        annotations.holds_edit = [&] { return doc.modified() && *doc.frame(name(w, 0)) == edited; };
        annotations.file_has_edit = [&] {
            auto read = Annotations::load(toLocal(file), doc.kinds());
            return read && read.value().frames.at(name(w, 0)) == edited;
        };
        annotations.file_as_before = [&] { return !QFileInfo::exists(file); };
        annotations.has_recovery = [&] { return doc.findRecovery().has_value(); };
        annotations.shows_other = [&] { return !doc.modified(); };
        answerUnsavedAsk(w, dialogs, annotations, answer, close, a, b);
    }

    void aRecoveryIsOfferedOnlyOnItsOwnStream_data()
    {
        QTest::addColumn<QString>("button");
        QTest::newRow("Recover") << QStringLiteral("accept");
        QTest::newRow("Discard") << QStringLiteral("decline");
        // Recovered, then dropped when the window closes: not offered again.
        QTest::newRow("Recover, then quit discarding") << QStringLiteral("accept_then_discard");
    }

    void aRecoveryIsOfferedOnlyOnItsOwnStream()
    {
        QFETCH(QString, button);
        const QString a = copyStream("rec_a_" + button), b = copyStream("rec_b_" + button, 3);
        ScriptedDialogs dialogs;
        FrameAnnotation edited;
        std::string f1;
        {
            MainWindow crashed;
            QVERIFY(showOn(crashed, a));
            QVERIFY(go(crashed, 1));
            QTest::keyClick(&crashed, Qt::Key_D);
            f1 = name(crashed, 1);
            edited = *crashed.session().annotations().frame(f1);
            QVERIFY(crashed.session().annotations().writeRecovery().ok()); // the autosave
        } // gone without closing: only the recovery file keeps the edit

        auto w = std::make_unique<MainWindow>();
        ui::OfferBar& bar = w->annotationsRecoveryBar();
        QVERIFY(showOn(*w, b)); // another stream: nothing offered
        QVERIFY(!bar.isVisible());
        QVERIFY(!w->recoveryBar().isVisible());
        QVERIFY(openAndWait(*w, a));
        QVERIFY(bar.isVisible());
        QVERIFY2(bar.question().contains("1 annotated frame"), qPrintable(bar.question()));
        QVERIFY(!w->session().annotations().frame(f1));
        QVERIFY(openAndWait(*w, b)); // and away again: the offer goes with its stream
        QVERIFY(!bar.isVisible());
        QVERIFY(openAndWait(*w, a));
        QVERIFY(bar.isVisible());

        const bool then_discard = button == "accept_then_discard";
        QTest::mouseClick(bar.findChild<QPushButton*>(then_discard ? "accept" : button),
                          Qt::LeftButton);
        QVERIFY(!bar.isVisible());
        QVERIFY(!QFileInfo::exists(a + "/annotations.json")); // nothing written before a save
        AnnotationsDocument& doc = w->session().annotations();
        if (then_discard) {
            QVERIFY(doc.frame(f1) && *doc.frame(f1) == edited);
            dialogs.answers.push_back(QMessageBox::Discard);
            QVERIFY(w->close());
            QVERIFY(dialogs.answers.empty());
            QVERIFY(!QFileInfo::exists(a + "/annotations.json"));
        } else if (button == "accept") {
            QVERIFY(doc.frame(f1) && *doc.frame(f1) == edited);
            QVERIFY(w->isWindowModified());
            QVERIFY2(w->lastMessage().startsWith("Recovered"), qPrintable(w->lastMessage()));
            QTest::keyClick(w.get(), Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
            auto read = Annotations::load(toLocal(a + "/annotations.json"), doc.kinds());
            QVERIFY(read && read.value().frames.at(f1) == edited);
            QVERIFY(!w->isWindowModified());
        } else {
            QVERIFY(!doc.frame(f1));
            QVERIFY(!w->isWindowModified());
        }
        QVERIFY(!doc.findRecovery());
        w.reset();
        MainWindow next;
        QVERIFY(showOn(next, a));
        QVERIFY(!next.annotationsRecoveryBar().isVisible());
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    void aDamagedFileIsNamedAndSaveAsksForAnotherFile()
    {
        const QString stream = copyStream("damaged");
        const QString file = stream + "/annotations.json";
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("{\"format\": \"fieldsight-annotations/1\", \"frames\": [");
        }
        const QByteArray damaged = fileBytes(file);
        ScriptedDialogs dialogs;
        MainWindow w;
        QVERIFY(showOn(w, stream));
        QVERIFY2(w.messageBar().isVisible() && w.messageBar().text().contains(file),
                 qPrintable(w.messageBar().text()));
        QTest::keyClick(&w, Qt::Key_D);
        QVERIFY(w.session().annotations().modified());

        // Save asks for a file, suggesting another name; cancelled, nothing is written.
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(dialogs.suggested.size(), qsizetype(1));
        QVERIFY2(dialogs.suggested.last() != file, qPrintable(dialogs.suggested.last()));
        QVERIFY2(w.lastMessage().contains(file), qPrintable(w.lastMessage()));
        QCOMPARE(fileBytes(file), damaged);
        QVERIFY(w.session().annotations().modified());

        const QString other = stream + "/annotations.new.json";
        dialogs.paths.push_back(other);
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(fileBytes(file), damaged);
        QVERIFY(!w.session().annotations().modified());
        auto read = Annotations::load(toLocal(other), w.session().annotations().kinds());
        QVERIFY(read && read.value().frames.at(name(w, 0)).done);
        QCOMPARE(w.session().annotations().path(), other);
    }

private:
    static std::string toLocal(const QString& path)
    {
        return QFile::encodeName(path).toStdString();
    }
};

FIELDSIGHT_TEST_SUITE(TestAnnotateActions, Widgets)

#include "test_annotate_actions.moc"
