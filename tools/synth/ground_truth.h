// Exact ground truth for a rendered frame (SPEC §5.2): what is visible, where, by which rule.
//
// Rules (a frame is always "done", so these decide what a detector is expected to find):
// - ball: the centroid and equal-area radius of its projected outline (see BallImage). Listed when
//   that centre is inside the image, the radius is >= 3 px, and >= 60 % of the pixel centres inside
//   the outline are inside the image and show the ball (not an occluder). A ball in view below
//   this threshold or with its centre outside the image, with >= 10 % seen, is listed as
//   concealed (scored apart by eval), so a detector that finds it scores no false positive.
// - goalposts: the box (inclusive px) of the pixels where the post is the nearest surface, listed
//   when that box is >= 8 px tall and >= 2 px wide, and as concealed when smaller or when its
//   foot is in the frame but hidden behind something nearer (the box then ends at the occluder,
//   not at the base). The crossbar is not a post.
// - obstacles: robots and people on the carpet. Visibility is judged on the parts below 0.5 m (all
//   of a robot; a person's shoes and shins): listed when >= 50 % of those parts' pixels are seen
//   and the box of all its seen pixels is >= 6 px wide, as concealed when 10 % to 50 % are seen.
//   The box is that of the seen pixels.
// - field_boundary: per column, the top of the carpet (field plus border strip) as projected,
//   ignoring everything standing on it; h-1 where the carpet is not in the column, 0 where it
//   covers the whole column. Simplified to a polyline within 0.25 px, x = 0 .. width-1.
// - field_lines: the straight lines (touch, goal, halfway, goal-area lines) as centre-line
//   segments clipped to the image, >= 3 px long. Listed as concealed when less than half of that
//   length is seen: at least kMinLineWidth wide across itself there and not behind anything
//   standing on the field (far lines run nearly along the image rows and grow thin; a robot hides
//   what is behind it). The centre circle and the marks are not straight lines and are not listed.
#pragma once

#include "synth/camera_model.h"
#include "synth/scene.h"

#include "visioncore/io/annotations.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"

#include <opencv2/core/mat.hpp>

#include <optional>
#include <vector>

namespace fieldsight::synth {

/// A sphere's image: the outline of its projection (an ellipse off the optical axis), the
/// outline's centroid, and the radius of the disc of equal area. On the optical axis this is a
/// circle of radius sqrt(f_x f_y) tan(asin(r / d)), within 0.3 % of f r / d for a ball beyond 1 m.
struct BallImage
{
    PointF centre;     ///< px
    double radius = 0; ///< px
    std::vector<PointF> outline;
};
/// Nothing when the ball is not wholly in front of the camera.
std::optional<BallImage> ballImage(const CameraModel& camera, const Eigen::Vector3d& centre,
                                   double radius);

/// `primitive` is RenderedFrame::primitive of the same scene and camera.
FrameAnnotation groundTruth(const Scene& scene, const CameraModel& camera,
                            const cv::Mat& primitive);

/// Per-column top of the carpet, before simplification (one value per column).
std::vector<double> fieldTopPerColumn(const CameraModel& camera);
/// A straight field line as the image shows its centre, and the line it is.
struct ProjectedLine
{
    FieldLine line;
    const LineSegment* source = nullptr;
};
std::vector<ProjectedLine> projectedFieldLines(const CameraModel& camera);
/// A line in the image narrower than this across itself (px) is not seen there: it covers less
/// than half of any pixel it crosses, so no pixel of it is mostly line and a colour table cannot
/// call one white.
constexpr double kMinLineWidth = 0.5;
/// The share of `line`'s length in the image that is seen: in the image, at least kMinLineWidth
/// wide there, and not behind anything standing on the field (`primitive`, the renderer's map of
/// what each pixel shows).
double seenLineShare(const LineSegment& line, const CameraModel& camera, const cv::Mat& primitive);

} // namespace fieldsight::synth
