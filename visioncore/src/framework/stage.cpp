// The parameter registry every stage shares, and typed parameters.
#include "visioncore/framework/stage.h"

#include <cmath>
#include <cstdio>

namespace fieldsight {

std::string_view paramKindName(ParamKind kind)
{
    switch (kind) {
    case ParamKind::Real:
        return "real";
    case ParamKind::Integer:
        return "integer";
    case ParamKind::Boolean:
        return "boolean";
    case ParamKind::Choice:
        return "choice";
    }
    return "real";
}

namespace detail {
std::vector<ParamChoice> colourChoices()
{
    std::vector<ParamChoice> choices;
    for (int id = 0; id < kColourCount; ++id)
        choices.push_back({id, std::string(colourName(Colour(id)))});
    return choices;
}
} // namespace detail

ParamBase::ParamBase(Stage* owner, ParamKind kind, double default_value, const ParamSpec& spec,
                     std::vector<ParamChoice> choices)
{
    m_info.name = spec.name;
    m_info.kind = kind;
    m_info.unit = spec.unit;
    m_info.scales_with_width = m_info.unit == "px" && kind != ParamKind::Choice;
    if (m_info.scales_with_width)
        m_scale = &owner->m_pixel_scale;
    m_info.description = spec.description;
    m_info.fitted = spec.fitted;
    m_info.default_value = default_value;
    m_info.min = spec.min;
    m_info.max = spec.max;
    m_info.choices = std::move(choices);
    if (kind == ParamKind::Boolean) {
        m_info.min = 0;
        m_info.max = 1;
    }
    if (kind == ParamKind::Choice && !m_info.choices.empty()) {
        m_info.min = m_info.choices.front().value;
        m_info.max = m_info.choices.back().value;
    }
    m_info.step = spec.step > 0             ? spec.step
                  : kind == ParamKind::Real ? (m_info.max - m_info.min) / 100.0
                                            : 1.0;
    owner->m_params.push_back(this);
}

ParamInfo ParamBase::info() const
{
    ParamInfo info = m_info;
    info.value = load();
    return info;
}

namespace {
std::string number(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}
} // namespace

Status checkParamValue(const ParamInfo& param, std::string_view stage_id, double value)
{
    const std::string where = std::string(stage_id) + "." + param.name + ": ";
    if (!std::isfinite(value) || value < param.min || value > param.max)
        return Error{where + number(value) + " is outside [" + number(param.min) + ", " +
                     number(param.max) + "]"};
    if (param.kind != ParamKind::Real && value != std::floor(value))
        return Error{where + number(value) + " is not a whole number (" +
                     std::string(paramKindName(param.kind)) + ")"};
    if (param.kind == ParamKind::Choice) {
        bool known = false;
        for (const ParamChoice& c : param.choices)
            known = known || c.value == value;
        if (!known)
            return Error{where + number(value) + " is not one of its choices"};
    }
    return {};
}

Status ParamBase::set(std::string_view stage_id, double value)
{
    if (Status s = checkParamValue(m_info, stage_id, value); !s)
        return s;
    store(value);
    return {};
}

std::vector<ParamInfo> Stage::params() const
{
    std::vector<ParamInfo> out;
    out.reserve(m_params.size());
    for (const ParamBase* p : m_params)
        out.push_back(p->info());
    return out;
}

Status Stage::setParam(std::string_view name, double value)
{
    for (ParamBase* p : m_params)
        if (p->name() == name)
            return p->set(info().id, value);
    return Error{info().id + ": no parameter named '" + std::string(name) + "'"};
}

void Stage::resetParams()
{
    for (ParamBase* p : m_params)
        p->reset();
}

} // namespace fieldsight
