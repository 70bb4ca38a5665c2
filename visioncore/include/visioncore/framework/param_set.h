// A set of stage parameter values: read from and written to JSON (fieldsight-params/1), parsed
// from "STAGE.PARAM=VALUE" settings, and applied to a core in one call.
#pragma once

#include "visioncore/basics/result.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

class Pipeline;
struct StageDescriptor;

struct ParamSet
{
    /// stage id -> parameter name -> value
    std::map<std::string, std::map<std::string, double, std::less<>>, std::less<>> values;

    bool empty() const { return values.empty(); }
    void set(std::string_view stage, std::string_view name, double value);
    /// Adds the values of `other`, replacing those already here.
    void merge(const ParamSet& other);

    /// Parses "STAGE.PARAM=VALUE" (e.g. transitions.goal_colour=9) into this set.
    Status parseSetting(std::string_view setting);
    /// Every value names a stage and parameter of `pipeline` (or of `stages`) and is valid for
    /// it (kind, range).
    Status check(const Pipeline& pipeline) const;
    Status check(const std::vector<StageDescriptor>& stages) const;

    /// {"format": "fieldsight-params/1", "stages": {"ball": {"min_radius": 2.5}}}
    std::string toJson() const;
    static Result<ParamSet> fromJson(const std::string& text, const std::string& source);
    static Result<ParamSet> load(const std::string& path);
    /// Writes toJson() atomically; the top-level keys other than "format" and "stages" of a
    /// parameters file already there (another tool's notes) are kept, after those two.
    Status save(const std::string& path) const;
};

} // namespace fieldsight
