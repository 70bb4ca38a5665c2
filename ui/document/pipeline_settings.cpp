#include "ui/document/pipeline_settings.h"

#include "visioncore/services/stream_runner.h"

#include <QUndoCommand>

#include <chrono>

namespace fieldsight::ui {

/// One settings change: the whole state before and after (a few numbers and names).
class SettingsCommand : public QUndoCommand
{
public:
    SettingsCommand(PipelineSettings& doc, const QString& text, PipelineSettings::State before,
                    PipelineSettings::State after, std::string merge_key)
        : QUndoCommand(text), m_doc(doc), m_before(std::move(before)), m_after(std::move(after)),
          m_merge_key(std::move(merge_key))
    {
    }
    void redo() override { m_doc.store(m_after); }
    void undo() override { m_doc.store(m_before); }
    int id() const override { return m_merge_key.empty() ? -1 : 2; }
    /// Changes of one parameter in a quick run (a spin box's arrows, typing a number) are one
    /// step; one that comes back to where the run started leaves no step.
    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* next = static_cast<const SettingsCommand*>(other);
        if (next->m_merge_key != m_merge_key || next->m_when - m_when > std::chrono::seconds(2))
            return false;
        m_after = next->m_after;
        m_when = next->m_when;
        setText(next->text());
        setObsolete(m_after.params->values == m_before.params->values &&
                    m_after.skip == m_before.skip);
        return true;
    }

private:
    PipelineSettings& m_doc;
    PipelineSettings::State m_before;
    PipelineSettings::State m_after;
    std::string m_merge_key;
    std::chrono::steady_clock::time_point m_when = std::chrono::steady_clock::now();
};

PipelineSettings::PipelineSettings(const Pipeline& pipeline, QObject* parent)
    : Document(Saving::None, parent), m_pipeline(pipeline)
{
}

const ParamInfo* PipelineSettings::paramInfo(std::string_view stage_id, std::string_view name) const
{
    const StageDescriptor* stage = m_pipeline.find(stage_id);
    if (!stage)
        return nullptr;
    for (const ParamInfo& p : stage->params)
        if (p.name == name)
            return &p;
    return nullptr;
}

double PipelineSettings::paramValue(std::string_view stage_id, std::string_view name) const
{
    const auto stage = m_params->values.find(stage_id);
    if (stage != m_params->values.end()) {
        const auto it = stage->second.find(name);
        if (it != stage->second.end())
            return it->second;
    }
    const ParamInfo* info = paramInfo(stage_id, name);
    return info ? info->default_value : 0;
}

bool PipelineSettings::paramChanged(std::string_view stage_id, std::string_view name) const
{
    const auto stage = m_params->values.find(stage_id);
    return stage != m_params->values.end() && stage->second.count(name) != 0;
}

void PipelineSettings::push(const QString& text, State after, const std::string& merge_key)
{
    undoStack().push(
        new SettingsCommand(*this, text, State{m_params, m_skip}, std::move(after), merge_key));
}

void PipelineSettings::store(const State& state)
{
    m_params = state.params;
    m_skip = state.skip;
    emit changed();
}

void PipelineSettings::reset(const ParamSet& params)
{
    undoStack().clear();
    if (params.values != m_params->values) // the same again: nothing to run again
        store(State{std::make_shared<ParamSet>(params), m_skip});
}

Status PipelineSettings::setStageEnabled(std::string_view stage_id, bool enabled)
{
    if (Status s = checkSkip(m_pipeline, {std::string(stage_id)}); !s)
        return s;
    if (enabled == stageEnabled(stage_id))
        return {};
    State after{m_params, m_skip};
    if (enabled)
        after.skip.erase(after.skip.find(stage_id));
    else
        after.skip.insert(std::string(stage_id));
    const QString id = QString::fromUtf8(stage_id.data(), qsizetype(stage_id.size()));
    push(enabled ? tr("Run %1").arg(id) : tr("Skip %1").arg(id), std::move(after));
    return {};
}

Status PipelineSettings::setParam(std::string_view stage_id, std::string_view name, double value)
{
    const ParamInfo* info = paramInfo(stage_id, name);
    if (!info)
        return Error{"unknown parameter '" + std::string(stage_id) + "." + std::string(name) + "'"};
    if (Status s = checkParamValue(*info, stage_id, value); !s)
        return s;
    if (value == paramValue(stage_id, name))
        return {};
    auto next = std::make_shared<ParamSet>(*m_params);
    if (value == info->default_value) {
        auto& stage = next->values[std::string(stage_id)];
        stage.erase(std::string(name));
        if (stage.empty())
            next->values.erase(std::string(stage_id));
    } else {
        next->set(stage_id, name, value);
    }
    const std::string key = std::string(stage_id) + "." + std::string(name);
    push(tr("%1 = %2").arg(QString::fromStdString(key)).arg(value), State{std::move(next), m_skip},
         key);
    return {};
}

void PipelineSettings::resetParam(std::string_view stage_id, std::string_view name)
{
    if (const ParamInfo* info = paramInfo(stage_id, name))
        (void)setParam(stage_id, name, info->default_value);
}

void PipelineSettings::resetStage(std::string_view stage_id)
{
    if (m_params->values.count(stage_id) == 0)
        return;
    auto next = std::make_shared<ParamSet>(*m_params);
    next->values.erase(std::string(stage_id));
    push(tr("Reset %1").arg(QString::fromUtf8(stage_id.data(), qsizetype(stage_id.size()))),
         State{std::move(next), m_skip});
}

Status PipelineSettings::setParamChanges(const ParamSet& params, const QString& text)
{
    if (Status s = params.check(m_pipeline); !s)
        return s;
    if (params.values == m_params->values)
        return {};
    push(text.isEmpty() ? tr("Set every parameter") : text,
         State{std::make_shared<ParamSet>(params), m_skip});
    return {};
}

} // namespace fieldsight::ui
