// The stage suites' frames: sky over a field, and one pipeline run that must succeed.
#pragma once

#include "support/synthetic_frames.h"
#include "visioncore/framework/control_wrapper.h"

#include <QtGlobal>

namespace fieldsight::test {

/// 320 x 240: unclassified above row `edge`, field green from it down.
inline cv::Mat fieldFrame(int edge = 60)
{
    cv::Mat f = filledFrame(320, 240, Colour::Unclassified);
    fillRect(f, 0, edge, 319, 239, Colour::Green);
    return f;
}

/// Runs the core on its frame; a failed run ends the suite (it is never what a test expects).
inline const Blackboard& runOrDie(ControlWrapper& core)
{
    auto r = core.runFrame();
    if (!r.ok())
        qFatal("runFrame failed: %s", r.error().message.c_str());
    return core.blackboard();
}

} // namespace fieldsight::test
