// Small helpers the stages share: the colours of their debug layers (also in their LayerInfo,
// the legend) and shape builders.
#pragma once

#include "visioncore/basics/debug_drawing.h"
#include "visioncore/framework/param.h"

#include <cstdio>
#include <string>
#include <vector>

namespace fieldsight {

namespace debug_colour {
inline constexpr Rgb kMagenta{255, 0, 255};
inline constexpr Rgb kRed{255, 0, 0};
inline constexpr Rgb kBlue{0, 80, 255};
inline constexpr Rgb kCyan{0, 255, 255};
inline constexpr Rgb kGrey{128, 128, 128};
inline constexpr Rgb kWhite{255, 255, 255};
inline constexpr Rgb kSkyBlue{40, 140, 255};
inline constexpr Rgb kPurple{170, 60, 255};
inline constexpr Rgb kLime{170, 255, 0};
inline constexpr Rgb kPink{255, 150, 200};
/// Every stage's layer of rejected candidates; each shape's note says why.
inline constexpr Rgb kRejected{220, 20, 60};
} // namespace debug_colour

/// The seed parameter of every stage that samples with RANSAC (default 1).
inline constexpr ParamSpec kRansacSeed{
    "seed", "", 0, 4294967295.0, 1, "RANSAC seed; every frame starts from it.", false};

template <class P> DebugShape pointsShape(const std::vector<P>& points, Rgb colour, double size)
{
    DebugShape shape{ShapeKind::Points, {}, colour, size, true, 1};
    shape.points.reserve(points.size());
    for (const P& p : points)
        shape.points.push_back({double(p.x), double(p.y)});
    return shape;
}

/// `value` with one decimal ("7.1"), for the notes of rejected candidates.
inline std::string oneDecimal(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

/// Adds `shape` in the rejected colour to a rejected-candidates layer, its note saying why.
/// Callers build the shape and the note only when the layer was asked for (bb.debug.layer is not
/// null): a frame nobody draws pays nothing for them.
inline void addRejected(DebugDrawing& layer, DebugShape shape, std::string why)
{
    shape.colour = debug_colour::kRejected;
    layer.add(std::move(shape), std::move(why));
}

inline DebugShape circleShape(PointF centre, double radius, Rgb colour)
{
    return DebugShape{ShapeKind::Circle, {centre}, colour, radius, false, 1};
}

inline DebugShape rectShape(PointF top_left, PointF bottom_right, Rgb colour)
{
    return DebugShape{ShapeKind::Rect, {top_left, bottom_right}, colour, 1, false, 1};
}

inline DebugShape lineShape(PointF a, PointF b, Rgb colour, double width = 1)
{
    return DebugShape{ShapeKind::Line, {a, b}, colour, 1, false, width};
}

} // namespace fieldsight
