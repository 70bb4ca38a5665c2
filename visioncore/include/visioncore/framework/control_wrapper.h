// ControlWrapper: how a host drives the core (run a frame, choose the stages, tune parameters).
#pragma once

#include "visioncore/framework/blackboard.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/data_wrapper.h"
#include "visioncore/framework/param_set.h"

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

class ControlWrapper
{
public:
    /// The DataWrapper must outlive the ControlWrapper. Throws std::invalid_argument when
    /// `pipeline` does not validate.
    explicit ControlWrapper(DataWrapper& data, const Pipeline& pipeline = Pipeline::standard());

    /// Processes the DataWrapper's current frame. Fails (with an Error) only when there is no frame
    /// or it is not CV_8UC3; problems inside stages become diagnostics on the blackboard.
    Result<FrameReport> runFrame();
    /// A frame in two parts, for a host that runs one frame with many parameter sets (the
    /// parameter search): runFrameUntil(split) processes the current frame with the stages
    /// before position `split` only; resumeFrame(earlier, split) then runs the stages from
    /// `split` on, starting from a copy of `earlier` (this core's blackboard after
    /// runFrameUntil(split) on the same frame, with the same parameters for the stages before
    /// `split`), and gives the same blackboard as runFrame() would.
    Result<FrameReport> runFrameUntil(std::size_t split);
    Result<FrameReport> resumeFrame(const Blackboard& earlier, std::size_t split);

    /// Switch a stage off for the following frames ("suppress detections"). Unknown or
    /// non-skippable ids are an error.
    Status setStageEnabled(std::string_view stage_id, bool enabled);
    bool stageEnabled(std::string_view stage_id) const;
    const std::set<std::string, std::less<>>& skippedStages() const { return m_skip; }

    /// The stages, in order, with their current parameter values.
    std::vector<StageDescriptor> stages() const;

    Status setParam(std::string_view stage_id, std::string_view name, double value);
    /// Applies every value of `params`, or none when any is unknown or invalid.
    Status applyParams(const ParamSet& params);
    /// Every stage's current parameter values.
    ParamSet params() const;
    /// Every parameter back to its default.
    void resetParams();

    /// This frame's state and output (valid until the next runFrame).
    const Blackboard& blackboard() const { return m_blackboard; }

private:
    DataWrapper& m_data;
    Controller m_controller;
    Blackboard m_blackboard;
    std::set<std::string, std::less<>> m_skip;
};

} // namespace fieldsight
