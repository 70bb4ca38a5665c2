// Qt-free debug drawings: shapes per layer, produced by stages only when that layer is requested.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/geometry.h"

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

enum class ShapeKind { Points, Line, Polyline, Circle, Rect };

/// One shape in image coordinates: x right, y down, integer coordinates at pixel centres (pixel
/// (x, y) covers [x - 0.5, x + 0.5) x [y - 0.5, y + 0.5)).
///  Points: every entry of `points` is a filled square of side `size` image px.
///  Line: points[0] to points[1]. Polyline: through all points in order.
///  Circle: centre points[0], radius `size` image px.
///  Rect: corners points[0] (top-left) and points[1] (bottom-right), outlined or `filled`.
/// Outlines are drawn `width` screen px wide at any zoom.
struct DebugShape
{
    ShapeKind kind = ShapeKind::Points;
    std::vector<PointF> points;
    Rgb colour;
    double size = 1; ///< image px: side of a point, radius of a circle
    bool filled = false;
    double width = 1; ///< screen px: pen width of lines and outlines
};

struct DebugDrawing
{
    std::string layer; ///< layer id, "<stage id>.<name>"
    std::vector<DebugShape> shapes;

    /// Why a shape is there, for a user pointing at it (a rejected candidate's reason), by its
    /// index in `shapes`; most shapes have none.
    std::map<std::size_t, std::string> notes;

    void add(DebugShape shape) { shapes.push_back(std::move(shape)); }
    void add(DebugShape shape, std::string note)
    {
        notes[shapes.size()] = std::move(note);
        shapes.push_back(std::move(shape));
    }
};

/// The layers requested for this frame and what the stages drew into them.
class DebugCanvas
{
public:
    void setRequested(std::set<std::string, std::less<>> layers)
    {
        m_requested = std::move(layers);
    }
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
