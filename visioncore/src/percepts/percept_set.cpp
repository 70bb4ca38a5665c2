// The percept set: type-erased lists of percepts, their JSON and their layers.
#include "visioncore/percepts/percept_set.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace fieldsight {

namespace {
std::string_view nameOf(const PerceptKind& kind, PerceptNames names)
{
    return names == PerceptNames::Truth ? kind.truth_key : kind.key;
}
} // namespace

PerceptSet::PerceptSet(const PerceptSet& other)
{
    *this = other;
}

PerceptSet& PerceptSet::operator=(const PerceptSet& other)
{
    if (this == &other)
        return *this;
    m_entries.clear();
    m_entries.reserve(other.m_entries.size());
    for (const auto& e : other.m_entries)
        m_entries.push_back(e->clone());
    m_present_count = other.m_present_count;
    return *this;
}

PerceptSet::~PerceptSet() = default;

PerceptEntry& PerceptSet::entry(const PerceptKind& kind)
{
    for (const auto& e : m_entries)
        if (&e->kind() == &kind)
            return *e;
    m_entries.push_back(kind.make());
    return *m_entries.back();
}

const PerceptEntry* PerceptSet::find(const PerceptKind& kind) const
{
    for (const auto& e : m_entries)
        if (&e->kind() == &kind)
            return e.get();
    return nullptr;
}

std::vector<const PerceptEntry*> PerceptSet::entries() const
{
    std::vector<const PerceptEntry*> out;
    for (const auto& e : m_entries)
        if (e->present())
            out.push_back(e.get());
    return out;
}

void PerceptSet::clear()
{
    for (const auto& e : m_entries) {
        e->clear();
        e->m_present = false;
    }
    m_present_count = 0;
}

void PerceptSet::toJson(nlohmann::ordered_json& object, PerceptNames names,
                        const std::vector<const PerceptKind*>& order) const
{
    const auto write = [&](const PerceptEntry& e) {
        e.toJson(names, object[std::string(nameOf(e.kind(), names))]);
    };
    for (const PerceptKind* kind : order)
        if (const PerceptEntry* e = find(*kind); e && e->present())
            write(*e);
    for (const auto& e : m_entries)
        if (e->present() && std::find(order.begin(), order.end(), &e->kind()) == order.end())
            write(*e);
}

std::optional<std::string> PerceptSet::fromJson(const nlohmann::json& object,
                                                const std::vector<const PerceptKind*>& kinds,
                                                PerceptNames names, const std::string& where)
{
    if (!object.is_object())
        return where + " must be an object";
    for (const PerceptKind* kind : kinds) {
        const std::string key(nameOf(*kind, names));
        const auto it = object.find(key);
        if (it == object.end())
            continue;
        PerceptEntry& e = entry(*kind);
        if (auto problem = e.fromJson(*it, names, where + "." + key))
            return problem;
        markPresent(e);
    }
    return std::nullopt;
}

std::vector<DebugDrawing> PerceptSet::drawings(bool truth) const
{
    std::vector<DebugDrawing> out;
    const PerceptNames names = truth ? PerceptNames::Truth : PerceptNames::Results;
    const std::string_view prefix = truth ? kTruthLayerPrefix : kPerceptLayerPrefix;
    for (const auto& e : m_entries) {
        if (!e->present())
            continue;
        DebugDrawing d;
        d.layer = std::string(prefix) + "." + std::string(nameOf(e->kind(), names));
        // A dark rim under each keeps it visible on its own colour (a ball outline on the ball,
        // a true line on a white line).
        if (truth) {
            e->draw(kPerceptRimColour, kTruthLineWidth + 2, d);
            e->draw(kTruthColour, kTruthLineWidth, d);
        } else {
            e->draw(kPerceptRimColour, kPerceptLineWidth + 2, d);
            e->draw(e->kind().colour, kPerceptLineWidth, d);
        }
        out.push_back(std::move(d));
    }
    return out;
}

std::vector<std::string> perceptLayerIds(const std::vector<const PerceptKind*>& kinds, bool truth)
{
    std::vector<std::string> ids;
    for (const PerceptKind* kind : kinds)
        ids.push_back(
            std::string(truth ? kTruthLayerPrefix : kPerceptLayerPrefix) + "." +
            std::string(nameOf(*kind, truth ? PerceptNames::Truth : PerceptNames::Results)));
    return ids;
}

} // namespace fieldsight
