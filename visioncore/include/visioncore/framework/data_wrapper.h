// DataWrapper: the only door through which the vision core reads the outside world.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/debug_drawing.h"
#include "visioncore/basics/geometry.h"

#include <opencv2/core/mat.hpp>

#include <set>
#include <string>

namespace fieldsight {

/// Receives what the core produced for a frame beyond its percepts.
class DebugSink
{
public:
    virtual ~DebugSink() = default;
    /// Layer ids to draw for the next frame; the core draws nothing else.
    virtual std::set<std::string, std::less<>> requestedLayers() const = 0;
    virtual void publish(const DebugCanvas& canvas) = 0;
};

/// What a host supplies to the core: the current frame, the kinematic horizon, the LUT and a debug
/// sink. File streams, the GUI and cameras each implement one; the core never knows which.
/// The wrapper keeps what it serves unchanged while a frame is processed.
class DataWrapper
{
public:
    virtual ~DataWrapper() = default;

    /// The current frame: CV_8UC3 with channels Y, Cb, Cr. Empty when there is none.
    virtual const cv::Mat& image() const = 0;
    /// The kinematic horizon for the current frame (the top row when unknown).
    virtual Horizon kinematicHorizon() const = 0;
    virtual const ColourLut& lut() const = 0;
    /// Where debug drawings go; nullptr means none are wanted.
    virtual DebugSink* debugSink() { return nullptr; }
};

} // namespace fieldsight
