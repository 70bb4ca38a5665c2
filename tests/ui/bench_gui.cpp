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
#include "bench_gui_timings.h"
#include "commands/commands.h"
#include "ui/main_window.h"
#include "ui/stream_navigator/stream_navigator.h"

#include "tool_platform.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

using namespace fieldsight;
using fieldsight::ui::MainWindow;

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
    bench::layersShown() = parser.value(layers_option).toStdString();
    if (bench::layersShown() != "default" &&
        !selectLayers(bench::layersShown(), Pipeline::standard())) {
        std::cerr << "bench_gui: --layers: "
                  << selectLayers(bench::layersShown(), Pipeline::standard()).error().message
                  << "\n";
        return 2;
    }
    const bool edits_only = parser.isSet(edits_option);
    std::printf("bench_gui: offscreen, layers %s, window 1280x800\n", bench::layersShown().c_str());

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
        if (!QFileInfo::exists(stream + "/image.strm") && !bench::synth(stream, w, h, frames, true))
            return 1;
        if (edits_only)
            continue;
        bench::benchStepping(QStringLiteral("%1x%2 PNG folder").arg(w).arg(h), stream);
        bench::benchStepping(QStringLiteral("%1x%2 .strm").arg(w).arg(h), stream + "/image.strm");
        bench::benchDrag(QStringLiteral("%1x%2 .strm").arg(w).arg(h), stream + "/image.strm");
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

    bench::benchEdits(QStringLiteral("320x240 .strm"), dir + "/s320x240/image.strm", 2);
    bench::benchEdits(QStringLiteral("640x480 .strm"), dir + "/s640x480/image.strm", 1);
    bench::benchEdits(QStringLiteral("9,000-frame .strm"), big_strm, 4);
    if (edits_only)
        return 0;

    // Play the 9,000-frame .strm through as fast as it goes; watch resident memory.
    MainWindow w;
    w.resize(1280, 800);
    w.show();
    if (!bench::open(w, big_strm))
        return 1;
    bench::showLayers(w);
    const double rss_start = bench::rssMb();
    double rss_max = rss_start;
    w.navigator().setSpeed(0);
    QElapsedTimer t;
    t.start();
    w.navigator().setPlaying(true);
    while (w.navigator().playing() && t.elapsed() < 120000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        rss_max = std::max(rss_max, bench::rssMb());
    }
    std::printf("play big.strm fastest: reached frame %zu in %.1f s (%.0f frames/s painted "
                "or skipped); RSS %.0f MB at start, %.0f MB max (growth %.0f MB)\n",
                w.session().stream().currentIndex(), double(t.elapsed()) / 1000.0,
                double(w.session().stream().currentIndex()) * 1000.0 / double(t.elapsed()),
                rss_start, rss_max, rss_max - rss_start);
    return 0;
}
