// The geometry the annotation tools edit, for any kind by its ShapeForm (image px, pixel centres
// at whole numbers): a new shape from a drag, how near a point is, the handles a shape is
// resized by and what dragging one does.
#pragma once

#include "visioncore/percepts/percept_set.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace fieldsight::ui {

/// What a drag from `from` to `to` draws: a circle from its centre to its rim, a box corner to
/// corner, a segment end to end; none when it is too small to be meant (a click).
std::optional<EditShape> shapeFromDrag(ShapeForm form, PointF from, PointF to);

/// How far `p` is from `shape`, px: 0 inside a circle or a box, else from its outline (a
/// segment's or polyline's line).
double distanceTo(ShapeForm form, const EditShape& shape, PointF p);
/// The area inside `shape` (0 for lines): of two shapes under the pointer, the smaller is the
/// one in front.
double areaOf(ShapeForm form, const EditShape& shape);

/// The points `shape` is resized by: a box's corners (top-left, top-right, bottom-right,
/// bottom-left) then its edges' middles (top, right, bottom, left); a circle's rim (right,
/// bottom, left, top); a segment's ends; a polyline's points.
std::vector<PointF> handlesOf(ShapeForm form, const EditShape& shape);
/// The handle of `handles` nearest `p`, if one is within `tolerance` px.
std::optional<std::size_t> handleAt(const std::vector<PointF>& handles, PointF p, double tolerance);
/// `shape` with handle `handle` (of handlesOf) dragged to `to`.
EditShape dragHandle(ShapeForm form, const EditShape& shape, std::size_t handle, PointF to);
/// `shape` moved by `by`.
EditShape moved(const EditShape& shape, PointF by);

/// The polyline's segment nearest `p` (i: from point i to point i + 1) and how far it is.
std::optional<std::pair<std::size_t, double>> nearestSegment(const EditShape& shape, PointF p);

/// How the frame's objects are shown: a box's four corners, a circle's centre, a line's points.
std::vector<PointF> outlinePoints(ShapeForm form, const EditShape& shape);

} // namespace fieldsight::ui
