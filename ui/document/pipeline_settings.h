// The pipeline settings document: which stages run and the parameter values that differ from the
// defaults. Every change is a command on its own undo stack (consecutive changes of one parameter
// merge into one step, as a spin box's arrows make them); each version is an immutable ParamSet
// the frame worker and the whole-stream scan read without copying.
#pragma once

#include "ui/document/document.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"

#include <QString>

#include <memory>
#include <set>
#include <string>

namespace fieldsight::ui {

using StageSet = std::set<std::string, std::less<>>;

class PipelineSettings : public Document
{
    Q_OBJECT
public:
    explicit PipelineSettings(const Pipeline& pipeline, QObject* parent = nullptr);

    const Pipeline& pipeline() const { return m_pipeline; }
    /// The open stream's own parameter file (empty: it has none), as it was read (`read`) or just
    /// saved: changedOnDisk() then says another window or a command wrote it since.
    using Document::setFile;

    bool stageEnabled(std::string_view stage_id) const { return m_skip.count(stage_id) == 0; }
    const StageSet& skippedStages() const { return m_skip; }
    /// The value in use: the one set, or the default.
    double paramValue(std::string_view stage_id, std::string_view name) const;
    bool paramChanged(std::string_view stage_id, std::string_view name) const;
    /// Values that differ from the defaults.
    const ParamSet& paramChanges() const { return *m_params; }
    /// The same, as the immutable version a worker keeps.
    std::shared_ptr<const ParamSet> paramVersion() const { return m_params; }

    /// Starts from `params` (checked by the caller): no undo step, the history is cleared.
    void reset(const ParamSet& params);

    // Edits, each an undoable command; checked first (an Error changes nothing).
    Status setStageEnabled(std::string_view stage_id, bool enabled);
    Status setParam(std::string_view stage_id, std::string_view name, double value);
    void resetParam(std::string_view stage_id, std::string_view name);
    void resetStage(std::string_view stage_id);
    /// Replaces every change at once (a loaded file, or reset all).
    Status setParamChanges(const ParamSet& params, const QString& text = {});

signals:
    /// A stage switch or a parameter changed (an edit, undo or redo).
    void changed();

private:
    friend class SettingsCommand;
    struct State
    {
        std::shared_ptr<const ParamSet> params;
        StageSet skip;
    };
    const ParamInfo* paramInfo(std::string_view stage_id, std::string_view name) const;
    /// Pushes the change from the current state to `after`; `merge_key` non-empty lets the next
    /// change of the same key merge into it.
    void push(const QString& text, State after, const std::string& merge_key = {});
    void store(const State& state);

    const Pipeline& m_pipeline;
    std::shared_ptr<const ParamSet> m_params = std::make_shared<ParamSet>();
    StageSet m_skip;
};

} // namespace fieldsight::ui
