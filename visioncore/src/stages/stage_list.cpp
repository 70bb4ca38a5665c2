// THE pipeline, in order. Adding a stage = its folder + one line here.
#include "visioncore/framework/controller.h"

#include "stages/ball/ball_detector.h"
#include "stages/field_lines/field_line_detector.h"
#include "stages/goalposts/goalpost_detector.h"
#include "stages/green_horizon/green_horizon_detector.h"
#include "stages/obstacles/obstacle_detector.h"
#include "stages/scanlines/scanline_classifier.h"
#include "stages/transitions/transition_filter.h"

namespace fieldsight {

const Pipeline& Pipeline::standard()
{
    static const Pipeline pipeline = Pipeline()
                                         .add<GreenHorizonDetector>()
                                         .add<ScanlineClassifier>()
                                         .add<TransitionFilter>()
                                         .add<GoalpostDetector>()
                                         .add<FieldLineDetector>()
                                         .add<BallDetector>()
                                         .add<ObstacleDetector>();
    return pipeline;
}

} // namespace fieldsight
