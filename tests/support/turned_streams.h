// Streams stored turned (docs/formats.md, "orientation"), for the tests that check a turned stream
// reads, runs and shows as its upright copy does.
#pragma once

#include "visioncore/io/orientation.h"

#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>
#include <vector>

namespace fieldsight::test {

/// Frame `i` of a small upright scene (320x240 YCbCr in testLut()'s classes): field below row 60,
/// a goalpost, a field line and a ball that moves right from frame to frame.
cv::Mat uprightScene(int i);

/// What a stream folder written by writeTurnedStream holds.
struct TurnedStream
{
    /// The pictures are stored so that turning them clockwise by this makes the upright frames.
    Orientation stored = Orientation::Upright;
    /// stream.json's "orientation" (none: the key is left out).
    std::optional<int> manifest_orientation;
    /// Each upright frame's horizon (none: no horizons); written as the stored pictures have it
    /// (for a quarter turn, which keeps no horizon, as it is).
    std::vector<Horizon> upright_horizons;
};

/// Writes `upright` into the new folder `dir` as frame_000000.png, ... (pixel format ycbcr) stored
/// as `how` says, with testLut() as default.lut and a stream.json. False (with a warning) when a
/// file cannot be written.
bool writeTurnedStream(const std::string& dir, const std::vector<cv::Mat>& upright,
                       const TurnedStream& how);

} // namespace fieldsight::test
