// What bench_gui's main() runs: the timed interactions of bench_gui_timings.cpp.
#pragma once

#include "ui/main_window.h"

#include <QString>

#include <string>

namespace fieldsight::bench {

/// The layers shown: "all" unless --layers says otherwise ("default": the window's defaults).
std::string& layersShown();
/// Resident memory of this process, in MB.
double rssMb();
/// Generates a lab1 stream of `frames` frames at width x height into `out` (a .strm with `strm`).
bool synth(const QString& out, int width, int height, int frames, bool strm);
/// Opens `stream` in `w` and waits for its first frame painted.
bool open(ui::MainWindow& w, const QString& stream);
/// Shows layersShown() and waits for the frame drawn with them.
void showLayers(ui::MainWindow& w);
/// A LUT edit to the repainted frame and to the whole-stream strip updated, `scans` times.
void benchEdits(const QString& label, const QString& stream, int scans);
/// Steps (spaced and back to back), a parameter edit and play at 60 fps.
void benchStepping(const QString& label, const QString& stream);
/// A box tool's drag: each mouse move to the view painted with it.
void benchDrag(const QString& label, const QString& stream);

} // namespace fieldsight::bench
