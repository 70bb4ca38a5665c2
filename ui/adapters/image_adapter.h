// The only cv::Mat <-> QImage code: frames from the core to QImages for painting and display;
// and the colour classes as the GUI shows them (name, swatch).
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/percepts/percept_set.h"

#include <QColor>
#include <QIcon>
#include <QImage>
#include <QString>

#include <opencv2/core/mat.hpp>

namespace fieldsight::ui {

/// A CV_8UC3 Y, Cb, Cr frame (the core's pixel order) as a QImage::Format_RGB888 that owns its
/// pixels, converted by visioncore's ycbcrToBgr (BT.601 full range). A null QImage when `ycbcr`
/// is empty or not CV_8UC3.
QImage ycbcrToQImage(const cv::Mat& ycbcr);

/// A CV_8UC3 Y, Cb, Cr frame enlarged `scale` times (scale < 1 counts as 1) with nearest neighbour,
/// so each image pixel is a crisp scale x scale block, as a QImage::Format_RGB32 (the format
/// QPainter draws on and widgets show fastest). A null QImage when `ycbcr` is empty or not CV_8UC3.
QImage ycbcrToZoomedQImage(const cv::Mat& ycbcr, int scale);

/// A CV_8UC3 B, G, R image as a QImage::Format_RGB888 that owns its pixels (no sharing with
/// `bgr`). A null QImage when `bgr` is empty or not CV_8UC3.
QImage bgrToQImage(const cv::Mat& bgr);

QColor toQColor(Rgb colour);
/// A colour class's name as shown ("pink_orange").
QString colourLabel(Colour colour);
/// What one detection of `kind` is called: its title's singular, from the percept registry (a
/// new kind needs no words in the GUI).
QString perceptNoun(const PerceptKind& kind);
/// A 16 px square of the class's display colour (SPEC §1) with a grey border.
QIcon colourSwatch(Colour colour);
/// A highlight: `colour` where the CV_8U `mask` is nonzero, transparent elsewhere (null when the
/// mask is empty).
QImage maskToQImage(const cv::Mat& mask, QColor colour);

} // namespace fieldsight::ui
