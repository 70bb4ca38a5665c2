// The automatic table's evidence (lut_auto.h): which pixels of a frame show which class, found
// from the frames alone. The carpet is modelled first over all frames; then each frame's pixels
// are labelled by where they are and what they form.
#pragma once

#include "visioncore/basics/colour.h"

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace fieldsight::autolut {

/// A Gaussian in Y, Cb, Cr.
struct Gaussian
{
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Matrix3d inverse = Eigen::Matrix3d::Identity();
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
    bool valid = false;

    /// The squared Mahalanobis distance, d' inverse d, in plain arithmetic on the coefficients
    /// (summed in the order Eigen's product and dot sum them, so the same bits): it runs for
    /// every pixel of every frame, and Eigen's expressions, unless inlined whole, cost tens of
    /// calls a pixel (the sanitizer build's -O1 inlines few: 30 % of its test time was here).
    double distance2(double y, double cb, double cr) const
    {
        const double* mu = mean.data();
        const double* a = inverse.data(); // column-major
        const double d0 = y - mu[0], d1 = cb - mu[1], d2 = cr - mu[2];
        const double r0 = a[0] * d0 + a[3] * d1 + a[6] * d2;
        const double r1 = a[1] * d0 + a[4] * d1 + a[7] * d2;
        const double r2 = a[2] * d0 + a[5] * d1 + a[8] * d2;
        return d0 * r0 + d1 * r1 + d2 * r2;
    }
};

/// Sums for a mean and covariance, in plain arrays: added to for every pixel of evidence (see
/// Gaussian::distance2).
struct Moments
{
    double n = 0;
    double sum[3] = {0, 0, 0};
    double outer[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; ///< [row][column]

    void add(const std::uint8_t* px) { add(px[0], px[1], px[2], 1); }
    void add(double y, double cb, double cr, double weight)
    {
        const double p[3] = {y, cb, cr};
        n += weight;
        for (int i = 0; i < 3; ++i) {
            const double wp = weight * p[i];
            sum[i] += wp;
            for (int j = 0; j < 3; ++j)
                outer[i][j] += p[j] * wp;
        }
    }
    /// The Gaussian of the samples with `floor` (units², per channel Y, Cb, Cr) added to the
    /// covariance's diagonal, so JPEG noise and a narrow sample do not make it a needle.
    Gaussian gaussian(const Eigen::Vector3d& floor) const;
};

/// The classes the evidence names; background is what must stay unclassified.
/// WarmShape: a warm (orange-red) shape on the field that is not a round blob: a ball cut by the
/// frame or half hidden by a robot, or a robot's red part. It holds cells back from the ball as
/// Background does, except in the core of the ball's colour (lut_auto.cpp).
enum class Evidence : std::uint8_t {
    Green,
    White,
    Orange,
    Yellow,
    Blue,
    Background,
    WarmShape,
    Count
};
inline constexpr std::size_t kEvidenceCount = std::size_t(Evidence::Count);
Colour evidenceColour(Evidence e);

/// Pixels per class per table cell, and each class's moments.
struct EvidenceSet
{
    std::unordered_map<std::uint32_t, std::array<std::uint32_t, kEvidenceCount>> cells;
    std::array<Moments, kEvidenceCount> moments;
    /// Ball-like blobs seen.
    std::size_t ball_blobs = 0;
    /// Per goal colour (yellow, blue): pixels of posts, and of all its shapes near the field. A
    /// goal's colour is mostly posts; a wall's or a crowd's is mostly not.
    struct GoalCue
    {
        double posts = 0;
        double shapes = 0;
        /// The share of the colour's shapes that are posts.
        double share() const { return shapes > 0 ? posts / shapes : 0; }
        /// Post pixels weighed by their share of the colour's shapes.
        double weight() const { return posts * share(); }
    };
    std::array<GoalCue, 2> goals{};
    GoalCue& goal(Evidence e) { return goals[e == Evidence::Blue ? 1 : 0]; }
    const GoalCue& goal(Evidence e) const { return goals[e == Evidence::Blue ? 1 : 0]; }

    void add(Evidence e, const std::uint8_t* px);
    /// `count` pixels of `cell` (a table index), as at the cell's centre.
    void addCell(Evidence e, std::uint32_t cell, std::uint32_t count);
};

/// The field's far edge per column (px; rows below it are the field), from a frame's carpet mask
/// (CV_8U, non-zero carpet): the upper convex hull of the largest carpet patch reaching the lower
/// half. A column without field gets the frame's height.
std::vector<double> fieldEdge(const cv::Mat& green, double scale);

/// Marks in `white` the `candidate` pixels that lie in thin runs with carpet at both ends, across
/// rows and down columns, on the field below `edge`.
void thinRuns(const cv::Mat& candidate, const cv::Mat& green, const std::vector<double>& edge,
              double scale, cv::Mat& white);

/// Calls `f(px)` for every second pixel of every second row of each frame's lower part (from row
/// `tops[i]` of `frames[i]`) whose luma is neither too dark nor clipped for its colour to count.
template <class F>
void forLowerPixels(const std::vector<cv::Mat>& frames, const std::vector<int>& tops, F&& f)
{
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const cv::Mat& img = frames[i];
        for (int y = std::max(0, tops[i]); y < img.rows; y += 2) {
            const std::uint8_t* row = img.ptr<std::uint8_t>(y);
            for (int x = 0; x < img.cols; x += 2) {
                const std::uint8_t* px = row + 3 * x;
                if (px[0] >= 24 && px[0] <= 240)
                    f(px);
            }
        }
    }
}

/// The carpet: the dominant chroma cluster in the lower part of the frames (below the kinematic
/// horizon where a frame has one). `frames` are CV_8UC3 Y, Cb, Cr; `tops` the first row of each
/// frame to look at.
std::optional<Gaussian> findCarpet(const std::vector<cv::Mat>& frames,
                                   const std::vector<int>& tops);

/// Labels one frame's pixels into `out`, given the carpet: green on the field, white in thin runs
/// bordered by carpet, ball-coloured blobs that are round and on the field, goal-coloured bars
/// that stand at the field's edge; other saturated shapes touching the field are background
/// (warm ones WarmShape, which holds cells back from all but the ball's core).
void collectEvidence(const cv::Mat& ycbcr, const Gaussian& carpet, EvidenceSet& out);

} // namespace fieldsight::autolut
