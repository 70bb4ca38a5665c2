// Renders one frame of a generated stream and derives its ground truth.
#include "synth/stream_frame.h"

#include "synth/ground_truth.h"

#include <cmath>
#include <cstdio>

namespace fieldsight::synth {

std::string frameFileName(int index)
{
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", index);
    return name;
}

StreamFrame renderStreamFrame(const ScenarioScript& script, int index)
{
    StreamFrame frame;
    frame.name = frameFileName(index);
    frame.timestamp_ms = std::round(index * ScenarioScript::kFramePeriodMs * 1000.0) / 1000.0;
    frame.scene = script.sceneAt(index);
    frame.camera = CameraModel(script.width(), script.height());
    frame.camera.setPose(frame.scene.camera);
    frame.image =
        renderScene(frame.scene, frame.camera, script.effectsAt(index), script.noiseSeed(index));
    frame.truth = groundTruth(frame.scene, frame.camera, frame.image.primitive);
    frame.horizon = frame.camera.horizon();
    return frame;
}

} // namespace fieldsight::synth
