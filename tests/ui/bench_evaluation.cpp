// The evaluation's speed in the real main window, offscreen, printed and not asserted (label
// bench): a 9,000-frame PNG folder (hard links to a 200-frame synth stream) with 1,000 annotated
// frames spread over it;
// - the first evaluation after the open (with the whole-stream edit-effect scan beside it);
// - the re-score after a LUT edit (a click's tolerance box of the field colour, then of the
//   ball's), from the edit to the panel's new scores, with the window's longest event-loop stall
//   meanwhile (a 5 ms QTimer probe) and the effect scan running too;
// - the re-score after an annotation edit (matched again with the detections made);
// - the same evaluation headless (evaluateStream, as `fieldsight eval`), for comparison.
//   build/tests/bench_evaluation [DIR]
#include "commands/commands.h"
#include "ui/actions/session_files.h"
#include "ui/document/annotations_document.h"
#include "ui/scans/evaluation_scan.h"
#include "ui/main_window.h"
#include "ui/panels/evaluation_panel.h"
#include "visioncore/services/lut_editing.h"

#include "tool_platform.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

using namespace fieldsight;
using fieldsight::ui::MainWindow;

namespace {

constexpr int kFrames = 9000;
constexpr int kAnnotated = 1000;

bool synth(const QString& out)
{
    std::ostringstream o, e;
    const cli::Context ctx{Pipeline::standard(), o, e};
    const int status = cli::runHeadless(
        "synth",
        {"fieldsight", "--scenario", "lab1", "--frames", "200", "--seed", "3", "--out", out}, ctx);
    if (status != 0)
        std::cerr << e.str();
    return status == 0;
}

QString frameName(int i)
{
    return QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0'));
}

/// 9,000 links to the small stream's PNGs; annotations for every 9th frame (1,000), each the
/// small stream's truth of the frame it links to.
bool makeBig(const QString& small, const QString& big)
{
    if (QFileInfo::exists(big + "/annotations.json"))
        return true;
    QDir().mkpath(big);
    QFile::copy(small + "/default.lut", big + "/default.lut");
    for (int i = 0; i < kFrames; ++i) {
        std::error_code ec;
        std::filesystem::create_hard_link((small + "/" + frameName(i % 200)).toStdString(),
                                          (big + "/" + frameName(i)).toStdString(), ec);
        if (ec)
            QFile::copy(small + "/" + frameName(i % 200), big + "/" + frameName(i));
    }
    const auto kinds = Pipeline::standard().perceptKinds();
    auto truth = Annotations::load((small + "/annotations.json").toStdString(), kinds);
    if (!truth) {
        std::cerr << truth.error().message << "\n";
        return false;
    }
    Annotations out;
    for (int n = 0; n < kAnnotated; ++n) {
        const int i = n * (kFrames / kAnnotated);
        const auto it = truth.value().frames.find(frameName(i % 200).toStdString());
        if (it != truth.value().frames.end())
            out.frames[frameName(i).toStdString()] = it->second;
    }
    return bool(out.save((big + "/annotations.json").toStdString(), kinds));
}

/// Runs the event loop until the evaluation has a fresh report; the longest gap between 5 ms
/// timer ticks meanwhile (ms).
double waitForEvaluation(MainWindow& w)
{
    ui::EvaluationScan& scan = w.session().evaluation();
    QEventLoop loop;
    QTimer tick;
    tick.setInterval(5);
    QElapsedTimer clock, gap;
    clock.start();
    gap.start();
    double longest = 0;
    QObject::connect(&tick, &QTimer::timeout, &loop, [&] {
        longest = std::max(longest, double(gap.nsecsElapsed()) / 1e6);
        gap.restart();
        if ((!scan.running() && !scan.pending()) || clock.elapsed() > 300000)
            loop.quit();
    });
    tick.start();
    loop.exec();
    return longest;
}

/// A click's edit at `p` of the current frame: its tolerance box becomes `colour`.
bool clickEdit(MainWindow& w, QPoint p, Colour colour)
{
    const cv::Mat& px = w.session().stream().current()->frame.ycbcr;
    const cv::Vec3b c = px.at<cv::Vec3b>(p.y() % px.rows, p.x() % px.cols);
    const auto cells = cellsInBox(c[0], c[1], c[2], {6, 4, 4});
    return w.session().lut().edit("bench", changesTo(w.session().lut().table(), cells, colour));
}

} // namespace

int main(int argc, char** argv)
{
    tools::useOffscreenWithoutDisplay();
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Times the window's evaluation, offscreen, on a 9,000-frame stream with 1,000 annotated "
        "frames (made in DIR, or in a temporary folder, on the first run): the first evaluation "
        "after the open, the re-score after a LUT edit and after an annotation edit, and the same "
        "evaluation headless. Prints the times; asserts nothing.");
    parser.addHelpOption();
    parser.addPositionalArgument("DIR", "where the generated streams are kept between runs",
                                 "[DIR]");
    parser.process(app);
    if (parser.positionalArguments().size() > 1) {
        std::cerr << "usage: bench_evaluation [DIR] (bench_evaluation --help says more)\n";
        return 2;
    }
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FieldsightBench");
    QSettings().clear();
    QTemporaryDir tmp;
    const QString dir =
        parser.positionalArguments().isEmpty() ? tmp.path() : parser.positionalArguments().front();
    const QString small = dir + "/eval_small";
    const QString big = dir + "/eval_big";
    if (!QFileInfo::exists(small + "/annotations.json") && !synth(small))
        return 1;
    if (!makeBig(small, big))
        return 1;

    {
        auto input = openStreamInput(big.toStdString(), {});
        auto truth = Annotations::load((big + "/annotations.json").toStdString(),
                                       Pipeline::standard().perceptKinds(), kFrames);
        if (!input || !truth)
            return 1;
        QElapsedTimer t;
        t.start();
        auto report = evaluateStream(input.value(), truth.value(), "annotations.json", 0);
        std::printf("headless evaluateStream: %zu frames of %d scored in %.2f s\n",
                    report ? report.value().scores.frames : 0, kFrames,
                    double(t.nsecsElapsed()) / 1e9);
    }

    MainWindow w;
    w.resize(1280, 800);
    w.show();
    QElapsedTimer opened;
    opened.start();
    QSignalSpy open(&w.files(), &ui::SessionFiles::streamOpened);
    w.files().openStream(big);
    if (!open.wait(120000) || !open.front().front().toBool())
        return 1;
    double stall = waitForEvaluation(w);
    ui::EvaluationScan& scan = w.session().evaluation();
    if (!scan.report()) {
        std::cerr << "no evaluation: " << scan.problem().toStdString() << "\n";
        return 1;
    }
    std::printf("window: first evaluation (%zu frames) done %.2f s after the open; longest "
                "event-loop stall %.1f ms\n",
                scan.report()->scores.frames, double(opened.elapsed()) / 1000.0, stall);

    const struct
    {
        const char* what;
        QPoint at;
        Colour colour;
    } edits[] = {{"field colour", {150, 200}, Colour::Yellow},
                 {"ball colour", {-1, -1}, Colour::Pink},
                 {"field colour undone", {-2, -2}, Colour::Unclassified}};
    for (const auto& e : edits) {
        bool ok = true;
        if (e.at.x() == -2) {
            w.session().undoGroup().undo();
        } else {
            QPoint at = e.at;
            const auto& balls = w.session().stream().current()->result.percepts.list<Ball>();
            if (at.x() < 0 && !balls.empty())
                at = QPoint(int(balls.front().x), int(balls.front().y));
            ok = clickEdit(w, at.x() < 0 ? QPoint(100, 120) : at, e.colour);
        }
        if (!ok)
            continue;
        stall = waitForEvaluation(w);
        std::printf("window: %s edit to new scores: %.2f s (%zu frames run); longest event-loop "
                    "stall %.1f ms; %s\n",
                    e.what, scan.lastRunMs() / 1000.0, scan.lastFramesRun(), stall,
                    qPrintable(w.evaluationPanel().changeText()));
    }

    // An annotation edit (a ball added on an annotated frame): matched again, nothing run.
    for (int i = 0; i < 3; ++i) {
        const std::string name = frameName(9 * (100 + 37 * i)).toStdString();
        ui::AnnotationsDocument& truth = w.session().annotations();
        if (!truth.frame(name))
            continue;
        FrameAnnotation f = *truth.frame(name);
        f.truth.output<Ball>().push_back({5.0 + i, 5.0, 3});
        QElapsedTimer edit;
        edit.start();
        truth.editFrame(name, f, "bench"); // the edit and every view's reaction (strips, marks)
        const double edit_ms = double(edit.nsecsElapsed()) / 1e6;
        stall = waitForEvaluation(w);
        std::printf("window: annotation edit to new scores: %.2f s (%zu frames run, %zu scored); "
                    "the edit itself (document and every view's refresh) %.2f ms; longest "
                    "event-loop stall %.1f ms\n",
                    scan.lastRunMs() / 1000.0, scan.lastFramesRun(), scan.report()->scores.frames,
                    edit_ms, stall);
    }
    return 0;
}
