// THE pipeline, in order. Adding a stage = its folder + one line here.
#include "visioncore/controller.h"

#include "stages/ball/ball_detector.h"
#include "stages/field_lines/field_line_detector.h"
#include "stages/goalposts/goalpost_detector.h"
#include "stages/green_horizon/green_horizon_detector.h"
#include "stages/obstacles/obstacle_detector.h"
#include "stages/scanlines/scanline_classifier.h"
#include "stages/transitions/transition_filter.h"

namespace fieldsight {

std::vector<std::unique_ptr<Stage>> makePipelineStages()
{
    std::vector<std::unique_ptr<Stage>> stages;
    stages.push_back(std::make_unique<GreenHorizonDetector>());
    stages.push_back(std::make_unique<ScanlineClassifier>());
    stages.push_back(std::make_unique<TransitionFilter>());
    stages.push_back(std::make_unique<GoalpostDetector>());
    stages.push_back(std::make_unique<FieldLineDetector>());
    stages.push_back(std::make_unique<BallDetector>());
    stages.push_back(std::make_unique<ObstacleDetector>());
    return stages;
}

std::vector<std::string> pipelineStageIds()
{
    std::vector<std::string> ids;
    for (const auto& stage : makePipelineStages())
        ids.push_back(stage->info().id);
    return ids;
}

} // namespace fieldsight
