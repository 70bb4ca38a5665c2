// The detections' labels over the frame view ("Ball 1" on a dark box above each object).
#pragma once

#include "ui/worker/frame_worker.h"
#include "visioncore/services/layers.h"

#include <QPointF>

#include <vector>

class QPainter;

namespace fieldsight::ui {

/// Paints the label of each of `items` whose layer is `visible`, above its top-left corner, at
/// `opacity`; a label that would cover another moves down a line, so every one stays readable.
/// `origin` is where image pixel (0, 0)'s corner is in the widget, `zoom` widget px per image
/// px. The painter's state is unchanged afterwards.
void paintPerceptLabels(QPainter& p, const std::vector<PerceptItem>& items, const LayerSet& visible,
                        QPointF origin, double zoom, double opacity);

} // namespace fieldsight::ui
