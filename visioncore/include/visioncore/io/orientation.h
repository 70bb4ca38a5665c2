// A stream's orientation (docs/formats.md): how far its stored pictures are turned clockwise to be
// upright, applied as frames are read so everything after the reader sees the upright frame.
#pragma once

#include "visioncore/basics/geometry.h"
#include "visioncore/basics/result.h"

#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>

namespace fieldsight {

/// Degrees clockwise the stored pictures are turned to be upright.
enum class Orientation { Upright = 0, Clockwise90 = 90, Half = 180, Clockwise270 = 270 };

inline int degrees(Orientation o)
{
    return int(o);
}
/// 0, 90, 180 or 270; anything else is none.
std::optional<Orientation> orientationFromDegrees(long long degrees);
/// "0", "90", "180" or "270", as the manifest and --orientation spell it.
std::string orientationText(Orientation o);

/// `in` turned clockwise by `o` into `out` (cv::rotate; `out` is reused when it has the size and
/// type already). `in` and `out` must not share pixels unless `o` is Upright.
void orientImage(const cv::Mat& in, cv::Mat& out, Orientation o);

/// The horizon of a picture `height` px tall after turning it by `o`. A half turn gives the
/// mirrored line; a quarter turn none, since a horizon turned a quarter is no longer a row line
/// with the sky above it (the whole image is then searched).
std::optional<Horizon> orientHorizon(const Horizon& horizon, Orientation o, int height);

/// Sets "orientation" in the stream.json of the image folder `folder`, keeping every other key
/// and dropping the older "flipped" (which it replaces); a folder without a manifest gets one
/// naming only the format and the orientation. Written atomically; a manifest that cannot be
/// read is never written over. Errors name the file and the problem.
Status writeStreamOrientation(const std::string& folder, Orientation o);

/// Sets "lut" in the stream.json of the image folder `folder` to the table `lut` (named relative
/// to the folder when it is inside it), so the stream opens with that table; the same rules as
/// writeStreamOrientation.
Status writeStreamLut(const std::string& folder, const std::string& lut);

/// Sets "params" in the stream.json of the image folder `folder` to the parameter file `params`
/// (named relative to the folder when it is inside it), so the stream opens with those
/// parameters; the same rules as writeStreamOrientation.
Status writeStreamParams(const std::string& folder, const std::string& params);

} // namespace fieldsight
