// What the percept types' JSON readers and writers share: rounding, and strict field reading
// whose messages name the place ("frames[\"f.png\"].balls[0].x must be a number").
#pragma once

#include "visioncore/basics/debug_drawing.h"
#include "visioncore/percepts/percept_set.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace fieldsight::percept_json {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

/// px to 0.001: JSON shows 207.5 rather than 207.50000000000003.
inline double px(double v)
{
    return std::isfinite(v) ? std::round(v * 1000.0) / 1000.0 : v;
}

/// The largest coordinate or size a percept may have in JSON, px: far beyond any frame (at most
/// 8192 px a side), small enough that sums, products and rounding cannot overflow.
inline constexpr double kMaxCoordinate = 1e6;

/// A coordinate read from JSON is a finite number within ±kMaxCoordinate.
inline bool saneCoordinate(double v)
{
    return std::isfinite(v) && std::abs(v) <= kMaxCoordinate;
}

/// Reads the fields of one JSON object, remembering the first problem.
class FieldReader
{
public:
    FieldReader(const Json& object, const std::string& where, std::optional<std::string>& problem)
        : m_object(object), m_where(where), m_problem(problem)
    {
        if (!object.is_object() && !m_problem)
            m_problem = where + " must be an object";
    }

    double number(const char* key)
    {
        if (m_problem)
            return 0;
        const auto it = m_object.find(key);
        if (it == m_object.end() || !it->is_number()) {
            m_problem = m_where + "." + key + " must be a number";
            return 0;
        }
        const double v = it->get<double>();
        if (!saneCoordinate(v)) {
            m_problem = m_where + "." + key + " must be within ±1000000 px (is " + it->dump() + ")";
            return 0;
        }
        return v;
    }
    /// A size: a number from 0 to kMaxCoordinate.
    double size(const char* key)
    {
        const double v = number(key);
        if (!m_problem && v < 0) {
            m_problem = m_where + "." + key + " must not be negative";
            return 0;
        }
        return v;
    }
    /// A pixel index: any JSON number, rounded to the nearest integer.
    int pixel(const char* key) { return int(std::lround(number(key))); }
    bool has(const char* key) const { return m_object.is_object() && m_object.contains(key); }

private:
    const Json& m_object;
    const std::string& m_where;
    std::optional<std::string>& m_problem;
};

/// Reads every element of the array `value` with `each(element, where, out)` (which reports
/// problems through a FieldReader).
template <class P, class Each>
std::optional<std::string> readList(const Json& value, const std::string& where,
                                    std::vector<P>& out, Each each)
{
    if (!value.is_array())
        return where + " must be an array";
    std::optional<std::string> problem;
    for (std::size_t i = 0; i < value.size() && !problem; ++i) {
        const std::string item = where + "[" + std::to_string(i) + "]";
        FieldReader f(value[i], item, problem);
        P p = each(f);
        if (!problem)
            out.push_back(p);
    }
    return problem;
}

/// Writes every element of `items` as the object `each(item)`.
template <class P, class Each>
void writeList(const std::vector<P>& items, OrderedJson& value, Each each)
{
    value = OrderedJson::array();
    for (const P& p : items)
        value.push_back(each(p));
}

} // namespace fieldsight::percept_json

namespace fieldsight {

/// A box's inclusive pixel rows and columns.
struct Box
{
    int left = 0;
    int right = 0;
    int top = 0;
    int bottom = 0;
};

/// The box a Box EditShape's two corners span, in either order, rounded to pixels.
inline Box boxOfShape(const EditShape& shape)
{
    const PointF a = shape.points.size() > 0 ? shape.points[0] : PointF{};
    const PointF b = shape.points.size() > 1 ? shape.points[1] : a;
    const auto lo = [](double u, double v) { return int(std::lround(std::min(u, v))); };
    const auto hi = [](double u, double v) { return int(std::lround(std::max(u, v))); };
    return {lo(a.x, b.x), hi(a.x, b.x), lo(a.y, b.y), hi(a.y, b.y)};
}

} // namespace fieldsight
