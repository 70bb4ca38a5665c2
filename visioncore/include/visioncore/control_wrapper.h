// ControlWrapper: how a host drives the core (run a frame, choose the stages, tune parameters).
#pragma once

#include "visioncore/blackboard.h"
#include "visioncore/controller.h"
#include "visioncore/data_wrapper.h"

#include <set>
#include <string>
#include <string_view>

namespace fieldsight {

class ControlWrapper
{
public:
    /// The DataWrapper must outlive the ControlWrapper.
    explicit ControlWrapper(DataWrapper& data);

    /// Processes the DataWrapper's current frame. Fails (with an Error) only when there is no frame
    /// or it is not CV_8UC3; problems inside stages become diagnostics on the blackboard.
    Result<FrameReport> runFrame();

    /// Switch a stage off for the following frames ("suppress detections"). Unknown or
    /// non-skippable ids are an error.
    Status setStageEnabled(std::string_view stage_id, bool enabled);
    bool stageEnabled(std::string_view stage_id) const;
    const std::set<std::string, std::less<>>& skippedStages() const { return m_skip; }

    Status setParam(std::string_view stage_id, std::string_view name, double value);

    const Blackboard& blackboard() const { return m_blackboard; }
    const Controller& controller() const { return m_controller; }

private:
    DataWrapper& m_data;
    Controller m_controller;
    Blackboard m_blackboard;
    std::set<std::string, std::less<>> m_skip;
};

} // namespace fieldsight
