// `fieldsight run --render DIR`: each frame with the requested layers drawn, as PNG, through the
// same painter the GUI's frame view uses.
#pragma once

#include "visioncore/io/annotations.h"
#include "visioncore/services/layers.h"
#include "visioncore/services/stream_runner.h"

#include <map>
#include <string>

namespace fieldsight::cli {

struct RenderOptions
{
    std::string dir;
    LayerSet layers;
    int scale = 2; ///< screen px per image px
    /// The truth drawn on the "truth.*" layers, by frame stem (Annotations::truthByStem).
    std::map<std::string, const PerceptSet*> truth;
    const Pipeline* pipeline = &Pipeline::standard();
};

/// Creates the folder and marks it as a render of `stream` (kRenderMarker); the message names it
/// when that fails. Check it with checkRenderFolder first.
Status prepareRenderFolder(const std::string& dir, const std::string& stream);
/// Writes `frame` with its layers to DIR/<frame stem>.png (atomically). Safe to call from several
/// worker threads at once.
Status renderFrame(const RenderOptions& options, const FrameResult& result, const Frame& frame,
                   const DebugCanvas& canvas);

} // namespace fieldsight::cli
