// The one painter of the core's debug drawings, shared by the GUI frame view and headless renders.
#pragma once

#include "visioncore/basics/debug_drawing.h"

#include <QImage>

#include <opencv2/core/mat.hpp>

#include <string_view>
#include <vector>

class QPainter;

namespace fieldsight::ui {

// Conventions (every caller relies on them, so a frame view and a saved render show the same
// pixels):
// - The painter's transform maps image coordinates to the target: renderOverlay() sets
//   scale(scale, scale); a frame view sets its zoom and pan.
// - Image pixel (x, y) covers [x, x+1) x [y, y+1) and a shape coordinate names a pixel, so
//   coordinate c is drawn at c + 0.5, the pixel's centre (fractional coordinates round to the
//   nearest pixel). Ties are broken up and left (by 1/32 device px): at an even zoom a 1 px line
//   through a pixel takes the upper (left) of the two middle device rows (columns) of its block.
// - No antialiasing: crisp pixels at any zoom, the same drawing always gives the same pixels.
// - Line, Polyline, Circle and Rect outlines use a cosmetic pen max(1, width) device px wide, so
//   their width does not grow with zoom. A Circle's `size` is its radius in image px; a filled
//   Circle is filled too.
// - Points: each point is a filled square of side `size` image px (1 if size <= 0) centred on its
//   pixel's centre: size 1 covers exactly that pixel, size 3 the 3x3 block around it.
// - Rect: corners points[0] and points[1], in either order. The outline runs through the centres of
//   the corner pixels; a filled Rect covers every pixel from one corner to the other, both
//   included, without an outline.
// - A shape with fewer points than its kind needs is skipped; so is a null drawing.
// - Ground truth (a layer "truth.<key>") is drawn dashed, 5 device px on and 3 off at any pen
//   width, flat-capped; detections solid. The truth goes over the detections (layers.h), so where
//   a detection lies on its true object both show.
// - No fonts or text, so painting needs no QGuiApplication and no display, only a QImage.

/// A ground-truth layer id ("truth.balls"): painted dashed.
bool isTruthLayer(std::string_view layer);

/// Paints one shape with the conventions above (outlines `dashed`, as ground truth's). Sets the
/// painter's pen, brush and antialiasing hint and leaves them set (it is called in loops;
/// paintDrawing() saves and restores around them).
void paintShape(QPainter& painter, const DebugShape& shape, bool dashed = false);

/// Paints the drawing's shapes in order; the painter's state is unchanged afterwards.
void paintDrawing(QPainter& painter, const DebugDrawing& drawing);

/// A CV_8UC3 Y, Cb, Cr frame enlarged `scale` times (scale < 1 counts as 1) with nearest
/// neighbour, so each image pixel is a scale x scale block, with `drawings` painted over it in
/// order (a later drawing covers an earlier one). Format_RGB32; a null QImage when `ycbcr` is empty
/// or not CV_8UC3.
QImage renderOverlay(const cv::Mat& ycbcr, const std::vector<const DebugDrawing*>& drawings,
                     int scale);

} // namespace fieldsight::ui
