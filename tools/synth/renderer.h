// Ray-casting renderer: a Scene seen through a CameraModel, with per-pixel class labels and the
// camera effects of a small robot camera (blur, vignetting, noise, 4:2:2 chroma).
#pragma once

#include "synth/camera_model.h"
#include "synth/scene.h"

#include <opencv2/core/mat.hpp>

#include <cstdint>

namespace fieldsight::synth {

struct CameraEffects
{
    double blur_sigma = 0.7;       ///< px, optical blur before the sensor
    double vignette = 0.2;         ///< relative darkening in the image corners
    double noise_y = 1.5;          ///< luma noise standard deviation, 8-bit levels
    double noise_c = 1.5;          ///< chroma noise standard deviation, 8-bit levels
    bool chroma_422 = true;        ///< average Cb and Cr over horizontal pixel pairs
    Eigen::Vector3d gain{1, 1, 1}; ///< white balance per R, G, B
};

/// Label of a pixel whose supersamples saw different classes, or a blend of classes (edges, lines
/// thinner than a supersample); never a LUT vote.
inline constexpr std::uint8_t kMixedLabel = 255;

struct RenderedFrame
{
    cv::Mat bgr;       ///< CV_8UC3, what the PNG holds
    cv::Mat ycbcr;     ///< CV_8UC3, Y, Cb, Cr of `bgr` (SPEC §2, as the core converts it)
    cv::Mat labels;    ///< CV_8U, the Colour id all supersamples saw, else kMixedLabel
    cv::Mat primitive; ///< CV_32S, Scene::primitives index hit at the pixel centre, -1 for none
};

/// Renders with 3 x 3 supersampling; `noise_seed` drives the sensor noise only.
RenderedFrame renderScene(const Scene& scene, const CameraModel& camera,
                          const CameraEffects& effects, std::uint64_t noise_seed);

/// Share (0..1) of a small ground footprint centred on field point (x, y) that is painted white
/// (lines, centre circle, marks). The footprint is spanned by `step_x` and `step_y` (m); zero
/// steps test the point itself. This anti-aliases lines far thinner than a supersample.
double lineCoverage(double x, double y, const Eigen::Vector2d& step_x,
                    const Eigen::Vector2d& step_y);
/// Whether a field point lies on a painted line or mark.
bool onFieldLine(double x, double y);

} // namespace fieldsight::synth
