// One frame of a generated stream, with everything known about it: the scene, the camera, the
// image with its pixel labels, the ground truth and the kinematic horizon.
#pragma once

#include "synth/camera_model.h"
#include "synth/renderer.h"
#include "synth/scenario_script.h"
#include "synth/scene.h"

#include "visioncore/io/annotations.h"
#include "visioncore/basics/geometry.h"

#include <string>

namespace fieldsight::synth {

struct StreamFrame
{
    std::string name;        ///< frame_000000.png, ...
    double timestamp_ms = 0; ///< ms, index * 1000/30 rounded to 1 us
    Scene scene;
    CameraModel camera{320, 240};
    RenderedFrame image;
    FrameAnnotation truth;
    Horizon horizon; ///< px, the camera's true kinematic horizon
};

std::string frameFileName(int index);
StreamFrame renderStreamFrame(const ScenarioScript& script, int index);

} // namespace fieldsight::synth
