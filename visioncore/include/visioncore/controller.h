// Controller: runs the stages of stage_list.cpp in order, skipping those switched off, timing each
// and turning a stage's exception into a per-frame diagnostic.
#pragma once

#include "visioncore/blackboard.h"
#include "visioncore/stage.h"

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
};

class Controller
{
public:
    /// The pipeline of stage_list.cpp.
    Controller();
    /// Another list of stages, in order (tests, experiments).
    explicit Controller(std::vector<std::unique_ptr<Stage>> stages);
    ~Controller();
    Controller(const Controller&) = delete;
    Controller& operator=(const Controller&) = delete;

    /// Runs one frame on `bb` (already begun). Stages whose id is in `skip` do not run; only
    /// skippable stages can be skipped (the others are needed by everything after them).
    FrameReport runFrame(Blackboard& bb, const std::set<std::string, std::less<>>& skip);

    const std::vector<std::unique_ptr<Stage>>& stages() const { return m_stages; }
    Stage* stage(std::string_view id) const;

private:
    std::vector<std::unique_ptr<Stage>> m_stages;
};

/// THE pipeline: every stage, in order (defined in src/stages/stage_list.cpp).
std::vector<std::unique_ptr<Stage>> makePipelineStages();
/// Ids of the pipeline stages in order, without building a controller.
std::vector<std::string> pipelineStageIds();

} // namespace fieldsight
