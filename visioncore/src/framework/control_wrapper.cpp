// The control wrapper: the host's handle on one vision core.
#include "visioncore/framework/control_wrapper.h"

namespace fieldsight {

ControlWrapper::ControlWrapper(DataWrapper& data, const Pipeline& pipeline)
    : m_data(data), m_controller(pipeline)
{
    m_controller.prepare(m_blackboard);
}

Result<FrameReport> ControlWrapper::runFrame()
{
    return runFrameUntil(m_controller.size());
}

Result<FrameReport> ControlWrapper::runFrameUntil(std::size_t split)
{
    const cv::Mat& image = m_data.image();
    if (image.empty())
        return Error{"no frame to process"};
    if (image.type() != CV_8UC3)
        return Error{"frame is not 8-bit 3-channel YCbCr"};
    m_blackboard.beginFrame(image, m_data.lut(), m_data.kinematicHorizon());
    DebugSink* sink = m_data.debugSink();
    if (sink)
        m_blackboard.debug.setRequested(sink->requestedLayers());
    else if (!m_blackboard.debug.requested().empty())
        m_blackboard.debug.setRequested({});
    FrameReport report = m_controller.runStages(m_blackboard, m_skip, 0, split);
    if (sink && split >= m_controller.size())
        sink->publish(m_blackboard.debug);
    return report;
}

Result<FrameReport> ControlWrapper::resumeFrame(const Blackboard& earlier, std::size_t split)
{
    if (m_data.image().empty())
        return Error{"no frame to process"};
    m_blackboard = earlier;
    FrameReport report = m_controller.runStages(m_blackboard, m_skip, split, m_controller.size());
    if (DebugSink* sink = m_data.debugSink())
        sink->publish(m_blackboard.debug);
    return report;
}

Status ControlWrapper::setStageEnabled(std::string_view stage_id, bool enabled)
{
    const Stage* stage = m_controller.stage(stage_id);
    if (!stage)
        return Error{"unknown stage '" + std::string(stage_id) + "'"};
    if (!stage->info().skippable && !enabled)
        return Error{"stage '" + std::string(stage_id) +
                     "' cannot be skipped: later stages need it"};
    if (enabled)
        m_skip.erase(std::string(stage_id));
    else
        m_skip.insert(std::string(stage_id));
    return {};
}

bool ControlWrapper::stageEnabled(std::string_view stage_id) const
{
    return m_skip.count(stage_id) == 0;
}

std::vector<StageDescriptor> ControlWrapper::stages() const
{
    return m_controller.descriptors();
}

Status ControlWrapper::setParam(std::string_view stage_id, std::string_view name, double value)
{
    Stage* stage = m_controller.stage(stage_id);
    if (!stage)
        return Error{"unknown stage '" + std::string(stage_id) + "'"};
    return stage->setParam(name, value);
}

Status ControlWrapper::applyParams(const ParamSet& params)
{
    // Checked whole first, so a bad set changes nothing.
    if (Status s = params.check(stages()); !s)
        return s;
    for (const auto& [stage, values] : params.values)
        for (const auto& [name, value] : values)
            if (Status s = setParam(stage, name, value); !s)
                return s;
    return {};
}

ParamSet ControlWrapper::params() const
{
    ParamSet set;
    for (const StageDescriptor& d : stages())
        for (const ParamInfo& p : d.params)
            set.set(d.info.id, p.name, p.value);
    return set;
}

void ControlWrapper::resetParams()
{
    for (const StageDescriptor& d : stages())
        if (Stage* stage = m_controller.stage(d.info.id))
            stage->resetParams();
}

} // namespace fieldsight
