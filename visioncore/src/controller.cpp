// The controller: stages in pipeline order, skips, timing, and exceptions as diagnostics.
#include "visioncore/controller.h"

#include <chrono>
#include <exception>

namespace fieldsight {

Controller::Controller() : m_stages(makePipelineStages()) {}
Controller::Controller(std::vector<std::unique_ptr<Stage>> stages) : m_stages(std::move(stages)) {}
Controller::~Controller() = default;

Stage* Controller::stage(std::string_view id) const
{
    for (const auto& s : m_stages)
        if (s->info().id == id)
            return s.get();
    return nullptr;
}

FrameReport Controller::runFrame(Blackboard& bb, const std::set<std::string, std::less<>>& skip)
{
    using Clock = std::chrono::steady_clock;
    FrameReport report;
    report.stages.reserve(m_stages.size());
    const auto frame_start = Clock::now();
    for (const auto& stage : m_stages) {
        const StageInfo& info = stage->info();
        StageTiming timing{info.id, 0.0, false};
        if (!(info.skippable && skip.count(info.id))) {
            const auto start = Clock::now();
            try {
                stage->run(bb);
            } catch (const std::exception& e) {
                bb.diagnostics.push_back({info.id, e.what()});
            } catch (...) {
                bb.diagnostics.push_back({info.id, "unknown exception"});
            }
            timing.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            timing.ran = true;
        }
        report.stages.push_back(std::move(timing));
    }
    report.total_ms = std::chrono::duration<double, std::milli>(Clock::now() - frame_start).count();
    return report;
}

} // namespace fieldsight
