// Qt-free debug drawings: shapes per layer, produced by stages only when that layer is requested.
#pragma once

#include "visioncore/colour.h"
#include "visioncore/geometry.h"

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

enum class ShapeKind { Points, Line, Polyline, Circle, Rect };

/// One shape in image pixel coordinates.
///  Points: every entry of `points` is a dot of diameter `size`.
///  Line: points[0] to points[1]. Polyline: through all points in order.
///  Circle: centre points[0], radius `size`. Rect: corners points[0] (top-left), points[1].
struct DebugShape
{
    ShapeKind kind = ShapeKind::Points;
    std::vector<PointF> points;
    Rgb colour;
    double size = 1;    ///< px: dot diameter, pen width, or circle radius
    bool filled = false;
};

struct DebugDrawing
{
    std::string layer; ///< layer id, "<stage id>.<name>"
    std::vector<DebugShape> shapes;

    void add(DebugShape shape) { shapes.push_back(std::move(shape)); }
};

/// The layers requested for this frame and what the stages drew into them.
class DebugCanvas
{
public:
    void setRequested(std::set<std::string, std::less<>> layers) { m_requested = std::move(layers); }
    const std::set<std::string, std::less<>>& requested() const { return m_requested; }
    bool wants(std::string_view layer) const { return m_requested.count(layer) != 0; }

    /// The drawing for `layer`, or nullptr when nobody asked for it (then draw nothing).
    DebugDrawing* layer(std::string_view layer);
    const std::map<std::string, DebugDrawing, std::less<>>& drawings() const { return m_drawings; }
    void clear() { m_drawings.clear(); }

private:
    std::set<std::string, std::less<>> m_requested;
    std::map<std::string, DebugDrawing, std::less<>> m_drawings;
};

} // namespace fieldsight
