// The stream.json manifest of an image folder (SPEC §4): pixel format, orientation, LUT, field of
// view and per-frame timestamps and horizons, read strictly.
#pragma once

#include "visioncore/basics/geometry.h"
#include "visioncore/basics/result.h"
#include "visioncore/io/orientation.h"

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace fieldsight::io {

constexpr const char* kManifestName = "stream.json";
constexpr const char* kManifestFormat = "fieldsight-stream/1";

enum class PixelFormat { Rgb, YCbCr };

struct FrameMeta
{
    std::optional<double> timestamp_ms;
    std::optional<Horizon> horizon;
};

struct Manifest
{
    PixelFormat pixel_format = PixelFormat::Rgb;
    /// Degrees clockwise the stored pictures are turned to be upright ("orientation"; the older
    /// "flipped": true is 180, as .strm's flipped).
    Orientation orientation = Orientation::Upright;
    std::optional<std::string> lut;
    /// The stream's own stage parameters: a fieldsight-params/1 file, relative to the folder.
    std::optional<std::string> params;
    std::optional<std::array<double, 2>> fov_deg;
    std::map<std::string, FrameMeta> frames; ///< by file name
};

/// The largest stream.json read for a folder of `frames` frame files: 1 MiB for what does not
/// grow with the stream, and 1 KiB a frame (an entry with a 255-byte file name, a timestamp and
/// a horizon is under 400 bytes; the sample streams' are 117). Parsed, JSON takes 15 to 25 times
/// its size in memory: an unbounded stream.json could take the machine's.
std::size_t maxManifestBytes(std::size_t frames);

/// Reads and checks the manifest at `path` of a folder of `frames` frame files, refused unread
/// when larger than maxManifestBytes(frames); errors name the file and the problem.
Result<Manifest> parseManifest(const std::string& path, std::size_t frames);

} // namespace fieldsight::io
