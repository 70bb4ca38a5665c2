// Not a test: saves a screenshot of the main window in a given state, to look at the GUI as a
// user would on a machine without a display (QT_QPA_PLATFORM=offscreen or xvfb-run).
//   gui_screenshot OUT.png STREAM [--lut FILE] [--set S.P=V] [--frame N] [--size WxH]
//                  [--layers all|default|ID,...] [--mode raw|classified|side|blend]
//                  [--zoom Z] [--focus LABEL] [--hover X,Y] [--dock OBJECT_NAME]...
//                  [--colour NAME] [--tool ID] [--click X,Y]... [--drag X0,Y0,X1,Y1]...
//                  [--preview X,Y] [--uv-select CB0,CR0,CB1,CR1] [--y-range LO,HI]
//                  [--orientation 0|90|180|270] [--disagreement ROW] [--signature FILE]
// --click presses the tool at image pixel X,Y (the LUT tools edit the table there, the annotation
// tools select), --drag drags it from X0,Y0 to X1,Y1 (draws or moves an annotated object);
// --preview hovers the tool there (all at zoom 1 unless --zoom); the whole-stream scan is waited
// for before the shot. --orientation turns the stream's pictures as View > Orientation does,
// before anything else. The evaluation is waited for; --disagreement chooses a row of its list
// of disagreements (go there, culprits drawn; --dock evaluation_dock shows the list).
// --signature writes what the shot shows of the window's make-up (menus, docks, tool bars, layers)
// beside it, so a check can tell a screenshot made from an older window (docs/make_screenshots.sh).
#include "ui/actions/session_files.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
#include "ui/panels/layers_panel.h"
#include "ui/panels/inspector_panel.h"
#include "ui/panels/lut_panel.h"
#include "ui/panels/uv_plane_panel.h"
#include "ui/scans/edit_effect_scan.h"
#include "ui/panels/evaluation_panel.h"

#include "tool_platform.h"

#include <QApplication>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTabBar>
#include <QSaveFile>
#include <QToolBar>
#include <QTreeWidgetItemIterator>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QSignalSpy>
#include <QTest>

#include <iostream>

using namespace fieldsight;

namespace {

QString withoutMnemonic(QString text)
{
    return text.remove(QRegularExpression("&(?!&)"));
}

/// What a screenshot shows of the window's make-up, one fact a line, in the window's own order:
/// when the window gains a menu, a dock, a tool bar button or a layer, this changes and the
/// screenshot made before is out of date.
QString windowSignature(ui::MainWindow& w)
{
    QStringList lines;
    QStringList menus;
    for (QAction* a : w.menuBar()->actions())
        if (a->isVisible() && !a->text().isEmpty())
            menus << withoutMnemonic(a->text());
    lines << "menus: " + menus.join(" | ");
    // Docks alone, and each group of tabbed docks as its tab bar shows it (* the tab in front).
    QStringList docks;
    for (QDockWidget* d : w.findChildren<QDockWidget*>())
        if (d->toggleViewAction()->isChecked() && w.tabifiedDockWidgets(d).isEmpty())
            docks << "dock: " + d->windowTitle();
    for (QTabBar* bar : w.findChildren<QTabBar*>()) {
        if (!bar->isVisible() || bar->parentWidget() != &w)
            continue; // a tab bar of a widget inside a dock, or one left over from a regrouping
        QStringList tabs;
        for (int i = 0; i < bar->count(); ++i)
            tabs << (i == bar->currentIndex() ? "*" : "") + bar->tabText(i);
        docks << "tabs: " + tabs.join(" | ");
    }
    docks.sort();
    lines << docks;
    for (QToolBar* bar : w.findChildren<QToolBar*>()) {
        if (bar->isHidden())
            continue;
        QStringList ids;
        for (QAction* a : bar->actions())
            if (!a->isSeparator() && a->isVisible())
                ids << (a->objectName().isEmpty() ? withoutMnemonic(a->text()) : a->objectName());
        lines << "toolbar " + bar->objectName() + ": " + ids.join(' ');
    }
    {
        for (QTreeWidgetItemIterator it(&w.layersPanel()); *it; ++it) {
            const bool checkable = (*it)->flags() & Qt::ItemIsUserCheckable;
            const QString mark = !checkable                                     ? "   "
                                 : (*it)->checkState(0) == Qt::Unchecked        ? "[ ]"
                                 : (*it)->checkState(0) == Qt::PartiallyChecked ? "[~]"
                                                                                : "[x]";
            lines << "layer " + mark + " " + (*it)->text(0);
        }
    }
    return lines.join('\n') + '\n';
}

} // namespace

int main(int argc, char** argv)
{
    tools::useOffscreenWithoutDisplay();
    QApplication app(argc, argv);
    QApplication::setOrganizationName("FieldsightScreenshots");
    QCommandLineParser p;
    p.setApplicationDescription(
        "Saves a screenshot of the main window with STREAM open, in the state the options set "
        "(applied in the order listed). Runs offscreen when no display is set. The user guide's "
        "screenshots are made with it: docs/make_screenshots.sh.");
    p.addHelpOption();
    p.addPositionalArgument("OUT.png", "the PNG to write");
    p.addPositionalArgument("STREAM", "the stream to open (a folder, a .strm, a video)");
    const struct
    {
        const char* name;
        const char* value;
        const char* help;
    } options[] = {
        {"lut", "FILE", "the colour table (default: the stream's)"},
        {"set", "STAGE.PARAM=VALUE", "a stage parameter (repeatable)"},
        {"orientation", "0|90|180|270", "turn the pictures as View > Orientation does"},
        {"frame", "N", "the frame to show (default 0)"},
        {"size", "WxH", "the window's size (default 1280x800)"},
        {"layers", "all|default|ID,...",
         "the layers shown (stage ids, truth, percepts, layer ids)"},
        {"mode", "raw|classified|side|blend", "the view mode (default raw)"},
        {"zoom", "Z", "the view's zoom"},
        {"focus", "TEXT", "with --zoom: centre the first detection whose label starts with TEXT"},
        {"hover", "X,Y", "the Pixel inspector on image pixel X,Y"},
        {"dock", "OBJECT_NAME", "bring a tabbed dock to the front, e.g. lut_dock (repeatable)"},
        {"colour", "NAME", "the LUT editor's class"},
        {"tool", "ID", "the active tool (click, brush, erase, wand, sample, an annotation tool)"},
        {"y-range", "LO,HI", "the UV plane's Y range"},
        {"click", "X,Y", "press the tool at image pixel X,Y (repeatable)"},
        {"drag", "X0,Y0,X1,Y1", "drag the tool from X0,Y0 to X1,Y1 (repeatable)"},
        {"uv-select", "CB0,CR0,CB1,CR1", "select UV plane cells (right-drag)"},
        {"preview", "X,Y", "hover the tool at image pixel X,Y (its preview)"},
        {"disagreement", "ROW", "choose a row of the evaluation's disagreements"},
        {"signature", "FILE",
         "also write the window's structure (menu titles, docks and their tabs, tool bars' action "
         "ids, the layer list) to FILE; docs/make_screenshots.sh --check compares it with the "
         "one committed beside each screenshot"},
    };
    for (const auto& o : options)
        p.addOption({o.name, o.help, o.value});
    p.process(app);
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) {
        std::cerr << "usage: gui_screenshot OUT.png STREAM [options] (gui_screenshot --help says "
                     "more)\n";
        return 2;
    }
    ui::MainWindow w;
    if (p.isSet("set")) {
        ParamSet params;
        for (const QString& s : p.values("set"))
            if (!params.parseSetting(s.toStdString())) {
                std::cerr << "bad --set\n";
                return 2;
            }
        (void)w.session().settings().setParamChanges(params);
        w.session().setParamOverrides(params);
    }
    const QStringList size =
        p.value("size").isEmpty() ? QStringList{"1280", "800"} : p.value("size").split('x');
    w.resize(size[0].toInt(), size[1].toInt());
    w.show();
    QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
    w.files().openStream(pos[1], p.value("lut"));
    if (!opened.wait(20000) || !opened.front().front().toBool()) {
        std::cerr << "cannot open: " << w.lastMessage().toStdString() << "\n";
        return 1;
    }
    auto waitFrame = [&] {
        QSignalSpy ready(&w.session().stream(), &ui::StreamDocument::frameReady);
        while (w.session().stream().waiting() && ready.wait(5000)) {
        }
        QApplication::processEvents();
    };
    waitFrame();
    if (p.isSet("orientation")) {
        const auto o = orientationFromDegrees(p.value("orientation").toLongLong());
        Status turned = o ? w.session().stream().setOrientation(*o)
                          : Status(Error{"--orientation: expected 0, 90, 180 or 270"});
        if (!turned) {
            std::cerr << turned.error().message << "\n";
            return 2;
        }
        waitFrame();
    }
    if (p.isSet("frame")) {
        w.session().stream().setCurrentIndex(p.value("frame").toULongLong());
        waitFrame();
    }
    const QString layers = p.value("layers");
    if (!layers.isEmpty() && layers != "default") {
        auto chosen = selectLayers(layers.toStdString(), w.session().stream().pipeline());
        if (!chosen) {
            std::cerr << chosen.error().message << "\n";
            return 2;
        }
        w.layersPanel().setVisibleLayers(chosen.value());
    } else {
        w.layersPanel().setVisibleLayers(
            ui::LayersPanel::defaultLayers(w.session().stream().pipeline()));
    }
    waitFrame(); // a stage layer shown runs the frame again to draw it
    const QString mode = p.value("mode");
    const ui::ViewMode m = mode == "classified" ? ui::ViewMode::Classified
                           : mode == "side"     ? ui::ViewMode::SideBySide
                           : mode == "blend"    ? ui::ViewMode::Blend
                                                : ui::ViewMode::Raw;
    w.view().setMode(m);
    QApplication::processEvents();
    if (p.isSet("zoom")) {
        const double zoom = p.value("zoom").toDouble();
        w.view().setZoom(zoom);
        const auto& out = w.session().stream().current();
        for (const ui::PerceptItem& item : out ? out->items : std::vector<ui::PerceptItem>{}) {
            if (!p.isSet("focus") || !item.label.startsWith(p.value("focus")))
                continue;
            const QPointF c = (item.bounds.center() + QPointF(0.5, 0.5)) * zoom;
            w.view().setImageOrigin((QPointF(w.view().rect().center()) - c).toPoint());
            break;
        }
    }
    if (p.isSet("hover")) {
        const QStringList xy = p.value("hover").split(',');
        w.inspector().inspect(w.session().stream().current().get(),
                              QPoint(xy[0].toInt(), xy[1].toInt()));
    }
    for (const QString& name : p.values("dock")) // bring tabbed docks to the front ("lut_dock")
        if (auto* dock = w.findChild<QDockWidget*>(name))
            dock->raise();
    QApplication::processEvents();
    if (p.isSet("colour"))
        if (auto c = colourFromName(p.value("colour").toStdString()))
            w.tools().settings().setColour(*c);
    const QString tool = p.value("tool");
    if (!tool.isEmpty())
        w.tools().activate(tool);
    const auto viewPoint = [&](const QString& xy) {
        const QStringList v = xy.split(',');
        const double z = w.view().zoom();
        return QPoint(int(w.view().imageOrigin().x() + (v[0].toInt() + 0.5) * z),
                      int(w.view().imageOrigin().y() + (v[1].toInt() + 0.5) * z));
    };
    if (!p.isSet("zoom") && (p.isSet("click") || p.isSet("drag") || p.isSet("preview"))) {
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
    }
    if (p.isSet("y-range")) {
        const QStringList v = p.value("y-range").split(',');
        w.uvPanel().setYLevels(v[0].toInt(), v[1].toInt());
    }
    // Edits are scored against the evaluation of the table before them.
    const auto waitEvaluation = [&w] {
        ui::EvaluationScan& scan = w.session().evaluation();
        for (int i = 0; i < 6000 && (scan.running() || scan.pending()); ++i)
            QTest::qWait(10);
    };
    if (p.isSet("click") || p.isSet("drag"))
        waitEvaluation();
    for (const QString& xy : p.values("click")) {
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, viewPoint(xy));
        waitFrame();
    }
    for (const QString& xyxy : p.values("drag")) {
        const QStringList v = xyxy.split(',');
        if (v.size() != 4) {
            std::cerr << "--drag: expected X0,Y0,X1,Y1\n";
            return 2;
        }
        const QPoint from = viewPoint(v[0] + ',' + v[1]);
        const QPoint to = viewPoint(v[2] + ',' + v[3]);
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, from);
        QTest::mouseMove(&w.view(), (from + to) / 2);
        QTest::mouseMove(&w.view(), to);
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, to);
        waitFrame();
    }
    if (p.isSet("uv-select")) {
        const QStringList v = p.value("uv-select").split(',');
        ui::UvCanvas& canvas = w.uvPanel().canvas();
        QTest::mousePress(&canvas, Qt::RightButton, {},
                          canvas.cellCentre(v[0].toInt(), v[1].toInt()).toPoint());
        QTest::mouseMove(&canvas, canvas.cellCentre(v[2].toInt(), v[3].toInt()).toPoint());
        QTest::mouseRelease(&canvas, Qt::RightButton, {},
                            canvas.cellCentre(v[2].toInt(), v[3].toInt()).toPoint());
    }
    if (p.isSet("preview"))
        QTest::mouseMove(&w.view(), viewPoint(p.value("preview")));
    for (int i = 0; i < 2000 && w.session().effectScan().running(); ++i)
        QTest::qWait(10);
    waitEvaluation();
    if (p.isSet("disagreement")) {
        w.evaluationPanel().showDisagreement(p.value("disagreement").toInt());
        waitFrame();
    }
    QApplication::processEvents();
    QTest::qWait(50);
    const QImage shot = w.grab().toImage();
    if (!shot.save(pos[0])) {
        std::cerr << "cannot write " << pos[0].toStdString() << "\n";
        return 1;
    }
    if (p.isSet("signature")) {
        QSaveFile file(p.value("signature"));
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
            file.write(windowSignature(w).toUtf8()) < 0 || !file.commit()) {
            std::cerr << "cannot write " << p.value("signature").toStdString() << "\n";
            return 1;
        }
    }
    std::cout << pos[0].toStdString() << " " << shot.width() << "x" << shot.height() << "\n";
    return 0;
}
