// What got in the way in the window at 1280x800 (issue 32), offscreen: the truth shows where a
// detection lies on it (drawn dashed, over the detections, which dim while annotating); the
// detections of one kind become annotations without touching the others; a ball is drawn to a
// fraction of a pixel; the status bar says "scanning n of N" until the whole-stream scan is done;
// a table made the stream's own keeps the orientation it was made on; the Evaluation dock and the
// Pixel inspector show everything; Help > Keyboard shortcuts fits an 800 px screen and lists
// only keys a user can press; annotated frames the stream lacks are named when it opens. The
// test names no percept kind: it takes them from the registry by their form.
#include "support/percept_kinds.h"
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/test_files.h"
#include "support/window_waits.h"

#include "ui/actions/annotations_file.h"
#include "ui/actions/menus.h"
#include "ui/adapters/overlay_painter.h"
#include "ui/dialogs/dialogs.h"
#include "ui/panels/evaluation_panel.h"
#include "ui/panels/inspector_panel.h"
#include "ui/stream_navigator/effect_strip.h"
#include "ui/tools/annotate_tool.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/orientation.h"
#include "visioncore/services/annotation_tracks.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QMenuBar>
#include <QDockWidget>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTextDocument>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;

namespace {

QString qstr(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

std::string frameName(MainWindow& w, std::size_t index)
{
    return w.session().stream().frameName(index).toStdString();
}

QJsonObject readJson(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

bool writeJson(const QString& path, const QJsonObject& object)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
           f.write(QJsonDocument(object).toJson()) > 0;
}

/// The scroll area `widget` is the content of, if any.
QScrollArea* scrollAreaOf(QWidget* widget)
{
    for (QWidget* p = widget ? widget->parentWidget() : nullptr; p; p = p->parentWidget())
        if (auto* area = qobject_cast<QScrollArea*>(p))
            return area;
    return nullptr;
}

} // namespace

class TestWindowTrial : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the sample stream: the first `frames` frames (all when 0, with its manifest),
    /// with its table and, when asked, its annotations.
    QString copyStream(const QString& name, int frames = 0, bool annotations = false)
    {
        const QString to = m_dir.filePath(name);
        QDir().mkpath(to);
        const QDir from(sampleStream());
        int copied = 0;
        for (const QString& file : from.entryList(QDir::Files, QDir::Name)) {
            const bool frame = file.startsWith(QLatin1String("frame_"));
            if (frame && frames > 0 && copied >= frames)
                continue;
            if (file == QLatin1String("annotations.json") && !annotations)
                continue;
            if (file == QLatin1String("stream.json") && frames > 0)
                continue; // it lists every frame

            copied += frame;
            QFile::copy(from.filePath(file), to + "/" + file);
        }
        return to;
    }

    /// The window at the size of the trial, 1280x800, shown and active on `stream`.
    static bool showOn(MainWindow& w, const QString& stream)
    {
        w.resize(1280, 800);
        w.show();
        if (!QTest::qWaitForWindowActive(&w)) {
            qWarning("the window is not active");
            return false;
        }
        const bool opened = openAndWait(w, stream);
        if (!opened)
            qWarning("%s", qPrintable(w.lastMessage()));
        return opened;
    }

private slots:
    void initTestCase() { QCOMPARE(test::startWindowSuite("test_window_trial", m_dir), QString()); }

    void init() { test::forgetEarlierTests(); }

    /// A detection exactly on its true object: the truth, dashed and drawn over it, still shows
    /// (its white dashes), and so does the detection (its colour in the gaps); the headless
    /// render and the window paint the same drawings.
    void truthShowsOverADetectionOnIt()
    {
        const Pipeline& pipeline = Pipeline::standard();
        const PerceptKind* circle = test::kindOfForm(pipeline.perceptKinds(), ShapeForm::Circle);
        QVERIFY(circle);
        PerceptSet detected;
        PerceptEntry& d = detected.entry(*circle);
        d.setShapes({{{{20, 20}}, 9}});
        detected.markPresent(d);
        const PerceptSet truth = detected;
        const LayerSet wanted = selectLayers("truth,percepts", pipeline).value();
        const std::vector<DebugDrawing> drawings =
            frameDrawings(pipeline, wanted, DebugCanvas(), detected, &truth);
        QVERIFY(drawings.size() >= 2);
        QVERIFY(ui::isTruthLayer(drawings.back().layer)); // on top
        std::vector<const DebugDrawing*> layers;
        for (const DebugDrawing& drawing : drawings)
            layers.push_back(&drawing);
        const cv::Mat grey(40, 40, CV_8UC3, cv::Scalar(128, 128, 128));
        const QImage image = ui::renderOverlay(grey, layers, 4);
        const QRgb white = qRgb(255, 255, 255);
        const QRgb kind = qRgb(circle->colour.r, circle->colour.g, circle->colour.b);
        int whites = 0;
        int kinds = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                whites += image.pixel(x, y) == white;
                kinds += image.pixel(x, y) == kind;
            }
        QVERIFY2(whites > 40, qPrintable(QString::number(whites)));
        QVERIFY2(kinds > 40, qPrintable(QString::number(kinds)));
    }

    /// With an annotation tool active the detections are drawn faint; back on a LUT tool, full.
    void detectionsDimWhileAnnotating()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("dim", 4)));
        QVERIFY(!w.view().detectionsDimmed());
        const QImage before = w.view().grab().toImage();
        QTest::keyClick(&w, Qt::Key_1, Qt::ShiftModifier);
        QVERIFY(qobject_cast<ui::AnnotateTool*>(&w.tools().active()));
        QVERIFY(w.view().detectionsDimmed());
        const QImage dimmed = w.view().grab().toImage();
        QVERIFY(before.size() == dimmed.size());
        QVERIFY(before != dimmed); // the frame has detections, drawn differently
        QTest::keyClick(&w, Qt::Key_C);
        QVERIFY(!w.view().detectionsDimmed());
        QVERIFY(w.view().grab().toImage() == before);
    }

    /// Annotate > Detections to annotations > <kind> only: that kind's list becomes the
    /// detections, another kind's keyframed track stays as it was; one undo step.
    void detectionsOfOneKindLeaveTheOtherKinds()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("one_kind", 6)));
        ui::AnnotationsDocument& doc = w.session().annotations();
        w.session().stream().setCurrentIndex(2);
        QVERIFY(waitForFrame(w, 2));
        const PerceptSet& detected = w.session().stream().current()->result.percepts;
        // The kind taken: one the detectors found on this frame; the kind kept: another.
        const PerceptKind* taken = nullptr;
        for (const PerceptKind* kind : doc.kinds()) {
            const PerceptEntry* e = detected.find(*kind);
            if (kind->form != ShapeForm::None && e && e->present() && e->size() > 0) {
                taken = kind;
                break;
            }
        }
        QVERIFY(taken);
        const PerceptKind* kept = nullptr;
        for (const PerceptKind* kind : doc.kinds())
            if (kind != taken && (kind->form == ShapeForm::Circle || kind->form == ShapeForm::Box))
                kept = kind;
        QVERIFY(kept);
        FrameAnnotation before;
        PerceptEntry& track = before.truth.entry(*kept);
        track.setShapes({kept->form == ShapeForm::Circle ? EditShape{{{30.5, 40.25}}, 4.5}
                                                         : EditShape{{{10, 20}, {30, 60}}, 0}});
        before.truth.markPresent(track);
        before.setFlags(kept->truth_key, 0, ObjectFlags{false, 7, true, false, false});
        QVERIFY(doc.editFrame(frameName(w, 2), before, "Before"));
        const int steps = doc.undoStack().count();

        auto* action =
            w.findChild<QAction*>(QStringLiteral("annotate.detections.") + qstr(taken->truth_key));
        QVERIFY2(action, qPrintable(qstr(taken->truth_key)));
        QVERIFY(action->isEnabled());
        action->trigger();
        QCOMPARE(doc.undoStack().count(), steps + 1);
        const FrameAnnotation* after = doc.frame(frameName(w, 2));
        QVERIFY(after);
        QVERIFY(after->truth.find(*taken)->shapes() == detected.find(*taken)->shapes());
        QVERIFY(after->truth.find(*kept)->shapes() == track.shapes());
        QCOMPARE(after->flagsOf(kept->truth_key, 0).track, 7);
        QVERIFY(after->flagsOf(kept->truth_key, 0).keyframe);
        // The other kinds the detectors found are not taken either.
        for (const PerceptKind* kind : doc.kinds())
            if (kind != taken && kind != kept)
                QVERIFY2(!after->truth.find(*kind), qPrintable(qstr(kind->title)));
        // "All kinds" (A) is still there, with its key.
        auto* all = w.findChild<QAction*>(QStringLiteral("annotate.detections"));
        QVERIFY(all);
        QCOMPARE(all->shortcut(), QKeySequence(Qt::Key_A));
        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(*doc.frame(frameName(w, 2)) == before);
    }

    /// The ball tool places the centre and the rim where the pointer is, to a tenth of a pixel:
    /// a ball drawn at zoom 8 from a pixel corner keeps centre 40.5 and radius 4.5.
    void aBallIsDrawnToAFractionOfAPixel()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("fraction", 3)));
        constexpr double zoom = 8;
        w.view().setZoom(zoom);
        w.view().setImageOrigin({0, 0});
        const auto at = [](double x, double y) {
            return QPoint(int((x + 0.5) * zoom), int((y + 0.5) * zoom));
        };
        auto* tool = [&]() -> ui::AnnotateTool* {
            for (const auto& t : w.tools().tools())
                if (auto* a = qobject_cast<ui::AnnotateTool*>(t.get());
                    a && a->kind().form == ShapeForm::Circle)
                    return a;
            return nullptr;
        }();
        QVERIFY(tool);
        w.tools().activate(tool->info().id);
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, at(20.5, 15.5));
        QTest::mouseMove(&w.view(), at(22.5, 15.5));
        QTest::mouseMove(&w.view(), at(25, 15.5));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at(25, 15.5));
        const FrameAnnotation* frame =
            w.session().annotations().frame(frameName(w, w.session().stream().currentIndex()));
        QVERIFY(frame);
        const std::vector<EditShape> shapes = shapesOf(*frame, tool->kind());
        QCOMPARE(shapes.size(), std::size_t(1));
        QCOMPARE(shapes[0].points.at(0).x, 20.5);
        QCOMPARE(shapes[0].points.at(0).y, 15.5);
        QCOMPARE(shapes[0].radius, 4.5);
        // Its rim pulled to a pixel corner: 4.5 becomes 6.0, the centre stays.
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, at(25, 15.5));
        QTest::mouseMove(&w.view(), at(26, 15.5));
        QTest::mouseMove(&w.view(), at(26.5, 15.5));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at(26.5, 15.5));
        const std::vector<EditShape> resized = shapesOf(
            *w.session().annotations().frame(frameName(w, w.session().stream().currentIndex())),
            tool->kind());
        QCOMPARE(resized.at(0).points.at(0).x, 20.5);
        QCOMPARE(resized.at(0).radius, 6.0);
    }

    /// While the whole-stream scan runs the status says how far it is and calls nothing final;
    /// once done, the totals.
    void theStatusSaysScanningUntilTheScanIsDone()
    {
        // A long stream, so the scan reports several times before it ends.
        const QString stream = m_dir.filePath("long");
        QDir().mkpath(stream);
        const QDir from(sampleStream());
        QFile::copy(from.filePath("default.lut"), stream + "/default.lut");
        const QStringList frames = from.entryList({QStringLiteral("frame_*.png")}, QDir::Files);
        int n = 0;
        for (int round = 0; round < 8; ++round)
            for (const QString& f : frames)
                QFile::copy(from.filePath(f),
                            stream + QStringLiteral("/frame_%1.png").arg(n++, 6, 10, QChar('0')));
        MainWindow w;
        QVERIFY(showOn(w, stream));
        ui::EditEffectScan& scan = w.session().effectScan();
        scan.setThreads(1);
        scan.setDelay(0);
        if (scan.running())
            QVERIFY(QSignalSpy(&scan, &ui::EditEffectScan::finished).wait(60000));
        QStringList partial;
        QString last;
        QObject::connect(&scan, &ui::EditEffectScan::updated, &w, [&] {
            const QString text = w.timeline().effectStrip().summary();
            if (scan.framesDone() < scan.effects().size()) {
                partial << text;
                QVERIFY2(text.contains(QStringLiteral("scanning %1 of %2")
                                           .arg(scan.framesDone())
                                           .arg(scan.effects().size())),
                         qPrintable(text));
                QVERIFY2(!text.contains(QLatin1String("no detection changed")) ||
                             text.contains(QLatin1String("so far")),
                         qPrintable(text));
            }
            last = text;
        });
        // Every orange cell erased: every ball vanishes, frame by frame.
        const ColourLut table = w.session().lut().table();
        std::vector<CellChange> changes;
        for (std::uint32_t i = 0; i < ColourLut::kCells; ++i)
            if (table.cell(i) == Colour::Orange)
                changes.push_back({i, Colour::Orange, Colour::Unclassified});
        QVERIFY(!changes.empty());
        QSignalSpy done(&scan, &ui::EditEffectScan::finished);
        w.session().lut().edit("erase orange", changes);
        QVERIFY(done.wait(120000));
        QVERIFY2(!partial.isEmpty(), "the scan reported nothing before it ended");
        QVERIFY2(last.contains(QStringLiteral("over %1 frames").arg(n)), qPrintable(last));
        QVERIFY2(last.contains(QStringLiteral("ball")), qPrintable(last));
        QVERIFY2(!last.contains(QLatin1String("scanning")), qPrintable(last));
    }

    /// "Use as this stream's table" after View > Orientation > Turn 180°: asked, the orientation
    /// is saved with the table, so the commands read the frames as the table was made on them.
    void useAsStreamTableKeepsTheOrientation()
    {
        const QString stream = copyStream("turned", 3);
        ScriptedDialogs dialogs;
        MainWindow w;
        QVERIFY(showOn(w, stream));
        auto* turn = w.findChild<QAction*>(QStringLiteral("view.orientation.180"));
        QVERIFY(turn);
        turn->trigger();
        QVERIFY(w.session().stream().orientationUnsaved());
        dialogs.paths.push_back(stream + "/venue.lut");
        dialogs.choices.push_back(0); // the table and the orientation
        QVERIFY(w.files().saveLutAs());
        QVERIFY2(dialogs.unanswered.isEmpty(), qPrintable(dialogs.unanswered.join(", ")));
        QVERIFY(dialogs.texts_asked.last().contains(QStringLiteral("180")));
        const QJsonObject manifest = readJson(stream + "/stream.json");
        QCOMPARE(manifest.value("orientation").toInt(), 180);
        QVERIFY2(manifest.value("lut").toString().contains("venue.lut"),
                 qPrintable(QJsonDocument(manifest).toJson()));
        QVERIFY(!w.session().stream().orientationUnsaved());

        // Turned back and saved as another table, "orientation as stored": the table only.
        w.findChild<QAction*>(QStringLiteral("view.orientation.0"))->trigger();
        dialogs.paths.push_back(stream + "/other.lut");
        dialogs.choices.push_back(1);
        QVERIFY(w.files().saveLutAs());
        const QJsonObject again = readJson(stream + "/stream.json");
        QCOMPARE(again.value("orientation").toInt(), 180);
        QVERIFY(again.value("lut").toString().contains("other.lut"));
    }

    /// The Evaluation dock at 1280x800 in the default arrangement: every row (the field lines
    /// last) and every column (the concealed one shown) is in view, with no scroll bar.
    void evaluationFitsAt1280x800()
    {
        const QString stream = copyStream("evaluation", 0, true);
        // A concealed ball, so the concealed column is shown.
        QJsonObject file = readJson(stream + "/annotations.json");
        QJsonObject frames = file.value("frames").toObject();
        QString first;
        for (auto it = frames.begin(); it != frames.end() && first.isEmpty(); ++it)
            if (!it.value().toObject().value("balls").toArray().isEmpty())
                first = it.key();
        QVERIFY(!first.isEmpty());
        QJsonObject f = frames.value(first).toObject();
        QJsonArray balls = f.value("balls").toArray();
        QJsonObject ball = balls.at(0).toObject();
        ball["concealed"] = true;
        balls[0] = ball;
        f["balls"] = balls;
        frames[first] = f;
        file["frames"] = frames;
        QVERIFY(writeJson(stream + "/annotations.json", file));

        MainWindow w;
        QVERIFY(showOn(w, stream));
        QVERIFY(waitForEvaluation(w));
        auto* dock = w.findChild<QDockWidget*>(QStringLiteral("evaluation_dock"));
        QVERIFY(dock);
        dock->raise();
        ui::EvaluationPanel& panel = w.evaluationPanel();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY(panel.isVisible());
        QScrollArea* area = scrollAreaOf(&panel);
        QVERIFY(area);
        QTRY_VERIFY(panel.width() <= area->viewport()->width()); // laid out in the area
        auto* table = panel.findChild<QTableWidget*>(QStringLiteral("evaluation.scores"));
        QVERIFY(table);
        QVERIFY(!table->isColumnHidden(6));
        QVERIFY(!table->horizontalScrollBar()->isVisible());
        QVERIFY(!table->verticalScrollBar()->isVisible());
        const QWidget* viewport = table->viewport();
        for (int r = 0; r < table->rowCount(); ++r)
            QVERIFY2(table->rowViewportPosition(r) + table->rowHeight(r) <= viewport->height(),
                     qPrintable(QStringLiteral("row %1 at %2+%3 of %4")
                                    .arg(r)
                                    .arg(table->rowViewportPosition(r))
                                    .arg(table->rowHeight(r))
                                    .arg(viewport->height())));
        for (int c = 0; c < table->columnCount(); ++c) {
            QVERIFY2(table->columnViewportPosition(c) + table->columnWidth(c) <= viewport->width(),
                     qPrintable(QStringLiteral("column %1 at %2+%3 of %4")
                                    .arg(c)
                                    .arg(table->columnViewportPosition(c))
                                    .arg(table->columnWidth(c))
                                    .arg(viewport->width())));
            // Each number whole in its cell.
            for (int r = 0; r < table->rowCount(); ++r)
                if (const QTableWidgetItem* item = table->item(r, c))
                    QVERIFY2(table->fontMetrics().horizontalAdvance(item->text()) + 4 <=
                                 table->columnWidth(c),
                             qPrintable(item->text()));
        }
        QVERIFY(!area->horizontalScrollBar()->isVisible());
        QVERIFY(!area->verticalScrollBar()->isVisible());
    }

    /// A long text in the Pixel inspector at 1280x800 is never cut off: it wraps and scrolls.
    void theInspectorScrollsWhatDoesNotFit()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("inspector", 2)));
        auto* inspector = w.findChild<ui::InspectorPanel*>(QStringLiteral("inspector"));
        QVERIFY(inspector);
        QStringList lines;
        for (int i = 0; i < 14; ++i)
            lines << QStringLiteral("Rejected obstacles #%1: (164, 134)–(200, 180): no field green "
                                    "on both sides of it, so it is not an obstacle standing on "
                                    "the field")
                         .arg(i);
        inspector->setText(lines.join('\n'));
        QScrollArea* area = scrollAreaOf(inspector);
        QVERIFY(area);
        QTRY_VERIFY(inspector->height() >= inspector->heightForWidth(inspector->width()));
        QVERIFY(inspector->width() <= area->viewport()->width());
        QVERIFY(area->verticalScrollBar()->maximum() > 0);
    }

    /// Help > Keyboard shortcuts lists the keys a user can press (Ctrl+Z, not Qt's F14) and its
    /// window fits an 800 px screen with Close on it.
    void theShortcutsFitAndAreKeysToPress()
    {
        MainWindow w;
        w.resize(1280, 800);
        // Undo's keys as Qt gives them under X11 (offscreen gives Ctrl+Z alone).
        auto* undo = w.findChild<QAction*>(QStringLiteral("edit.undo"));
        QVERIFY(undo);
        undo->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_Z), QKeySequence(Qt::Key_F14)});
        const QString html = ui::shortcutsHtml(*w.menuBar());
        QVERIFY(html.contains(QKeySequence(QKeySequence::Undo)
                                  .toString(QKeySequence::NativeText)
                                  .section(QLatin1String(", "), 0, 0)));
        QVERIFY2(!html.contains(QLatin1String("F14")), qPrintable(html));
        QVERIFY(html.contains(QLatin1String("Ctrl+Shift+Z")));
        QVERIFY(html.contains(QLatin1String("Detections to annotations: All kinds")));
        std::unique_ptr<QDialog> dialog(ui::makeDocumentDialog(&w, "Keyboard shortcuts", html));
        dialog->show();
        QVERIFY(QTest::qWaitForWindowExposed(dialog.get()));
        const QSize screen = dialog->screen()->availableSize();
        QVERIFY2(dialog->height() <= std::max(800, screen.height()) * 0.9 + 1,
                 qPrintable(QString::number(dialog->height())));
        QVERIFY(dialog->height() <= 720);
        // On a 1280x800 screen it needs no scrolling: the text unwrapped, with Close, within
        // 90% of it.
        auto* view = dialog->findChild<QTextBrowser*>();
        QVERIFY(view);
        QTextDocument text;
        text.setDefaultFont(view->font());
        text.setHtml(html);
        const QSize chrome = dialog->size() - view->viewport()->size();
        QVERIFY2(text.size().width() + chrome.width() <= 1280 * 0.9 &&
                     text.size().height() + chrome.height() <= 800 * 0.9,
                 qPrintable(QStringLiteral("%1x%2 and %3x%4 around it")
                                .arg(text.size().width())
                                .arg(text.size().height())
                                .arg(chrome.width())
                                .arg(chrome.height())));
        auto* buttons = dialog->findChild<QDialogButtonBox*>();
        QVERIFY(buttons && buttons->isVisible());
        QVERIFY(dialog->rect().contains(buttons->geometry()));
        // Through the seam.
        ScriptedDialogs dialogs;
        auto* help = w.findChild<QAction*>(QStringLiteral("help.shortcuts"));
        QVERIFY(help);
        help->trigger();
        QCOMPARE(dialogs.asked, QStringList{"Keyboard shortcuts"});
    }

    /// Annotations naming frames the stream lacks (`fieldsight eval` refuses them) are named in
    /// the message bar when the stream opens: how many and the first.
    void annotatedFramesTheStreamLacksAreNamed()
    {
        const QString stream = copyStream("lacking", 5, true);
        const QJsonObject frames =
            readJson(stream + "/annotations.json").value("frames").toObject();
        QStringList lacking;
        for (auto it = frames.begin(); it != frames.end(); ++it)
            if (!QFileInfo::exists(stream + "/" + it.key()))
                lacking << it.key();
        QVERIFY(!lacking.isEmpty());
        lacking.sort();
        MainWindow w;
        QVERIFY(showOn(w, stream));
        const QString message = w.lastMessage();
        QVERIFY2(
            message.contains(QStringLiteral("%1 frames this stream lacks").arg(lacking.size())),
            qPrintable(message));
        QVERIFY2(message.contains(lacking.front()), qPrintable(message));
        // Reloaded from disk: named again.
        w.clearMessage();
        QVERIFY(w.annotationFiles().reload());
        QVERIFY2(w.lastMessage().contains(
                     QStringLiteral("%1 frames this stream lacks").arg(lacking.size())),
                 qPrintable(w.lastMessage()));
        // A stream with every annotated frame says nothing of the kind.
        MainWindow all;
        QVERIFY(showOn(all, copyStream("every", 0, true)));
        QVERIFY2(!all.lastMessage().contains(QLatin1String("lacks")),
                 qPrintable(all.lastMessage()));
    }
};

FIELDSIGHT_TEST_SUITE(TestWindowTrial, Widgets)

#include "test_window_trial.moc"
