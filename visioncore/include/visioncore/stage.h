// Stage: one processing module of the bottom layer, with its id, parameters and debug layers.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "visioncore/result.h"

namespace fieldsight {

class Blackboard;

/// A tunable parameter. All are doubles; integer ones are rounded where used.
struct ParamInfo
{
    std::string name;        ///< snake_case, unique within the stage
    std::string unit;        ///< "px", "cm", "rad", "" for counts and ratios
    std::string description;
    double value = 0;
    double min = 0;
    double max = 0;
};

struct LayerInfo
{
    std::string id;   ///< "<stage id>.<name>", e.g. "green_horizon.hull"
    std::string name; ///< for a layer list
};

struct StageInfo
{
    std::string id;   ///< SPEC §5 stage id, e.g. "green_horizon"
    std::string name; ///< human name, e.g. "Green horizon"
    bool skippable = true; ///< can a host switch it off per frame
    std::vector<std::string> reads;  ///< blackboard fields it needs
    std::vector<std::string> writes; ///< blackboard fields it produces
    std::vector<LayerInfo> layers;
};

class Stage
{
public:
    Stage() = default;
    Stage(const Stage&) = delete; // parameters point into the stage
    Stage& operator=(const Stage&) = delete;
    virtual ~Stage() = default;
    virtual const StageInfo& info() const = 0;
    /// Reads its inputs from and writes its results to `bb`. May throw; the controller turns an
    /// exception into a per-frame diagnostic.
    virtual void run(Blackboard& bb) = 0;

    std::vector<ParamInfo> params() const;
    Status setParam(std::string_view name, double value);

protected:
    /// Registers a parameter stored in `storage` (a member of the stage), with its default.
    void addParam(double& storage, ParamInfo info);

private:
    struct Bound
    {
        ParamInfo info;
        double* storage;
    };
    std::vector<Bound> m_params;
};

} // namespace fieldsight
