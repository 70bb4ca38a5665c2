// The annotation tools in the window, driven by the mouse and the keys as a user would: each form
// drawn, moved, resized, undone, redone and deleted; a polyline clicked point by point; a circle
// interpolated between two keyframes; propagation; the concealed flag; saved and read back the
// same. The test names no percept kind: it takes the tools from the registry by their form.
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/test_files.h"
#include "support/window_waits.h"

#include "ui/adapters/image_adapter.h"
#include "ui/adapters/local_path.h"
#include "ui/panels/layers_panel.h"
#include "ui/panels/lut_panel.h"
#include "ui/tools/annotate_tool.h"

#include "visioncore/services/annotation_tracks.h"

#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::AnnotateTool;

namespace {

/// Screen px per image px in these tests: image pixel (x, y) is at widget ((x + 0.5) * 2, ...).
constexpr double kZoom = 2;

QPoint at(PointF p)
{
    return QPoint(int((p.x + 0.5) * kZoom), int((p.y + 0.5) * kZoom));
}

void click(MainWindow& w, PointF p)
{
    QTest::mouseClick(&w.view(), Qt::LeftButton, {}, at(p));
}

/// A drag in three moves (a tool sees each).
void drag(MainWindow& w, PointF from, PointF to)
{
    QTest::mousePress(&w.view(), Qt::LeftButton, {}, at(from));
    QTest::mouseMove(&w.view(), at({from.x + (to.x - from.x) / 3, from.y + (to.y - from.y) / 3}));
    QTest::mouseMove(&w.view(), at({(from.x + to.x) / 2, (from.y + to.y) / 2}));
    QTest::mouseMove(&w.view(), at(to));
    QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at(to));
}

/// The annotation tool of the first kind drawn as `form`.
AnnotateTool* toolOf(MainWindow& w, ShapeForm form)
{
    for (const auto& tool : w.tools().tools())
        if (auto* a = qobject_cast<AnnotateTool*>(tool.get()); a && a->kind().form == form)
            return a;
    return nullptr;
}

std::string frameName(MainWindow& w, std::size_t index)
{
    return ui::toLocalPath(w.session().stream().frameName(index));
}

std::vector<EditShape> shapesOn(MainWindow& w, std::size_t frame, const PerceptKind& kind)
{
    const FrameAnnotation* f = w.session().annotations().frame(frameName(w, frame));
    return f ? shapesOf(*f, kind) : std::vector<EditShape>{};
}

ObjectFlags flagsOn(MainWindow& w, std::size_t frame, const PerceptKind& kind, std::size_t i = 0)
{
    const FrameAnnotation* f = w.session().annotations().frame(frameName(w, frame));
    return f ? f->flagsOf(kind.truth_key, i) : ObjectFlags{};
}

/// Shapes as text, so a failed comparison shows both.
QString text(const std::vector<EditShape>& shapes)
{
    QStringList out;
    for (const EditShape& s : shapes) {
        QStringList points;
        for (const PointF& p : s.points)
            points << QStringLiteral("(%1, %2)").arg(p.x).arg(p.y);
        out << points.join(' ') + (s.radius > 0 ? QStringLiteral(" r %1").arg(s.radius) : "");
    }
    return out.join(" | ");
}

QString text(const EditShape& shape)
{
    return text(std::vector<EditShape>{shape});
}

void goTo(MainWindow& w, std::size_t frame)
{
    w.session().stream().setCurrentIndex(frame);
    QVERIFY(waitForFrame(w, frame));
}

} // namespace

class TestAnnotateTools : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the sample stream without its annotations.
    QString copyStream(const QString& name)
    {
        return test::copyFolderFiles(sampleStream(), m_dir.filePath(name), test::isNotAnnotations);
    }

    /// `w` showing `stream` at kZoom with image pixel (0, 0) at the view's corner.
    bool open(MainWindow& w, const QString& stream)
    {
        w.resize(1400, 900);
        w.show();
        if (!QTest::qWaitForWindowExposed(&w) || !openAndWait(w, stream))
            return false;
        w.view().setZoom(kZoom);
        w.view().setImageOrigin({0, 0});
        return true;
    }

    /// Saves `w`'s annotations and reads them back in a session of their own: the same, frame
    /// by frame and byte for byte. Empty when they are.
    static QString savedAndReadBack(MainWindow& w, const QString& stream)
    {
        ui::AnnotationsDocument& doc = w.session().annotations();
        if (Status s = doc.save(); !s)
            return QString::fromStdString(s.error().message);
        ui::EditingSession again;
        if (Status s = again.open(stream); !s)
            return QString::fromStdString(s.error().message);
        const Annotations& read = again.annotations().annotations();
        if (read.frames.size() != doc.annotations().frames.size() || read.frames.empty())
            return QStringLiteral("%1 frames read, %2 saved")
                .arg(read.frames.size())
                .arg(doc.annotations().frames.size());
        for (const auto& [name, frame] : doc.annotations().frames)
            if (!read.frames.count(name) || !(read.frames.at(name) == frame))
                return QStringLiteral("frame %1 differs").arg(QString::fromStdString(name));
        if (read.toJson(doc.kinds()) != doc.annotations().toJson(doc.kinds()))
            return QStringLiteral("the JSON differs");
        return {};
    }

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_annotate_tools", m_dir), QString());
        QSettings().clear();
    }

    void init() { QSettings().clear(); }

    /// A tool per form, Shift+1.. in the pipeline's order, named and coloured by its kind.
    void aToolPerKindDrawnByHand()
    {
        MainWindow w;
        QVERIFY(open(w, copyStream("tools")));
        int ordinal = 0;
        for (const PerceptKind* kind : w.session().annotations().kinds()) {
            if (kind->form == ShapeForm::None)
                continue;
            ++ordinal;
            QTest::keyClick(&w, Qt::Key(Qt::Key_0 + ordinal), Qt::ShiftModifier);
            auto* tool = qobject_cast<AnnotateTool*>(&w.tools().active());
            QVERIFY2(tool, qPrintable(w.tools().active().info().id));
            QCOMPARE(&tool->kind(), kind);
            QCOMPARE(tool->info().name,
                     QString::fromUtf8(kind->title.data(), qsizetype(kind->title.size())));
            QCOMPARE(tool->info().id,
                     "annotate." + QString::fromUtf8(kind->truth_key.data(),
                                                     qsizetype(kind->truth_key.size())));
        }
        QCOMPARE(ordinal, 5);
        // Their buttons are a bar of their own, not in the LUT editor.
        auto* bar = w.findChild<QToolBar*>("annotate_toolbar");
        QVERIFY(bar);
        QCOMPARE(bar->actions().size(), 5);
        QCOMPARE(bar->actions().front()->data().toString(),
                 w.tools().actions(QStringLiteral("annotate")).front()->data().toString());
        QVERIFY(!bar->actions().front()->icon().isNull());
        for (QToolButton* button : w.lutPanel().findChildren<QToolButton*>())
            QVERIFY2(!button->objectName().startsWith("tool.annotate"),
                     qPrintable(button->objectName()));
        QVERIFY(w.lutPanel().findChild<QToolButton*>("tool.brush"));
        for (ShapeForm form :
             {ShapeForm::Circle, ShapeForm::Box, ShapeForm::Polyline, ShapeForm::Segment})
            QVERIFY(toolOf(w, form));
    }

    /// A drag's edits are painted from the annotations document: no frame is run again, and the
    /// truth layer in the grabbed view shows the box where it was dropped, not where it was.
    void aDragPaintsTheTruthWithoutRunningTheFrame()
    {
        MainWindow w;
        QVERIFY(open(w, copyStream("drag_truth")));
        AnnotateTool* tool = toolOf(w, ShapeForm::Box);
        QVERIFY(tool);
        w.tools().activate(tool->info().id);
        QTest::mouseMove(&w.view(), at({30, 30})); // hovered: the inspector's layers are drawn
        QVERIFY(waitForFrame(w, 0));
        drag(w, {40, 40}, {80, 70});
        QVERIFY(waitForFrame(w, 0));
        const std::uint64_t serial = w.session().stream().lastSerial();
        drag(w, {60, 55}, {90, 95});
        QCOMPARE(text(shapesOn(w, 0, tool->kind())), text(EditShape{{{70, 80}, {110, 110}}, 0}));
        QCOMPARE(w.session().stream().lastSerial(), serial); // not one frame request
        QVERIFY(!w.session().stream().waiting());

        // A LUT tool: the tool's own outline of the box goes, the truth layer shows it; the
        // pointer gone, so does the tool's preview.
        QTest::keyClick(&w, Qt::Key_C);
        QVERIFY(!qobject_cast<AnnotateTool*>(&w.tools().active()));
        QEvent leave(QEvent::Leave);
        QCoreApplication::sendEvent(&w.view(), &leave);
        QCoreApplication::processEvents();
        const QImage with = w.view().grab().toImage();
        LayerSet layers = w.view().visibleLayers();
        std::erase_if(layers, [](const std::string& id) { return id.starts_with("truth."); });
        w.layersPanel().setVisibleLayers(layers);
        QCoreApplication::processEvents();
        const QImage without = w.view().grab().toImage();
        QCOMPARE(w.session().stream().lastSerial(), serial);
        QCOMPARE(with.size(), without.size());
        // Every pixel the truth changes is at the dropped box (widget px: image coordinate c is
        // at (c + 0.5) * kZoom; its outline has a dark rim, and a box's truth marks its foot),
        // none where it was; its top edge is dashed along the whole width.
        const QRectF outline(at({70, 80}), at({110, 110}));
        const QRectF near = outline.adjusted(-8, -8, 8, 8);
        int changed = 0;
        int top_edge = 0;
        for (int y = 0; y < with.height(); ++y)
            for (int x = 0; x < with.width(); ++x) {
                if (with.pixel(x, y) == without.pixel(x, y))
                    continue;
                ++changed;
                top_edge += y == int(outline.top()) && x >= outline.left() && x <= outline.right();
                QVERIFY2(near.contains(x, y), qPrintable(QStringLiteral("(%1, %2)").arg(x).arg(y)));
            }
        QVERIFY2(top_edge > 40, qPrintable(QString::number(top_edge)));
        QVERIFY2(changed > 150, qPrintable(QString::number(changed)));
    }

    /// Each form drawn with the mouse, moved, resized by a handle, undone and redone, deleted;
    /// a drag is one undo step however many moves it takes. Saved, it reads back the same.
    void eachFormIsDrawnMovedResizedAndDeleted()
    {
        struct Case
        {
            ShapeForm form;
            PointF from, to; ///< the drag that draws it
            EditShape drawn;
            PointF grab, drop; ///< the drag that moves it
            EditShape moved;
            PointF handle, pulled; ///< the drag that resizes it
            EditShape resized;
        };
        const std::vector<Case> cases = {
            {ShapeForm::Circle,
             {100, 80},
             {106, 88},
             {{{100, 80}}, 10},
             {100, 80},
             {110, 85},
             {{{110, 85}}, 10},
             {120, 85},
             {125, 85},
             {{{110, 85}}, 15}},
            {ShapeForm::Box,
             {60, 80},
             {40, 40},
             {{{40, 40}, {60, 80}}, 0},
             {50, 60},
             {55, 70},
             {{{45, 50}, {65, 90}}, 0},
             {65, 70},
             {80, 70},
             {{{45, 50}, {80, 90}}, 0}},
            {ShapeForm::Segment,
             {150, 150},
             {200, 170},
             {{{150, 150}, {200, 170}}, 0},
             {175, 160},
             {175, 150},
             {{{150, 140}, {200, 160}}, 0},
             {200, 160},
             {210, 180},
             {{{150, 140}, {210, 180}}, 0}},
        };
        const QString stream = copyStream("forms");
        MainWindow w;
        QVERIFY(open(w, stream));
        ui::AnnotationsDocument& doc = w.session().annotations();
        QUndoStack& undo = doc.undoStack();
        for (const Case& c : cases) {
            AnnotateTool* tool = toolOf(w, c.form);
            QVERIFY(tool);
            const PerceptKind& kind = tool->kind();
            w.tools().activate(tool->info().id);
            const int steps = undo.index();

            drag(w, c.from, c.to);
            QCOMPARE(text(shapesOn(w, 0, kind)), text(c.drawn));
            QCOMPARE(undo.index(), steps + 1);
            QCOMPARE(tool->selected(), std::optional<std::size_t>(0));
            QVERIFY(flagsOn(w, 0, kind).track > 0); // a track of its own
            const ui::ToolOutline outline = tool->outline();
            QCOMPARE(outline.shapes.size(), std::size_t(1));
            QCOMPARE(outline.shapes[0].colour, ui::toQColor(kind.colour));
            QVERIFY(outline.shapes[0].selected);

            drag(w, c.grab, c.drop);
            QCOMPARE(text(shapesOn(w, 0, kind)), text(c.moved));
            QCOMPARE(undo.index(), steps + 2);
            drag(w, c.handle, c.pulled);
            QCOMPARE(text(shapesOn(w, 0, kind)), text(c.resized));
            QCOMPARE(undo.index(), steps + 3);

            undo.undo();
            QCOMPARE(text(shapesOn(w, 0, kind)), text(c.moved));
            undo.undo();
            QCOMPARE(text(shapesOn(w, 0, kind)), text(c.drawn));
            undo.redo();
            undo.redo();
            QCOMPARE(text(shapesOn(w, 0, kind)), text(c.resized));

            // A click away from it selects nothing; Delete then removes nothing.
            click(w, {300, 20});
            QCOMPARE(tool->selected(), std::nullopt);
            QTest::keyClick(&w, Qt::Key_Delete);
            QCOMPARE(shapesOn(w, 0, kind).size(), std::size_t(1));
            // A click on it selects it; Delete removes it, one step; undone it is back.
            click(w, c.resized.points.back());
            QCOMPARE(tool->selected(), std::optional<std::size_t>(0));
            QTest::keyClick(&w, Qt::Key_Delete);
            QCOMPARE(shapesOn(w, 0, kind).size(), std::size_t(0));
            QCOMPARE(undo.index(), steps + 4);
            undo.undo();
            QCOMPARE(text(shapesOn(w, 0, kind)), text(c.resized));
        }

        // Shown in the view in the kind's colour: the box's left edge, away from its handles.
        AnnotateTool* boxes = toolOf(w, ShapeForm::Box);
        w.tools().activate(boxes->info().id);
        click(w, {60, 60}); // selected: drawn 3 px wide
        const QImage shown = w.view().grab().toImage();
        QCOMPARE(QColor(shown.pixel(at({45, 60}))), ui::toQColor(boxes->kind().colour));

        const QString problem = savedAndReadBack(w, stream);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    /// A polyline: clicked point by point and ended with a double click (its ends put on the
    /// image's edges), one step; a point dragged; a click on its line adds a point; Enter ends
    /// one, Escape drops one.
    void aPolylineIsClickedPointByPoint()
    {
        const QString stream = copyStream("polyline");
        MainWindow w;
        QVERIFY(open(w, stream));
        AnnotateTool* tool = toolOf(w, ShapeForm::Polyline);
        QVERIFY(tool);
        const PerceptKind& kind = tool->kind();
        w.tools().activate(tool->info().id);
        QUndoStack& undo = w.session().annotations().undoStack();
        const int steps = undo.index();

        for (PointF p : std::vector<PointF>{{2, 100}, {100, 90}, {200, 95}, {317, 100}})
            click(w, p);
        QCOMPARE(tool->draft().size(), std::size_t(4));
        QCOMPARE(undo.index(), steps); // nothing is written while it is being drawn
        QTest::mouseDClick(&w.view(), Qt::LeftButton, {}, at({317, 100}));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at({317, 100}));
        QVERIFY(tool->draft().empty());
        QCOMPARE(text(shapesOn(w, 0, kind)),
                 QStringLiteral("(0, 100) (100, 90) (200, 95) (319, 100)"));
        QCOMPARE(undo.index(), steps + 1);

        drag(w, {100, 90}, {100, 70});
        QCOMPARE(text(shapesOn(w, 0, kind)),
                 QStringLiteral("(0, 100) (100, 70) (200, 95) (319, 100)"));
        QCOMPARE(undo.index(), steps + 2);
        click(w, {260, 98}); // on the line from (200, 95) to (319, 100)
        QCOMPARE(text(shapesOn(w, 0, kind)),
                 QStringLiteral("(0, 100) (100, 70) (200, 95) (260, 98) (319, 100)"));
        QCOMPARE(undo.index(), steps + 3);
        undo.undo();
        QCOMPARE(shapesOn(w, 0, kind).front().points.size(), std::size_t(4));
        // A point pressed is chosen (ringed): Delete removes that point alone, one step; with
        // two points left Delete removes the whole line.
        drag(w, {200, 95}, {200, 95});
        QCOMPARE(tool->outline().shapes.at(0).chosen_handle, 2);
        QTest::keyClick(&w, Qt::Key_Delete);
        QCOMPARE(text(shapesOn(w, 0, kind)), QStringLiteral("(0, 100) (100, 70) (319, 100)"));
        QCOMPARE(tool->outline().shapes.at(0).chosen_handle, -1); // the choice is used up
        undo.undo();
        QCOMPARE(shapesOn(w, 0, kind).front().points.size(), std::size_t(4));
        undo.redo();
        QCOMPARE(shapesOn(w, 0, kind).front().points.size(), std::size_t(3));
        undo.undo();
        // One a frame: a click off the line starts no second one.
        click(w, {150, 200});
        QVERIFY(tool->draft().empty());

        goTo(w, 1);
        for (PointF p : std::vector<PointF>{{10, 50}, {150, 60}, {300, 55}})
            click(w, p);
        QTest::keyClick(&w.view(), Qt::Key_Return);
        QCOMPARE(text(shapesOn(w, 1, kind)), QStringLiteral("(10, 50) (150, 60) (300, 55)"));

        goTo(w, 2);
        click(w, {10, 50});
        click(w, {150, 60});
        QCOMPARE(tool->draft().size(), std::size_t(2));
        QCOMPARE(tool->outline().shapes.size(), std::size_t(1)); // the line being drawn
        QTest::keyClick(&w.view(), Qt::Key_Escape);
        QVERIFY(tool->draft().empty());
        QVERIFY(shapesOn(w, 2, kind).empty());
        QVERIFY(tool->outline().shapes.empty());

        const QString problem = savedAndReadBack(w, stream);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    /// A circle marked a keyframe (K) on frame 0, propagated over the next four frames
    /// (Ctrl+Shift+P), moved and resized on frame 4: that becomes the second keyframe and the
    /// frames between are its linear interpolation; Shift+K switches that off and on. Each
    /// action is one undo step.
    void aCircleIsInterpolatedBetweenTwoKeyframes()
    {
        const QString stream = copyStream("interpolation");
        MainWindow w;
        QVERIFY(open(w, stream));
        ScriptedDialogs dialogs;
        AnnotateTool* tool = toolOf(w, ShapeForm::Circle);
        const PerceptKind& kind = tool->kind();
        w.tools().activate(tool->info().id);
        QUndoStack& undo = w.session().annotations().undoStack();

        drag(w, {50, 50}, {55, 50});
        QCOMPARE(text(shapesOn(w, 0, kind)), text(EditShape{{{50, 50}}, 5}));
        int steps = undo.index();
        QTest::keyClick(&w, Qt::Key_K);
        QVERIFY(flagsOn(w, 0, kind).keyframe);
        QCOMPARE(undo.index(), ++steps);
        QVERIFY(w.findChild<QAction*>("object.keyframe")->isChecked());

        dialogs.numbers = {4};
        QTest::keyClick(&w, Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(dialogs.offered, QList<int>{10});
        QCOMPARE(undo.index(), ++steps);
        for (std::size_t f = 1; f <= 4; ++f)
            QCOMPARE(text(shapesOn(w, f, kind)), text(EditShape{{{50, 50}}, 5}));
        QVERIFY(shapesOn(w, 5, kind).empty());

        // On frame 4 the selection has followed the track.
        goTo(w, 4);
        QCOMPARE(tool->selected(), std::optional<std::size_t>(0));
        drag(w, {50, 50}, {90, 70});
        QCOMPARE(undo.index(), ++steps);
        drag(w, {95, 70}, {99, 70});
        QCOMPARE(undo.index(), ++steps);
        QCOMPARE(text(shapesOn(w, 4, kind)), text(EditShape{{{90, 70}}, 9}));
        QVERIFY(flagsOn(w, 4, kind).keyframe);
        for (std::size_t f = 1; f <= 3; ++f) {
            const double t = double(f) / 4.0;
            const std::vector<EditShape> shapes = shapesOn(w, f, kind);
            QCOMPARE(shapes.size(), std::size_t(1));
            QCOMPARE(shapes[0].points[0].x, 50 + 40 * t);
            QCOMPARE(shapes[0].points[0].y, 50 + 20 * t);
            QCOMPARE(shapes[0].radius, 5 + 4 * t);
            QVERIFY(flagsOn(w, f, kind).interpolated);
            QCOMPARE(flagsOn(w, f, kind).track, flagsOn(w, 0, kind).track);
        }
        QCOMPARE(text(shapesOn(w, 2, kind)), text(EditShape{{{70, 60}}, 7}));
        // The moves' step undone: the frames between are the copies again.
        undo.undo();
        undo.undo();
        QCOMPARE(text(shapesOn(w, 2, kind)), text(EditShape{{{50, 50}}, 5}));
        undo.redo();
        undo.redo();
        QCOMPARE(text(shapesOn(w, 2, kind)), text(EditShape{{{70, 60}}, 7}));

        // Shift+K on the second keyframe: not interpolated, the frames between are empty.
        QTest::keyClick(&w, Qt::Key_K, Qt::ShiftModifier);
        QCOMPARE(undo.index(), ++steps);
        QVERIFY(!flagsOn(w, 4, kind).interpolate);
        for (std::size_t f = 1; f <= 3; ++f)
            QVERIFY(shapesOn(w, f, kind).empty());
        QTest::keyClick(&w, Qt::Key_K, Qt::ShiftModifier);
        QCOMPARE(text(shapesOn(w, 3, kind)), text(EditShape{{{80, 65}}, 8}));

        // The interpolated ball on frame 2 deleted stays deleted: frame 3 keeps its shape and a
        // move of keyframe 4 no longer reaches the span.
        goTo(w, 2);
        click(w, {70, 60});
        QCOMPARE(tool->selected(), std::optional<std::size_t>(0));
        steps = undo.index();
        QTest::keyClick(&w, Qt::Key_Delete);
        QCOMPARE(undo.index(), ++steps);
        QVERIFY(shapesOn(w, 2, kind).empty());
        goTo(w, 4);
        drag(w, {90, 70}, {92, 70});
        QVERIFY(shapesOn(w, 2, kind).empty());
        QCOMPARE(text(shapesOn(w, 3, kind)), text(EditShape{{{80, 65}}, 8}));
        QVERIFY(!flagsOn(w, 3, kind).interpolated);

        // Backwards (Ctrl+Alt+P) from a new circle on frame 10, offered the last count again.
        goTo(w, 10);
        drag(w, {200, 100}, {200, 106});
        dialogs.numbers = {2};
        QTest::keyClick(&w, Qt::Key_P, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(dialogs.offered, (QList<int>{10, 4}));
        for (std::size_t f : {8, 9})
            QCOMPARE(text(shapesOn(w, f, kind)), text(EditShape{{{200, 100}}, 6}));
        QVERIFY(shapesOn(w, 7, kind).empty());
        QVERIFY(flagsOn(w, 9, kind).track != flagsOn(w, 0, kind).track);

        const QString problem = savedAndReadBack(w, stream);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));

        // The count is remembered with the window's settings: the next session offers it.
        QVERIFY(w.close());
        MainWindow next;
        QVERIFY(open(next, stream));
        next.tools().activate(tool->info().id);
        goTo(next, 0);
        click(next, {50, 50}); // frame 0's keyframe, selected
        dialogs.numbers = {1};
        QTest::keyClick(&next, Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(dialogs.offered, (QList<int>{10, 4, 2}));
    }

    /// Q marks the selected object concealed (one step, saved in the file) and clears it;
    /// without a selection the object keys change nothing and say how to select.
    void concealedIsToggledAndSaved()
    {
        const QString stream = copyStream("concealed");
        MainWindow w;
        QVERIFY(open(w, stream));
        AnnotateTool* tool = toolOf(w, ShapeForm::Box);
        const PerceptKind& kind = tool->kind();
        w.tools().activate(tool->info().id);
        QUndoStack& undo = w.session().annotations().undoStack();
        drag(w, {20, 20}, {40, 60});
        drag(w, {100, 20}, {140, 60});
        QCOMPARE(tool->selected(), std::optional<std::size_t>(1));
        const int steps = undo.index();

        QTest::keyClick(&w, Qt::Key_Q);
        QVERIFY(flagsOn(w, 0, kind, 1).concealed);
        QVERIFY(!flagsOn(w, 0, kind, 0).concealed);
        QCOMPARE(undo.index(), steps + 1);
        QVERIFY(w.findChild<QAction*>("object.concealed")->isChecked());
        QVERIFY(w.session().annotations().save().ok());
        const QByteArray saved = fileBytes(stream + "/annotations.json");
        QVERIFY2(saved.contains("\"concealed\": true") || saved.contains("\"concealed\":true"),
                 saved.constData());
        ui::EditingSession again;
        QVERIFY(again.open(stream).ok());
        const FrameAnnotation* read = again.annotations().frame(frameName(w, 0));
        QVERIFY(read);
        QVERIFY(read->flagsOf(kind.truth_key, 1).concealed);
        QVERIFY(!read->flagsOf(kind.truth_key, 0).concealed);

        // Deleting the first box moves the second's flag along with it.
        click(w, {30, 40});
        QTest::keyClick(&w, Qt::Key_Delete);
        QVERIFY(flagsOn(w, 0, kind, 0).concealed);

        // Escape in the view drops the selection: then no object key does anything.
        click(w, {120, 40});
        QCOMPARE(tool->selected(), std::optional<std::size_t>(0));
        QTest::keyClick(&w.view(), Qt::Key_Escape);
        QCOMPARE(tool->selected(), std::nullopt);
        const int before = undo.index();
        QTest::keyClick(&w, Qt::Key_Q);
        QTest::keyClick(&w, Qt::Key_K);
        QCOMPARE(undo.index(), before);
        QVERIFY(w.statusBar()->currentMessage().contains("Select an object"));

        click(w, {120, 40});
        QTest::keyClick(&w, Qt::Key_Q);
        QVERIFY(!flagsOn(w, 0, kind, 0).concealed);
        QVERIFY(!w.findChild<QAction*>("object.concealed")->isChecked());
    }
};

FIELDSIGHT_TEST_SUITE(TestAnnotateTools, Widgets)

#include "test_annotate_tools.moc"
