// Parameter sets: JSON, settings, and the check against a pipeline's parameters.
#include "visioncore/framework/param_set.h"

#include "visioncore/basics/json_text.h"
#include "basics/json_format.h"
#include "visioncore/framework/controller.h"
#include "visioncore/basics/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

#include <cstdlib>

namespace fieldsight {

namespace {
constexpr const char* kParamsFormat = "fieldsight-params/1";
}

void ParamSet::set(std::string_view stage, std::string_view name, double value)
{
    values[std::string(stage)][std::string(name)] = value;
}

void ParamSet::merge(const ParamSet& other)
{
    for (const auto& [stage, params] : other.values) {
        values[stage]; // a stage with no values is kept, so check() still sees its name
        for (const auto& [name, value] : params)
            set(stage, name, value);
    }
}

Status ParamSet::parseSetting(std::string_view text)
{
    const auto dot = text.find('.');
    const auto eq = text.find('=');
    const std::string where = "'" + std::string(text) + "': ";
    if (dot == std::string_view::npos || eq == std::string_view::npos || dot > eq || dot == 0 ||
        eq == dot + 1)
        return Error{where + "expected STAGE.PARAM=VALUE"};
    const std::string number(text.substr(eq + 1));
    char* end = nullptr;
    const double value = std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size())
        return Error{where + "the value is not a number"};
    set(text.substr(0, dot), text.substr(dot + 1, eq - dot - 1), value);
    return {};
}

Status ParamSet::check(const std::vector<StageDescriptor>& stages) const
{
    // Named references, not structured bindings: clang before 16 cannot capture those.
    for (const auto& stage_entry : values) {
        const std::string& stage_id = stage_entry.first;
        const auto& params = stage_entry.second;
        const auto stage =
            std::find_if(stages.begin(), stages.end(),
                         [&](const StageDescriptor& d) { return d.info.id == stage_id; });
        if (stage == stages.end()) {
            std::string list;
            for (const StageDescriptor& d : stages)
                list += (list.empty() ? "" : ", ") + d.info.id;
            return Error{"unknown stage '" + stage_id + "' (the stages are " + list + ")"};
        }
        for (const auto& param_entry : params) {
            const std::string& name = param_entry.first;
            const double value = param_entry.second;
            const auto param = std::find_if(stage->params.begin(), stage->params.end(),
                                            [&](const ParamInfo& p) { return p.name == name; });
            if (param == stage->params.end())
                return Error{stage_id + ": no parameter named '" + name + "'"};
            if (Status s = checkParamValue(*param, stage_id, value); !s)
                return s;
        }
    }
    return {};
}

Status ParamSet::check(const Pipeline& pipeline) const
{
    return check(pipeline.descriptors());
}

std::string ParamSet::toJson() const
{
    nlohmann::ordered_json stages = nlohmann::ordered_json::object();
    for (const auto& [stage, params] : values)
        for (const auto& [name, value] : params)
            stages[stage][name] = value;
    nlohmann::ordered_json root;
    root["format"] = kParamsFormat;
    root["stages"] = std::move(stages);
    return jsonText(root, 2) + "\n";
}

Result<ParamSet> ParamSet::fromJson(const std::string& text, const std::string& source)
{
    auto parsed = parseJson(text, source);
    if (!parsed)
        return parsed.error();
    const nlohmann::json root = std::move(parsed).value();
    if (auto problem = formatProblem(root, source, kParamsFormat))
        return *problem;
    ParamSet set;
    const auto stages = root.find("stages");
    if (stages == root.end())
        return set;
    if (!stages->is_object())
        return Error{source + ": \"stages\" must be an object keyed by stage id"};
    for (const auto& [stage, params] : stages->items()) {
        if (!params.is_object())
            return Error{source + ": stages." + stage + " must be an object"};
        set.values[stage]; // kept even when empty: check() then names an unknown stage
        for (const auto& [name, value] : params.items()) {
            if (value.is_boolean())
                set.set(stage, name, value.get<bool>() ? 1.0 : 0.0);
            else if (value.is_number())
                set.set(stage, name, value.get<double>());
            else
                return Error{source + ": stages." + stage + "." + name + " must be a number"};
        }
    }
    return set;
}

Result<ParamSet> ParamSet::load(const std::string& path)
{
    // Every parameter of every stage takes a few kilobytes.
    constexpr std::size_t kMaxBytes = std::size_t(1) << 20;
    return readingWithinMemory(path, [&]() -> Result<ParamSet> {
        auto text = readWholeFile(path, kMaxBytes, "a parameters file");
        if (!text)
            return text.error();
        return fromJson(text.value(), path);
    });
}

Status ParamSet::save(const std::string& path) const
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return writeFileAtomically(path, toJson());
    // What this version does not read is written back as it was.
    nlohmann::ordered_json root = parseJson<nlohmann::ordered_json>(toJson(), path).value();
    if (auto old = readWholeFile(path, std::size_t(1) << 20); old) {
        const auto before = jsonOrDiscarded(old.value());
        if (!formatProblem(before, path, kParamsFormat))
            addUnknownKeys(unknownKeys(before, {"format", "stages"}), root);
    }
    return writeFileAtomically(path, jsonText(root, 2) + "\n");
}

} // namespace fieldsight
