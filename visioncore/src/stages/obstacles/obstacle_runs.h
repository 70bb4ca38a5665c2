// What the obstacle stage's parts share about runs of obstacle colour on a vertical scan.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/segments.h"

#include <cstddef>

namespace fieldsight::obstacle_runs {

inline bool inMask(unsigned mask, Colour c)
{
    return (mask >> unsigned(c)) & 1u;
}

/// Field-coloured bits this short inside a run of obstacle colour (a white marking on a robot)
/// belong to the run (px at kParamReferenceWidth wide; ObstacleDetector::maxBridged scales it).
inline constexpr int kMaxBridged = 3;

/// Whether segment `k` of `scan` is such a bit: at most `max_bridged` px, with obstacle colour
/// right after it.
inline bool bridged(const Scan& scan, std::size_t k, unsigned field_mask, int max_bridged)
{
    return scan[k].length() <= max_bridged && k + 1 < scan.size() &&
           !inMask(field_mask, scan[k + 1].colour);
}

} // namespace fieldsight::obstacle_runs
