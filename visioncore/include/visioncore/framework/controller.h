// Pipeline and Controller: which stages run, in which order (THE pipeline is in
// src/stages/stage_list.cpp), and running them over a frame, skipping those switched off, timing
// each and turning a stage's exception into a per-frame diagnostic.
#pragma once

#include "visioncore/framework/blackboard.h"
#include "visioncore/framework/stage.h"
#include "visioncore/basics/result.h"

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

struct StageTiming
{
    std::string stage; ///< stage id
    double ms = 0;     ///< wall-clock ms of this stage
    bool ran = false;  ///< false when skipped
};

struct FrameReport
{
    double total_ms = 0;             ///< ms, all stages
    std::vector<StageTiming> stages; ///< in pipeline order, skipped ones included
    /// Did stage `stage_id` run (false when skipped or unknown).
    bool ran(std::string_view stage_id) const;
};

/// The stages of a core, in order, as factories: each core builds its own stages. Everything a
/// host lists (stage switches, parameters, layers, percept kinds) comes from here.
class Pipeline
{
public:
    using Factory = std::function<std::unique_ptr<Stage>()>;

    /// THE pipeline: every stage of the vision system, in order (src/stages/stage_list.cpp).
    static const Pipeline& standard();

    /// Adds a stage at `position` (default: the end).
    Pipeline& add(Factory factory, std::size_t position = std::size_t(-1));
    template <class S> Pipeline& add()
    {
        return add([] { return std::make_unique<S>(); });
    }

    std::vector<std::unique_ptr<Stage>> build() const;
    std::size_t size() const { return m_factories.size(); }

    /// Each stage's info and default parameters, in order.
    const std::vector<StageDescriptor>& descriptors() const { return m_descriptors; }
    const StageDescriptor* find(std::string_view id) const;
    std::vector<std::string> ids() const;
    /// The percept kinds the stages produce, in pipeline order.
    std::vector<const PerceptKind*> perceptKinds() const;
    /// Every debug layer of every stage, in order.
    std::vector<LayerInfo> layers() const;
    /// "green_horizon, scanlines, ..." for messages and usage texts.
    std::string idList() const;

    /// Stage ids and layer ids unique, layer ids prefixed by their stage's id, and every slot a
    /// stage reads is an input or written by an earlier stage. The message names the stage.
    Status validate() const;

private:
    std::vector<Factory> m_factories;
    std::vector<StageDescriptor> m_descriptors;
};

class Controller
{
public:
    /// Builds the stages of `pipeline`; throws std::invalid_argument when it does not validate.
    explicit Controller(const Pipeline& pipeline = Pipeline::standard());
    ~Controller();
    Controller(const Controller&) = delete;
    Controller& operator=(const Controller&) = delete;

    /// Runs one frame on `bb` (already begun). Stages whose id is in `skip` do not run; only
    /// skippable stages can be skipped (the others are needed by everything after them). Before
    /// a stage runs its percept lists are made present; a stage that adds a list it did not
    /// declare gets a diagnostic.
    FrameReport runFrame(Blackboard& bb, const std::set<std::string, std::less<>>& skip);
    /// Runs only the stages at positions [first, end) (the others are reported as not run): a
    /// frame in parts, for ControlWrapper::runFrameUntil and resumeFrame.
    FrameReport runStages(Blackboard& bb, const std::set<std::string, std::less<>>& skip,
                          std::size_t first, std::size_t end);
    std::size_t size() const { return m_stages.size(); }

    /// Makes `bb` hold every percept list of the pipeline (absent), so they are listed in
    /// pipeline order.
    void prepare(Blackboard& bb) const;

    std::vector<StageDescriptor> descriptors() const;
    Stage* stage(std::string_view id);
    const Stage* stage(std::string_view id) const;

private:
    std::vector<std::unique_ptr<Stage>> m_stages;
};

} // namespace fieldsight
