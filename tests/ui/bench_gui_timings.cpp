// The GUI's timed interactions for bench_gui (see bench_gui.cpp): stepping, playing, editing the
// table and dragging an annotation, each on the real main window, offscreen; printed, nothing
// asserted.
#include "bench_gui_timings.h"

#include "commands/commands.h"
#include "ui/actions/session_files.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
#include "ui/scans/edit_effect_scan.h"
#include "ui/panels/layers_panel.h"
#include "ui/tools/annotate_tool.h"
#include "visioncore/services/lut_editing.h"
#include "ui/stream_navigator/stream_navigator.h"

#include <QApplication>
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

namespace fieldsight::bench {

using ui::MainWindow;

std::string& layersShown()
{
    static std::string layers = "all";
    return layers;
}

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

void showLayers(MainWindow& w)
{
    const Pipeline& pipeline = w.session().stream().pipeline();
    w.layersPanel().setVisibleLayers(layersShown() == "default"
                                         ? ui::LayersPanel::defaultLayers(pipeline)
                                         : selectLayers(layersShown(), pipeline).value());
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

} // namespace fieldsight::bench
