// A stream lit by a light that changes over it: a copy of any stream with its frames' R, G, B
// multiplied by gains ramping from 1 at the first frame to given gains at the last (a synthetic
// change of white balance and level), for the tests and measurements of following the light.
#pragma once

#include <QString>

#include <array>

namespace fieldsight::test {

/// Writes into `out` (created; it must not exist or be empty) the frames of `stream`, as served
/// upright, lit by gains ramping linearly from (1, 1, 1) at frame 0 to `end_gain` (R, G, B) at
/// the last frame, as PNG (named as the stream names them) with their times and horizons in
/// stream.json; with the stream's table as default.lut, and its parameter file and annotations.json
/// when it has them. Empty on success, else what failed.
QString writeLightRamp(const QString& stream, const QString& out,
                       const std::array<double, 3>& end_gain);

} // namespace fieldsight::test
