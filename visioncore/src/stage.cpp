// Stage parameter registry shared by every stage.
#include "visioncore/stage.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

void Stage::addParam(double& storage, ParamInfo info)
{
    storage = info.value;
    m_params.push_back({std::move(info), &storage});
}

std::vector<ParamInfo> Stage::params() const
{
    std::vector<ParamInfo> out;
    out.reserve(m_params.size());
    for (const Bound& b : m_params) {
        ParamInfo info = b.info;
        info.value = *b.storage;
        out.push_back(std::move(info));
    }
    return out;
}

Status Stage::setParam(std::string_view name, double value)
{
    for (Bound& b : m_params) {
        if (b.info.name != name)
            continue;
        if (!std::isfinite(value) || value < b.info.min || value > b.info.max)
            return Error{info().id + "." + std::string(name) + ": " + std::to_string(value) +
                         " is outside [" + std::to_string(b.info.min) + ", " +
                         std::to_string(b.info.max) + "]"};
        *b.storage = value;
        return {};
    }
    return Error{info().id + ": no parameter named '" + std::string(name) + "'"};
}

} // namespace fieldsight
