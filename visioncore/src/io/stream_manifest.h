// The stream.json manifest of an image folder (SPEC §4): pixel format, orientation, LUT, field of
// view and per-frame timestamps and horizons, read strictly.
#pragma once

#include "visioncore/basics/geometry.h"
#include "visioncore/basics/result.h"
#include "visioncore/io/orientation.h"

#include <array>
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
    std::optional<std::array<double, 2>> fov_deg;
    std::map<std::string, FrameMeta> frames; ///< by file name
};

/// Reads and checks the manifest at `path`; errors name the file and the problem.
Result<Manifest> parseManifest(const std::string& path);

} // namespace fieldsight::io
