// The rule every command and the window follow before writing an output: never over what they
// read, never over a stream's own files, and never over a file that is not an earlier output of
// the same kind. One rule, so `run --render`, `bench --json`, a snapshot of the view and a
// recording agree.
#pragma once

#include "visioncore/basics/result.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

/// Refuses an output that is one of `inputs` (a file, or a folder such as a stream), or that would
/// replace a file inside an input folder, after resolving links and `..`: an Error naming both
/// paths, for the caller to give before it writes anything. Empty inputs, "-" and cameras are
/// skipped. `who` starts the message (a command's name, or what the window was saving).
Status checkNotAnInput(std::string_view who, const std::string& output,
                       const std::vector<std::string>& inputs);

/// Refuses a folder to write a new set of files into (a recording) unless it is new or empty:
/// an Error naming it and what is there.
Status checkNewOrEmptyFolder(std::string_view who, const std::string& folder);

/// What a command writes to an output file, so that a file already there is replaced only when
/// it is an earlier output of the same kind.
struct OutputFileKind
{
    /// JSON carrying this "format" ("fieldsight-bench/1"); empty: not a fieldsight JSON.
    std::string json_format;
    /// Other JSON: an object always having this top-level key ("categories" for COCO).
    std::string json_key;
    bool table = false; ///< a colour table (.lut): exactly ColourLut::kCells bytes
    /// A report derived from a stream (results, scores, timings): may replace its own kind inside
    /// a stream folder. Everything else (tables, annotations, samples) is a document a stream
    /// reads, never replaced there by a command.
    bool report = false;
};

/// The one guard of an output file, run before anything is written: checkNotAnInput, then an
/// existing file at `output` is replaced only when it holds `kind` (an earlier output of the same
/// kind; never an image, a stream.json or another command's JSON) and, unless `kind` is a report,
/// lies outside every stream folder (isStreamFolder). "-" (standard output) passes.
Status checkOutputFile(std::string_view who, const std::string& output,
                       const std::vector<std::string>& inputs, const OutputFileKind& kind);

/// The name of the marker file `run --render` leaves in its folder, so a later render may
/// replace its own pictures and nothing else.
inline constexpr std::string_view kRenderMarker = "fieldsight-render.json";

/// The guard of a folder a command fills with pictures (`run --render`): checkNotAnInput, then
/// the folder is new, empty, or an earlier render (it holds kRenderMarker); never a stream or
/// another folder of the user's.
Status checkRenderFolder(std::string_view who, const std::string& folder,
                         const std::vector<std::string>& inputs);

/// A file name a stream folder reads as a frame (.png, .jpg, .jpeg, .bmp, any case).
bool isImageFileName(const std::filesystem::path& name);

/// `folder` holds a stream: a stream.json, a .strm, or frames (isImageFileName).
bool isStreamFolder(const std::filesystem::path& folder);

} // namespace fieldsight
