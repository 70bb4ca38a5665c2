// The GUI's speed (issue 8's targets), measured offscreen on the real main window with every layer
// on (or those `--layers` names; `--layers default` the window's own), and printed; nothing is
// asserted (timings depend on the machine). Label `bench`:
//   ctest --test-dir build -L bench -R bench_gui --verbose  or  build/tests/bench_gui [DIR
//   [--steps-only]]
// - step: key press (Right) to the painted frame, median and 95th percentile, at 320x240,
//   640x480 and 1280x720 (generated with synth; `--sizes`), from PNG folders and .strm files;
// - play: frames painted per second at 60 fps with every layer on;
// - a parameter edit to the repainted frame;
// - a LUT edit (a click's tolerance box) to the repainted frame, and to the whole-stream effect
//   strip fully updated, with the window's longest stall and frame steps meanwhile
//   (`bench_gui DIR --edits-only` runs this part alone);
// - an annotation drag: a box tool's drag, each mouse move to the view painted with it, and the
//   frame requests the drag made (with the steps: `--steps-only` times it too);
// - opening a 9,000-frame .strm and a folder of 9,000 PNGs, and resident memory while playing the
//   .strm through.
#include "commands/commands.h"
#include "ui/actions/session_files.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
#include "ui/scans/edit_effect_scan.h"
#include "ui/panels/layers_panel.h"
#include "ui/tools/annotate_tool.h"
#include "visioncore/services/lut_editing.h"
#include "ui/stream_navigator/stream_navigator.h"

#include "tool_platform.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QTest>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <unistd.h>

using namespace fieldsight;
using fieldsight::ui::MainWindow;

namespace {

double rssMb()
{
    long pages = 0, resident = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
            resident = 0;
        std::fclose(f);
    }
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

bool synth(const QString& out, int width, int height, int frames, bool strm)
{
    std::ostringstream o, e;
    const cli::Context ctx{Pipeline::standard(), o, e};
    QStringList args{"fieldsight",
                     "--scenario",
                     "lab1",
                     "--frames",
                     QString::number(frames),
                     "--seed",
                     "3",
                     "--width",
                     QString::number(width),
                     "--height",
                     QString::number(height),
                     "--out",
                     out};
    if (strm)
        args << "--strm";
    const int status = cli::runHeadless("synth", args, ctx);
    if (status != 0)
        std::cerr << e.str();
    return status == 0;
}

/// Waits until the view painted the answer to the document's newest request.
bool waitPainted(MainWindow& w, int timeout_ms = 5000)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < timeout_ms) {
        if (!w.session().stream().waiting() &&
            w.view().paintedSerial() >= w.session().stream().lastSerial())
            return true;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    }
    return false;
}

bool open(MainWindow& w, const QString& stream)
{
    QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
    w.files().openStream(stream);
    return opened.wait(60000) && opened.front().front().toBool() && waitPainted(w);
}

/// The layers shown: "all" unless --layers says otherwise ("default": the window's defaults).
std::string g_layers = "all";

void showLayers(MainWindow& w)
{
    const Pipeline& pipeline = w.session().stream().pipeline();
    w.layersPanel().setVisibleLayers(g_layers == "default"
                                         ? ui::LayersPanel::defaultLayers(pipeline)
                                         : selectLayers(g_layers, pipeline).value());
    (void)waitPainted(w); // a stage layer shown runs the frame again
}

/// A click's edit at `p` of the current frame: its tolerance box becomes `colour`.
bool clickEdit(MainWindow& w, QPoint p, Colour colour)
{
    const cv::Mat& px = w.session().stream().current()->frame.ycbcr;
    const cv::Vec3b c = px.at<cv::Vec3b>(p.y() % px.rows, p.x() % px.cols);
    const auto cells = cellsInBox(c[0], c[1], c[2], {6, 4, 4});
    return w.session().lut().edit("bench", changesTo(w.session().lut().table(), cells, colour));
}

/// Waits for the whole-stream scan in a sleeping event loop (as the window's own); returns the
/// loop's longest gap between 5 ms timer ticks (ms) meanwhile, and the times of frame steps (step
/// to painted) taken every 100 ms while it ran.
double waitForScan(MainWindow& w, std::vector<double>* steps)
{
    ui::EditEffectScan& scan = w.session().effectScan();
    QEventLoop loop;
    QTimer tick;
    tick.setInterval(5);
    QElapsedTimer clock, gap, since_step, step;
    clock.start();
    gap.start();
    since_step.start();
    bool stepping = false;
    double longest = 0;
    QObject::connect(&w.view(), &ui::FrameView::painted, &loop, [&] {
        if (stepping && !w.session().stream().waiting() &&
            w.view().paintedSerial() >= w.session().stream().lastSerial()) {
            steps->push_back(double(step.nsecsElapsed()) / 1e6);
            stepping = false;
        }
    });
    QObject::connect(&tick, &QTimer::timeout, &loop, [&] {
        longest = std::max(longest, double(gap.nsecsElapsed()) / 1e6);
        gap.restart();
        if (!scan.running() || clock.elapsed() > 60000)
            loop.quit();
        if (steps && !stepping && since_step.elapsed() > 100) {
            stepping = true;
            step.start();
            since_step.restart();
            w.navigator().step(1);
        }
    });
    tick.start();
    loop.exec();
    return longest;
}

void benchEdits(const QString& label, const QString& stream, int scans)
{
    MainWindow w;
    w.resize(1280, 800);
    w.show();
    QElapsedTimer opened;
    opened.start();
    if (!open(w, stream)) {
        std::cout << label.toStdString() << ": cannot open\n";
        return;
    }
    showLayers(w);
    waitForScan(w, nullptr);
    std::printf("%-20s first whole-stream scan (%zu frames) done %.2f s after the open\n",
                qPrintable(label), w.session().effectScan().effects().size(),
                double(opened.elapsed()) / 1000.0);

    // Edit to repaint: 40 click edits at different pixels, alternately pink and unclassified;
    // then again with the UV plane in front (it redraws the table at every edit).
    for (const bool uv : {false, true}) {
        if (uv)
            if (auto* dock = w.findChild<QDockWidget*>("uv_dock"))
                dock->raise();
        std::vector<double> repaint;
        for (int i = 0; i < 40; ++i) {
            QElapsedTimer t;
            t.start();
            if (!clickEdit(w, QPoint(37 * i + 5, 23 * i + 100),
                           i % 2 ? Colour::Unclassified : Colour::Pink))
                continue;
            if (waitPainted(w)) {
                QCoreApplication::processEvents(); // the rest of the window's paint
                repaint.push_back(double(t.nsecsElapsed()) / 1e6);
            }
            QTest::qWait(20);
        }
        std::printf("%-20s edit to repainted frame%s: median %5.2f ms  p95 %5.2f ms  max %5.2f "
                    "ms (%zu edits)\n",
                    qPrintable(label), uv ? " (UV plane shown)" : "", percentile(repaint, 0.5),
                    percentile(repaint, 0.95), percentile(repaint, 1.0), repaint.size());
    }
    waitForScan(w, nullptr);

    // The worst case, an edit of the field colour that changes pixels in every frame; then an
    // edit of the ball's colour, which only frames with a ball show.
    for (int i = 0; i < scans; ++i) {
        QPoint at(150 + 10 * i, 200);
        Colour colour = Colour::Yellow;
        QString what = QStringLiteral("field colour");
        const auto& balls = w.session().stream().current()->result.percepts.list<Ball>();
        if (i % 2 == 1 && !balls.empty()) {
            at = QPoint(int(balls.front().x), int(balls.front().y));
            colour = Colour::Pink;
            what = QStringLiteral("ball colour");
        }
        clickEdit(w, at, colour);
        std::vector<double> steps;
        const double stall = waitForScan(w, &steps);
        std::size_t changed = 0;
        for (const auto& e : w.session().effectScan().effects())
            changed += e.changed_pixels > 0;
        std::printf("%-20s %s edit to whole-stream strip updated: %.2f s (%zu frames, %zu "
                    "changed); longest event-loop stall %.1f ms; steps meanwhile median %.1f ms "
                    "max %.1f ms\n",
                    qPrintable(label), qPrintable(what),
                    w.session().effectScan().lastScanMs() / 1000.0,
                    w.session().effectScan().framesDone(), changed, stall, percentile(steps, 0.5),
                    percentile(steps, 1.0));
    }
}

/// `w` shown at 1280x800 with `stream` open and the bench's layers on; false (said) if the
/// stream cannot be opened.
bool showWithStream(MainWindow& w, const QString& label, const QString& stream)
{
    w.resize(1280, 800);
    w.show();
    (void)QTest::qWaitForWindowActive(&w);
    if (!open(w, stream)) {
        std::cout << label.toStdString() << ": cannot open\n";
        return false;
    }
    showLayers(w);
    return true;
}

void benchStepping(const QString& label, const QString& stream)
{
    MainWindow w;
    if (!showWithStream(w, label, stream))
        return;
    // Two rounds over the stream: steps 30 ms apart (a held key repeats at 25-40 per second, and
    // a single press comes later still), then back to back (each key as soon as the last frame
    // is painted, so the next frame's prefetch is often still running).
    QElapsedTimer t;
    double ready = 0;
    const QMetaObject::Connection on_ready =
        QObject::connect(&w.session().stream(), &ui::StreamDocument::frameReady,
                         [&] { ready = double(t.nsecsElapsed()) / 1e6; });
    for (const int gap_ms : {30, 0}) {
        w.session().stream().setCurrentIndex(0);
        (void)waitPainted(w);
        std::vector<double> step_ms, wait_ms, worker_ms, paint_ms, ready_ms;
        const int frames = int(w.session().stream().frameCount());
        for (int i = 1; i < frames; ++i) {
            if (gap_ms > 0)
                QTest::qWait(gap_ms);
            t.start();
            QTest::keyClick(&w, Qt::Key_Right);
            if (!waitPainted(w))
                break;
            step_ms.push_back(double(t.nsecsElapsed()) / 1e6);
            ready_ms.push_back(ready);
            wait_ms.push_back(w.session().stream().current()->wait_ms);
            worker_ms.push_back(w.session().stream().current()->worker_ms);
            paint_ms.push_back(w.view().lastPaintMs());
        }
        std::printf("%-20s step %-13s median %5.2f ms  p95 %5.2f ms  (result in %5.2f ms, "
                    "worker waking %5.2f ms, working %5.2f ms, view paint %5.2f ms, %zu steps)\n",
                    qPrintable(label), gap_ms > 0 ? "30 ms apart" : "back to back",
                    percentile(step_ms, 0.5), percentile(step_ms, 0.95), percentile(ready_ms, 0.5),
                    percentile(wait_ms, 0.5), percentile(worker_ms, 0.5), percentile(paint_ms, 0.5),
                    step_ms.size());
    }
    QObject::disconnect(on_ready);
    std::vector<double> edit_ms;
    for (int i = 0; i < 20; ++i) {
        t.start();
        const StageDescriptor& stage = w.session().stream().pipeline().descriptors().front();
        const ParamInfo& p = stage.params.front();
        (void)w.session().settings().setParam(stage.info.id, p.name,
                                              i % 2 ? p.default_value : p.default_value + p.step);
        if (!waitPainted(w))
            break;
        edit_ms.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    std::printf("%-20s parameter edit     median %5.2f ms  max %5.2f ms\n", qPrintable(label),
                percentile(edit_ms, 0.5), percentile(edit_ms, 1.0));

    // Play at 60 fps for two seconds, looping.
    w.session().stream().setCurrentIndex(0);
    (void)waitPainted(w);
    w.navigator().setSpeed(60);
    w.navigator().loopAction()->setChecked(true);
    std::uint64_t painted = 0, last = w.view().paintedSerial();
    QObject::connect(&w.view(), &ui::FrameView::painted, [&](std::uint64_t serial) {
        if (serial != last)
            ++painted;
        last = serial;
    });
    t.start();
    w.navigator().setPlaying(true);
    while (t.elapsed() < 2000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    w.navigator().setPlaying(false);
    std::printf("%-20s play at 60 fps: %.1f frames painted per second\n", qPrintable(label),
                double(painted) * 1000.0 / double(t.elapsed()));
}

/// An annotation drag with every layer on: a box drawn with its tool at 2x, then grabbed and
/// moved a pixel at a time; each mouse move's time to the view painted with it (and with every
/// frame request made meanwhile answered), and the frame requests the whole drag made.
void benchDrag(const QString& label, const QString& stream)
{
    MainWindow w;
    if (!showWithStream(w, label, stream))
        return;
    (void)waitPainted(w);
    for (const auto& tool : w.tools().tools())
        if (auto* a = qobject_cast<ui::AnnotateTool*>(tool.get());
            a && a->kind().form == ShapeForm::Box) {
            w.tools().activate(a->info().id);
            break;
        }
    if (!qobject_cast<ui::AnnotateTool*>(&w.tools().active())) {
        std::cout << label.toStdString() << ": no box tool\n";
        return;
    }
    constexpr int kZoom = 2;
    w.view().setZoom(kZoom);
    w.view().setImageOrigin({0, 0});
    const auto at = [](int x, int y) { return QPoint(x * kZoom + 1, y * kZoom + 1); };
    QTest::mousePress(&w.view(), Qt::LeftButton, {}, at(40, 40));
    QTest::mouseMove(&w.view(), at(60, 55));
    QTest::mouseMove(&w.view(), at(80, 70));
    QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at(80, 70));
    (void)waitPainted(w);
    QTest::qWait(100);

    // A paint counts once it shows the newest answer: a move that asks the worker again is
    // painted only with that answer.
    int settled = 0;
    const QMetaObject::Connection on_paint =
        QObject::connect(&w.view(), &ui::FrameView::painted, [&] {
            settled += !w.session().stream().waiting() &&
                       w.view().paintedSerial() >= w.session().stream().lastSerial();
        });
    const std::uint64_t serial_before = w.session().stream().lastSerial();
    std::vector<double> move_ms;
    QTest::mousePress(&w.view(), Qt::LeftButton, {}, at(60, 55));
    for (int i = 1; i <= 40; ++i) {
        const int before = settled;
        QElapsedTimer t;
        t.start();
        QTest::mouseMove(&w.view(), at(60 + i, 55 + i / 2));
        while (settled == before && t.elapsed() < 5000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
        if (settled == before)
            break;
        move_ms.push_back(double(t.nsecsElapsed()) / 1e6);
        QTest::qWait(16); // a mouse moves at about 60 events a second
    }
    QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at(100, 75));
    QObject::disconnect(on_paint);
    std::printf("%-20s annotation drag    move to repaint median %5.2f ms  p95 %5.2f ms  max "
                "%5.2f ms (%zu moves, %llu frame requests)\n",
                qPrintable(label), percentile(move_ms, 0.5), percentile(move_ms, 0.95),
                percentile(move_ms, 1.0), move_ms.size(),
                static_cast<unsigned long long>(w.session().stream().lastSerial() - serial_before));
}

} // namespace

int main(int argc, char** argv)
{
    tools::useOffscreenWithoutDisplay();
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Times the main window, offscreen, with every layer on, at 1280x800: a step to the painted "
        "frame (320x240, 640x480 and 1280x720 or --sizes, PNG folders and .strm), play, a "
        "parameter edit, a LUT edit to "
        "the repainted frame and to the whole-stream strip, opening 9,000-frame streams and memory "
        "while playing. The streams are generated in DIR (kept between runs) or in a temporary "
        "folder. Prints the times; asserts nothing.");
    parser.addHelpOption();
    parser.addPositionalArgument("DIR", "where the generated streams are kept between runs",
                                 "[DIR]");
    const QCommandLineOption steps_option("steps-only", "only the steps");
    const QCommandLineOption edits_option("edits-only", "only the LUT edits");
    const QCommandLineOption sizes_option(
        "sizes", "the frame sizes stepped through (default 320x240,640x480,1280x720)", "WxH,...",
        "320x240,640x480,1280x720");
    parser.addOption(steps_option);
    parser.addOption(edits_option);
    parser.addOption(sizes_option);
    const QCommandLineOption layers_option(
        "layers", "the layers shown (default all; \"default\": the window's own defaults)", "LIST",
        "all");
    parser.addOption(layers_option);
    parser.process(app);
    if (parser.positionalArguments().size() > 1) {
        std::cerr << "usage: bench_gui [DIR] [--steps-only | --edits-only] (bench_gui --help says "
                     "more)\n";
        return 2;
    }
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FieldsightBench");
    QSettings().clear();
    QTemporaryDir tmp;
    const QString dir =
        parser.positionalArguments().isEmpty() ? tmp.path() : parser.positionalArguments().front();
    const bool steps_only = parser.isSet(steps_option);
    g_layers = parser.value(layers_option).toStdString();
    if (g_layers != "default" && !selectLayers(g_layers, Pipeline::standard())) {
        std::cerr << "bench_gui: --layers: "
                  << selectLayers(g_layers, Pipeline::standard()).error().message << "\n";
        return 2;
    }
    const bool edits_only = parser.isSet(edits_option);
    std::printf("bench_gui: offscreen, layers %s, window 1280x800\n", g_layers.c_str());

    std::vector<std::pair<int, int>> sizes;
    for (const QString& size : parser.value(sizes_option).split(',', Qt::SkipEmptyParts)) {
        const QStringList wh = size.split('x');
        const int w = wh.value(0).toInt(), h = wh.value(1).toInt();
        if (wh.size() != 2 || w < 16 || h < 16) {
            std::cerr << "bench_gui: --sizes takes WxH,... (e.g. 320x240,1280x720)\n";
            return 2;
        }
        sizes.emplace_back(w, h);
    }
    // The edit benchmarks below use the 320x240 and 640x480 streams whatever --sizes says.
    for (const auto& [w, h] : {std::pair{320, 240}, std::pair{640, 480}})
        if (std::find(sizes.begin(), sizes.end(), std::pair{w, h}) == sizes.end() && !steps_only)
            sizes.emplace_back(w, h);
    for (const auto& [w, h] : sizes) {
        const QString stream = QStringLiteral("%1/s%2x%3").arg(dir).arg(w).arg(h);
        // HD frames take the generator about 1 s each: 60 of them, 200 of smaller ones.
        const int frames = w * h > 640 * 480 ? 60 : 200;
        if (!QFileInfo::exists(stream + "/image.strm") && !synth(stream, w, h, frames, true))
            return 1;
        if (edits_only)
            continue;
        benchStepping(QStringLiteral("%1x%2 PNG folder").arg(w).arg(h), stream);
        benchStepping(QStringLiteral("%1x%2 .strm").arg(w).arg(h), stream + "/image.strm");
        benchDrag(QStringLiteral("%1x%2 .strm").arg(w).arg(h), stream + "/image.strm");
    }

    if (steps_only)
        return 0;

    // 9,000 frames: the 200-frame .strm 45 times over, and 9,000 links to its PNGs.
    const QString small = dir + "/s320x240";
    const QString big_strm = dir + "/big.strm";
    const QString big_dir = dir + "/big_png";
    if (!QFileInfo::exists(big_strm)) {
        QFile in(small + "/image.strm");
        QFile out(big_strm);
        if (!in.open(QIODevice::ReadOnly) || !out.open(QIODevice::WriteOnly))
            return 1;
        const QByteArray bytes = in.readAll();
        for (int i = 0; i < 45; ++i)
            out.write(bytes);
    }
    if (!QFileInfo::exists(big_dir)) {
        QDir().mkpath(big_dir);
        QFile::copy(small + "/default.lut", big_dir + "/default.lut");
        for (int i = 0; i < 9000; ++i) {
            const QString src =
                QStringLiteral("%1/frame_%2.png").arg(small).arg(i % 200, 6, 10, QLatin1Char('0'));
            const QString dst =
                QStringLiteral("%1/frame_%2.png").arg(big_dir).arg(i, 6, 10, QLatin1Char('0'));
            std::error_code ec;
            std::filesystem::create_hard_link(src.toStdString(), dst.toStdString(), ec);
            if (ec)
                QFile::copy(src, dst);
        }
    }
    for (const QString& stream : {big_strm, big_dir}) {
        if (edits_only)
            break;
        QElapsedTimer t;
        t.start();
        auto opened = ui::StreamDocument::openSource(stream, {}, Pipeline::standard());
        const double ms = double(t.nsecsElapsed()) / 1e6;
        std::printf("open %-22s %zu frames in %.0f ms\n", qPrintable(QFileInfo(stream).fileName()),
                    opened ? opened.value()->names.size() : 0, ms);
    }

    benchEdits(QStringLiteral("320x240 .strm"), dir + "/s320x240/image.strm", 2);
    benchEdits(QStringLiteral("640x480 .strm"), dir + "/s640x480/image.strm", 1);
    benchEdits(QStringLiteral("9,000-frame .strm"), big_strm, 4);
    if (edits_only)
        return 0;

    // Play the 9,000-frame .strm through as fast as it goes; watch resident memory.
    MainWindow w;
    w.resize(1280, 800);
    w.show();
    if (!open(w, big_strm))
        return 1;
    showLayers(w);
    const double rss_start = rssMb();
    double rss_max = rss_start;
    w.navigator().setSpeed(0);
    QElapsedTimer t;
    t.start();
    w.navigator().setPlaying(true);
    while (w.navigator().playing() && t.elapsed() < 120000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        rss_max = std::max(rss_max, rssMb());
    }
    std::printf("play big.strm fastest: reached frame %zu in %.1f s (%.0f frames/s painted "
                "or skipped); RSS %.0f MB at start, %.0f MB max (growth %.0f MB)\n",
                w.session().stream().currentIndex(), double(t.elapsed()) / 1000.0,
                double(w.session().stream().currentIndex()) * 1000.0 / double(t.elapsed()),
                rss_start, rss_max, rss_max - rss_start);
    return 0;
}
