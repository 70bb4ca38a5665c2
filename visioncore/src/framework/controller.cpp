// The pipeline's stage list and checks, and the controller: stages in order, skips, timing, and
// exceptions as diagnostics.
#include "visioncore/framework/controller.h"

#include "visioncore/basics/debug_drawing.h"
#include "visioncore/percepts/percept_set.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <stdexcept>

namespace fieldsight {

bool FrameReport::ran(std::string_view stage_id) const
{
    for (const StageTiming& t : stages)
        if (t.stage == stage_id)
            return t.ran;
    return false;
}

namespace {
StageDescriptor describe(const Stage& stage)
{
    return {stage.info(), stage.params()};
}
} // namespace

Pipeline& Pipeline::add(Factory factory, std::size_t position)
{
    position = std::min(position, m_factories.size());
    const StageDescriptor descriptor = describe(*factory());
    m_factories.insert(m_factories.begin() + std::ptrdiff_t(position), std::move(factory));
    m_descriptors.insert(m_descriptors.begin() + std::ptrdiff_t(position), descriptor);
    return *this;
}

std::vector<std::unique_ptr<Stage>> Pipeline::build() const
{
    std::vector<std::unique_ptr<Stage>> stages;
    stages.reserve(m_factories.size());
    for (const Factory& make : m_factories)
        stages.push_back(make());
    return stages;
}

const StageDescriptor* Pipeline::find(std::string_view id) const
{
    for (const StageDescriptor& d : m_descriptors)
        if (d.info.id == id)
            return &d;
    return nullptr;
}

std::vector<std::string> Pipeline::ids() const
{
    std::vector<std::string> ids;
    for (const StageDescriptor& d : m_descriptors)
        ids.push_back(d.info.id);
    return ids;
}

std::vector<const PerceptKind*> Pipeline::perceptKinds() const
{
    std::vector<const PerceptKind*> kinds;
    for (const StageDescriptor& d : m_descriptors)
        for (const PerceptKind* k : d.info.percepts)
            if (std::find(kinds.begin(), kinds.end(), k) == kinds.end())
                kinds.push_back(k);
    return kinds;
}

std::vector<LayerInfo> Pipeline::layers() const
{
    std::vector<LayerInfo> layers;
    for (const StageDescriptor& d : m_descriptors)
        layers.insert(layers.end(), d.info.layers.begin(), d.info.layers.end());
    return layers;
}

std::string Pipeline::idList() const
{
    std::string list;
    for (const StageDescriptor& d : m_descriptors)
        list += (list.empty() ? "" : ", ") + d.info.id;
    return list;
}

Status Pipeline::validate() const
{
    std::vector<std::string> available = blackboardInputs();
    std::vector<std::string> stage_ids, layer_ids;
    for (const StageDescriptor& d : m_descriptors) {
        const StageInfo& info = d.info;
        if (std::find(stage_ids.begin(), stage_ids.end(), info.id) != stage_ids.end())
            return Error{"stage '" + info.id + "' is in the pipeline twice"};
        stage_ids.push_back(info.id);
        for (const std::string& slot : info.reads)
            if (std::find(available.begin(), available.end(), slot) == available.end())
                return Error{"stage '" + info.id + "' reads '" + slot +
                             "', which no earlier stage writes"};
        for (const LayerInfo& layer : info.layers) {
            if (layer.id.rfind(info.id + ".", 0) != 0)
                return Error{"stage '" + info.id + "': layer '" + layer.id +
                             "' does not start with '" + info.id + ".'"};
            if (std::find(layer_ids.begin(), layer_ids.end(), layer.id) != layer_ids.end())
                return Error{"stage '" + info.id + "': layer '" + layer.id + "' exists twice"};
            layer_ids.push_back(layer.id);
        }
        available.insert(available.end(), info.writes.begin(), info.writes.end());
        for (const PerceptKind* kind : info.percepts)
            available.emplace_back(kind->key);
    }
    return {};
}

Controller::Controller(const Pipeline& pipeline)
{
    if (Status s = pipeline.validate(); !s)
        throw std::invalid_argument("invalid pipeline: " + s.error().message);
    m_stages = pipeline.build();
}

Controller::~Controller() = default;

Stage* Controller::stage(std::string_view id)
{
    for (const auto& s : m_stages)
        if (s->info().id == id)
            return s.get();
    return nullptr;
}

const Stage* Controller::stage(std::string_view id) const
{
    return const_cast<Controller*>(this)->stage(id);
}

std::vector<StageDescriptor> Controller::descriptors() const
{
    std::vector<StageDescriptor> out;
    for (const auto& s : m_stages)
        out.push_back(describe(*s));
    return out;
}

namespace {

std::string pixelText(double v)
{
    if (std::isnan(v))
        return "nan";
    if (std::isinf(v))
        return v > 0 ? "inf" : "-inf";
    return std::to_string(std::lround(v));
}

/// Why `entry`, as a stage wrote it for a width x height image, is nonsense, or nullopt: a
/// coordinate or size that is not a finite number, or a point more than one image size beyond
/// the image's edge. Read through the percepts' own drawing, so every kind is checked alike.
std::optional<std::string> nonsenseIn(const PerceptEntry& entry, int width, int height)
{
    if (entry.size() == 0)
        return std::nullopt;
    DebugDrawing drawing;
    entry.draw(Rgb{}, 1.0, drawing);
    const double margin = std::max(width, height);
    for (const DebugShape& shape : drawing.shapes) {
        if (!std::isfinite(shape.size) || std::abs(shape.size) > 2 * margin)
            return "a size of " + pixelText(shape.size) + " px";
        for (const PointF& p : shape.points)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || p.x < -margin ||
                p.x > width + margin || p.y < -margin || p.y > height + margin)
                return "the point (" + pixelText(p.x) + ", " + pixelText(p.y) + ") for a " +
                       std::to_string(width) + "x" + std::to_string(height) + " image";
    }
    return std::nullopt;
}

} // namespace

void Controller::prepare(Blackboard& bb) const
{
    for (const auto& s : m_stages)
        for (const PerceptKind* kind : s->info().percepts)
            bb.percepts.entry(*kind);
}

FrameReport Controller::runFrame(Blackboard& bb, const std::set<std::string, std::less<>>& skip)
{
    return runStages(bb, skip, 0, m_stages.size());
}

FrameReport Controller::runStages(Blackboard& bb, const std::set<std::string, std::less<>>& skip,
                                  std::size_t first, std::size_t end)
{
    using Clock = std::chrono::steady_clock;
    FrameReport report;
    report.stages.reserve(m_stages.size());
    const auto frame_start = Clock::now();
    for (const auto& stage : m_stages)
        stage->setFrameWidth(bb.width());
    for (std::size_t position = 0; position < m_stages.size(); ++position) {
        const auto& stage = m_stages[position];
        const StageInfo& info = stage->info();
        StageTiming timing{info.id, 0.0, false};
        const bool in_part = position >= first && position < end;
        if (in_part && !(info.skippable && skip.count(info.id))) {
            const auto start = Clock::now();
            for (const PerceptKind* kind : info.percepts)
                bb.percepts.markPresent(bb.percepts.entry(*kind));
            const std::size_t present = bb.percepts.presentCount();
            try {
                stage->run(bb);
            } catch (const std::exception& e) {
                bb.diagnostics.push_back({info.id, e.what()});
            } catch (...) {
                bb.diagnostics.push_back({info.id, "unknown exception"});
            }
            if (bb.percepts.presentCount() != present)
                bb.diagnostics.push_back(
                    {info.id, "wrote a percept list its StageInfo does not declare"});
            timing.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            timing.ran = true;
            // A faulty stage's nonsense stops here, before the later stages, the results file
            // and the overlay see it: its list is dropped for this frame, and the frame says why.
            // (After the timing: a stage's time is its own work.)
            for (const PerceptKind* kind : info.percepts) {
                PerceptEntry& entry = bb.percepts.entry(*kind);
                if (const auto why = nonsenseIn(entry, bb.width(), bb.height())) {
                    bb.diagnostics.push_back({info.id, "returned " + std::string(kind->key) +
                                                           " with " + *why +
                                                           "; dropped for this frame"});
                    entry.clear();
                }
            }
        }
        report.stages.push_back(std::move(timing));
    }
    report.total_ms = std::chrono::duration<double, std::milli>(Clock::now() - frame_start).count();
    return report;
}

} // namespace fieldsight
