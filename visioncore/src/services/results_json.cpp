// fieldsight-results/1: built and read with the JSON library.
#include "visioncore/services/results_json.h"

#include "visioncore/basics/json_text.h"
#include "basics/json_format.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace fieldsight {

namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json; // keeps the field order of SPEC §5.1

constexpr const char* kFormat = "fieldsight-results/1";
constexpr double kMaxTimeMs = 1e9; // 11 days a frame: more is a damaged file

/// ms to 0.1 microsecond.
double ms(double v)
{
    return std::isfinite(v) ? std::round(v * 1e4) / 1e4 : v;
}

OrderedJson frameJson(const FrameResult& f)
{
    OrderedJson j;
    j["index"] = f.index;
    j["name"] = f.name;
    OrderedJson& time = j["time_ms"];
    time["total"] = ms(f.report.total_ms);
    for (const StageTiming& t : f.report.stages)
        if (t.ran)
            time[t.stage] = ms(t.ms);
    f.percepts.toJson(j, PerceptNames::Results);
    if (!f.diagnostics.empty()) {
        OrderedJson& list = j["diagnostics"] = OrderedJson::array();
        for (const Diagnostic& d : f.diagnostics)
            list.push_back({{"stage", d.stage}, {"message", d.message}});
    }
    return j;
}

OrderedJson summaryJson(const std::vector<FrameResult>& frames,
                        const std::vector<std::string>& stage_ids)
{
    std::vector<double> totals;
    totals.reserve(frames.size());
    for (const FrameResult& f : frames)
        totals.push_back(f.report.total_ms);
    const TimingStats total = TimingStats::of(totals);

    OrderedJson summary;
    summary["frames"] = frames.size();
    summary["mean_ms"] = ms(total.mean_ms);
    summary["std_ms"] = ms(total.std_ms);
    // One pass over the frames: a frame's timings are in pipeline order, so the position of a
    // stage in its report is usually its position in `stage_ids`.
    std::vector<double> sums(stage_ids.size(), 0.0);
    std::vector<std::size_t> runs(stage_ids.size(), 0);
    for (const FrameResult& f : frames)
        for (std::size_t i = 0; i < f.report.stages.size(); ++i) {
            const StageTiming& t = f.report.stages[i];
            if (!t.ran)
                continue;
            std::size_t k = i < stage_ids.size() && stage_ids[i] == t.stage ? i : stage_ids.size();
            for (std::size_t j = 0; k == stage_ids.size() && j < stage_ids.size(); ++j)
                if (stage_ids[j] == t.stage)
                    k = j;
            if (k < stage_ids.size()) {
                sums[k] += t.ms;
                ++runs[k];
            }
        }
    OrderedJson& stages = summary["stage_mean_ms"] = OrderedJson::object();
    for (std::size_t k = 0; k < stage_ids.size(); ++k)
        if (runs[k] > 0)
            stages[stage_ids[k]] = ms(sums[k] / double(runs[k]));
    return summary;
}

} // namespace

ResultsHeader resultsHeader(const StreamInput& input)
{
    return {input.stream,        input.lut_path, input.info().width,
            input.info().height, input.skip,     degrees(input.info().orientation)};
}

std::string resultsJson(const ResultsHeader& header, const std::vector<FrameResult>& frames,
                        const std::vector<std::string>& stage_ids)
{
    OrderedJson doc;
    doc["format"] = kFormat;
    doc["stream"] = header.stream;
    doc["lut"] = header.lut;
    doc["width"] = header.width;
    doc["height"] = header.height;
    if (header.orientation != 0) // the coordinates are in the turned frame
        doc["orientation"] = header.orientation;
    if (!header.skipped_stages.empty())
        doc["skipped_stages"] = header.skipped_stages;
    OrderedJson& list = doc["frames"] = OrderedJson::array();
    for (const FrameResult& f : frames)
        list.push_back(frameJson(f));
    doc["summary"] = summaryJson(frames, stage_ids);
    return jsonText(doc) + "\n";
}

Result<ResultsFile> readResults(const std::string& text, const std::string& source,
                                const Pipeline& pipeline)
{
    // Ordered, so stage times come back in the order they were written (pipeline order).
    auto parsed = parseJson<OrderedJson>(text, source);
    if (!parsed)
        return parsed.error();
    const OrderedJson root = std::move(parsed).value();
    if (auto problem = formatProblem(root, source, std::string(kFormat)))
        return *problem;
    ResultsFile file;
    const auto str = [&](const char* key) {
        const auto it = root.find(key);
        return it != root.end() && it->is_string() ? it->get<std::string>() : std::string();
    };
    const auto num = [&](const char* key) {
        const auto it = root.find(key);
        return it != root.end() && it->is_number_integer() ? it->get<int>() : 0;
    };
    file.header = {str("stream"), str("lut"), num("width"), num("height"), {}, num("orientation")};
    if (const auto it = root.find("skipped_stages"); it != root.end() && it->is_array())
        for (const OrderedJson& id : *it)
            if (id.is_string())
                file.header.skipped_stages.push_back(id.get<std::string>());
    const auto frames = root.find("frames");
    if (frames == root.end() || !frames->is_array())
        return Error{source + ": \"frames\" must be an array"};
    const std::vector<const PerceptKind*> kinds = pipeline.perceptKinds();
    for (std::size_t i = 0; i < frames->size(); ++i) {
        const OrderedJson& f = (*frames)[i];
        const std::string where = "frames[" + std::to_string(i) + "]";
        if (!f.is_object() || !f.contains("index") || !f["index"].is_number_unsigned() ||
            !f.contains("name") || !f["name"].is_string())
            return Error{source + ": " + where + " needs \"index\" and \"name\""};
        FrameResult r;
        r.index = f["index"].get<std::size_t>();
        r.name = f["name"].get<std::string>();
        if (const auto time = f.find("time_ms"); time != f.end() && time->is_object())
            for (const auto& [key, value] : time->items()) {
                // Read to the precision written (0.1 microsecond), so a summary made from what
                // was read is the summary of the file's own numbers.
                const double v = value.is_number() ? value.get<double>() : -1.0;
                if (!(v >= 0.0 && v <= kMaxTimeMs))
                    return Error{source + ": " + where + ".time_ms." + key +
                                 " must be a number of milliseconds from 0 to 1e9"};
                if (key == "total")
                    r.report.total_ms = ms(v);
                else
                    r.report.stages.push_back({key, ms(v), true});
            }
        if (auto problem = r.percepts.fromJson(Json(f), kinds, PerceptNames::Results, where))
            return Error{source + ": " + *problem};
        if (const auto diags = f.find("diagnostics"); diags != f.end() && diags->is_array())
            for (const OrderedJson& d : *diags)
                if (d.is_object() && d.contains("stage") && d.contains("message") &&
                    d["stage"].is_string() && d["message"].is_string())
                    r.diagnostics.push_back(
                        {d["stage"].get<std::string>(), d["message"].get<std::string>()});
        file.frames.push_back(std::move(r));
    }
    return file;
}

} // namespace fieldsight
