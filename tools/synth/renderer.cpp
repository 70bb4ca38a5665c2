// Ray-casting renderer with exact occlusion: each supersample takes the nearest surface.
#include "synth/renderer.h"

#include "synth/synth_random.h"
#include "visioncore/basics/ycbcr.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace fieldsight::synth {

namespace {

using Vec3 = Eigen::Vector3d;

struct ScreenRect
{
    int left = 0;
    int right = -1;
    int top = 0;
    int bottom = -1;
};

/// The primitive's image box (with a pixel of margin), clipped to the image.
ScreenRect screenRect(const Primitive& p, const CameraModel& camera)
{
    double ex = p.radius;
    double ey = p.radius;
    double z0 = p.z0;
    double z1 = p.z1;
    if (p.shape == Primitive::Shape::Box) {
        const double c = std::abs(p.cos_yaw);
        const double s = std::abs(p.sin_yaw);
        ex = c * p.half_x + s * p.half_y;
        ey = s * p.half_x + c * p.half_y;
    }
    if (p.shape == Primitive::Shape::Sphere) {
        z0 = p.centre.z() - p.radius;
        z1 = p.centre.z() + p.radius;
    }
    ScreenRect full{0, camera.width() - 1, 0, camera.height() - 1};
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner(p.centre.x() + ((i & 1) ? ex : -ex), p.centre.y() + ((i & 2) ? ey : -ey),
                          (i & 4) ? z1 : z0);
        const Vec3 c = camera.toCamera(corner);
        if (c.z() < 0.02)
            return full; // straddles the camera plane: test every pixel
        const PointF q = camera.projectCamera(c);
        u0 = std::min(u0, q.x);
        u1 = std::max(u1, q.x);
        v0 = std::min(v0, q.y);
        v1 = std::max(v1, q.y);
    }
    ScreenRect r;
    r.left = int(std::max(0.0, std::floor(u0) - 1));
    r.right = int(std::min(double(camera.width() - 1), std::ceil(u1) + 1));
    r.top = int(std::max(0.0, std::floor(v0) - 1));
    r.bottom = int(std::min(double(camera.height() - 1), std::ceil(v1) + 1));
    return r;
}

/// What a ray from the camera needs to know of a primitive's bounding sphere: how near the
/// primitive can be (the nearest-first order), and, to see that the ray misses it, the centre
/// from the camera and the squared radius with a margin for rounding.
struct RayBound
{
    Vec3 offset; ///< centre - origin
    double reach2 = 0;
    double offset2 = 0; ///< |offset|²
    double nearest = 0; ///< a lower bound on the distance from the camera to any of its points
};

RayBound rayBound(const Primitive& p, const Vec3& origin)
{
    Vec3 centre = p.centre;
    double radius = p.radius;
    if (p.shape != Primitive::Shape::Sphere) {
        const double half_z = (p.z1 - p.z0) / 2;
        centre.z() = p.z0 + half_z;
        const double half_xy =
            p.shape == Primitive::Shape::Box ? std::hypot(p.half_x, p.half_y) : p.radius;
        radius = std::hypot(half_xy, half_z);
    }
    RayBound r;
    r.offset = centre - origin;
    r.offset2 = r.offset.squaredNorm();
    r.nearest = std::max(0.0, std::sqrt(r.offset2) - radius);
    const double reach = radius * (1 + 1e-9) + 1e-9;
    r.reach2 = reach * reach;
    return r;
}

/// Whether the ray from the camera along unit `d` passes outside the bounding sphere: then it
/// cannot hit the primitive, and the exact intersection need not be tried (a render's most
/// frequent outcome, and most of its time).
bool missesBound(const RayBound& r, const Vec3& d)
{
    if (r.offset2 <= r.reach2)
        return false; // the camera is inside the sphere
    const double along = r.offset.dot(d);
    return along < 0 || r.offset2 - along * along > r.reach2;
}

/// A straight painted band: field lines and the arms of the marks, with precomputed frame.
struct Feature
{
    Eigen::Vector2d a;
    Eigen::Vector2d direction; ///< unit, from a along the band
    Eigen::Vector2d normal;    ///< unit, across the band
    double length = 0;         ///< m; the paint reaches half a line width past both ends
};

std::vector<Feature> makeFeatures()
{
    std::vector<Feature> features;
    auto add = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        Feature f;
        f.a = a;
        f.length = (b - a).norm();
        f.direction = (b - a) / f.length;
        f.normal = Eigen::Vector2d(-f.direction.y(), f.direction.x());
        features.push_back(f);
    };
    for (const LineSegment& s : straightFieldLines())
        add(s.a, s.b);
    // Penalty marks and the centre mark: crosses of 10 cm, arms one line wide.
    constexpr double arm = 0.05 - FieldGeometry::kLineWidth / 2;
    const double mark_x = FieldGeometry::kLength / 2 - FieldGeometry::kPenaltyMark;
    for (const double mx : {-mark_x, 0.0, mark_x}) {
        add(Eigen::Vector2d(mx - arm, 0), Eigen::Vector2d(mx + arm, 0));
        add(Eigen::Vector2d(mx, -arm), Eigen::Vector2d(mx, arm));
    }
    return features;
}

const std::vector<Feature>& paintedFeatures()
{
    static const std::vector<Feature> features = makeFeatures();
    return features;
}

double carpetTexture(double x, double y, std::uint64_t seed)
{
    const double grain = latticeNoise(std::int64_t(std::floor(x / 0.006)),
                                      std::int64_t(std::floor(y / 0.006)), seed);
    const double patch = valueNoise(x / 0.45, y / 0.45, seed + 1);
    return 1.0 + 0.04 * (grain - 0.5) + 0.08 * (patch - 0.5);
}

/// Soft contact shadows of the objects standing on the field.
double shadowFactor(const Scene& scene, double x, double y)
{
    double f = 1.0;
    for (const SceneObject& o : scene.objects) {
        if (o.kind == ObjectKind::Post)
            continue;
        const double r = o.kind == ObjectKind::Ball ? o.radius * 1.1 : o.radius * 1.4;
        const double dx = x - o.position.x();
        const double dy = y - o.position.y();
        const double d2 = (dx * dx + dy * dy) / (r * r);
        if (d2 < 9)
            f *= 1.0 - (o.kind == ObjectKind::Ball ? 0.45 : 0.3) * std::exp(-d2);
    }
    return f;
}

struct Sample
{
    Rgbf colour;
    Colour label = Colour::Unclassified;
    int primitive = -1;
    bool partial = false; ///< a blend of classes (a line thinner than the footprint)
};

Rgbf wallColour(const Surroundings& s, int wall, double u, double z)
{
    Rgbf c = s.wall;
    if (s.skirting && z < 0.12)
        c *= 0.7;
    for (const WallPatch& p : s.patches) {
        if (p.wall == wall && u >= p.u0 && u <= p.u1 && z >= p.z0 && z <= p.z1) {
            c = p.colour;
            if (p.stripes) {
                const double v = (z - p.z0) / (p.z1 - p.z0);
                const double w = (u - p.u0) / std::max(0.01, p.u1 - p.u0);
                if (v > 0.3 && v < 0.7 && std::fmod(w * 9.0, 1.0) < 0.6)
                    c *= 0.55;
            }
        }
    }
    // Walls are lit from above: a little darker towards the floor.
    return c * (0.85 + 0.15 * std::min(1.0, z / 2.5));
}

/// How far a ground hit moves per supersample step in image x and y (field metres).
struct GroundSteps
{
    Vec3 right;   ///< the camera's x axis in the world, over f_x, times the step (px)
    Vec3 down;    ///< the camera's y axis in the world, over f_y, times the step (px)
    Vec3 forward; ///< the camera's optical axis in the world
};

/// Where a ray meets the surroundings: how far, and which surface.
struct EnvironmentHit
{
    double t = std::numeric_limits<double>::infinity();
    int surface = -1; ///< 0..3 walls, 4 floor, 5 ceiling
};

EnvironmentHit environmentHit(const Surroundings& s, const Vec3& o, const Vec3& d)
{
    EnvironmentHit hit;
    auto consider = [&](double tc, int id) {
        if (tc > 0 && tc < hit.t) {
            hit.t = tc;
            hit.surface = id;
        }
    };
    if (d.x() > 1e-12)
        consider((s.half_x - o.x()) / d.x(), 0);
    if (d.x() < -1e-12)
        consider((-s.half_x - o.x()) / d.x(), 1);
    if (d.y() > 1e-12)
        consider((s.half_y - o.y()) / d.y(), 2);
    if (d.y() < -1e-12)
        consider((-s.half_y - o.y()) / d.y(), 3);
    if (d.z() < -1e-12)
        consider(-o.z() / d.z(), 4);
    if (d.z() > 1e-12)
        consider((s.ceiling - o.z()) / d.z(), 5);
    return hit;
}

/// The surroundings' colour and class where the ray meets them (`hit`, of environmentHit):
/// carpet, floor, walls or ceiling.
Sample environment(const Scene& scene, const Vec3& o, const Vec3& d, const GroundSteps& steps,
                   const EnvironmentHit& hit)
{
    const Surroundings& s = scene.surroundings;
    const double t = hit.t;
    const int surface = hit.surface;
    const Vec3 p = o + t * d;
    Sample out;
    if (surface == 4) {
        const double light =
            scene.lighting.fieldFactor(p.x(), p.y()) * shadowFactor(scene, p.x(), p.y());
        if (std::abs(p.x()) <= FieldGeometry::kCarpetHalfLength &&
            std::abs(p.y()) <= FieldGeometry::kCarpetHalfWidth) {
            const double tex = carpetTexture(p.x(), p.y(), scene.texture_seed);
            // The ray r = d / (d . forward) has unit depth; its ground hit is o - o.z r / r.z, so
            // moving the image point moves the hit by -o.z (r' r.z - r r'.z) / r.z^2.
            const Vec3 r = d / d.dot(steps.forward);
            auto move = [&](const Vec3& dr) {
                const Vec3 dp = -o.z() * (dr * r.z() - r * dr.z()) / (r.z() * r.z());
                return Eigen::Vector2d(dp.x(), dp.y());
            };
            const double paint = lineCoverage(p.x(), p.y(), move(steps.right), move(steps.down));
            const Rgbf green = scene.carpet * tex * light;
            const Rgbf white = scene.line * (0.97 + 0.3 * (tex - 1.0)) * light;
            out.colour = green + paint * (white - green);
            out.label = paint >= 0.5 ? Colour::White : Colour::Green;
            out.partial = paint > 0.02 && paint < 0.98;
        } else {
            const double tex =
                0.95 + 0.1 * valueNoise(p.x() / 0.8, p.y() / 0.8, scene.texture_seed + 7);
            out.colour = s.floor * tex * light;
        }
        return out;
    }
    const double level = scene.lighting.level;
    if (surface == 5) {
        out.colour = s.ceiling_colour * level;
        return out;
    }
    const double u = surface < 2 ? p.y() : p.x();
    out.colour = wallColour(s, surface, u, p.z()) * level;
    return out;
}

Rgbf shadePrimitive(const Scene& scene, const Primitive& p, const Vec3& point, const Vec3& normal,
                    const Vec3& d)
{
    static const Vec3 kLight = Vec3(-0.3, 0.25, 1.0).normalized();
    const double diffuse = std::max(0.0, normal.dot(kLight));
    const double fill = std::max(0.0, -normal.dot(d));
    const double shade = p.ambient + (1.0 - p.ambient) * (0.8 * diffuse + 0.3 * fill);
    const double light =
        p.field_lit ? scene.lighting.fieldFactor(point.x(), point.y()) : scene.lighting.level;
    Rgbf c = p.albedo * shade * light;
    if (p.specular > 0) {
        const Vec3 h = (kLight - d).normalized();
        const double s = p.specular * std::pow(std::max(0.0, normal.dot(h)), 24.0) * light;
        c += s * (Rgbf(255, 235, 210) - c);
    }
    return c;
}

/// Separable Gaussian with mirrored borders, in plain C++ so the bytes do not depend on which
/// SIMD path a library picks on this CPU.
cv::Mat gaussianBlur(const cv::Mat& src, double sigma)
{
    const int radius = std::max(1, int(std::ceil(3 * sigma)));
    std::vector<double> kernel(std::size_t(2 * radius + 1));
    double total = 0;
    for (int i = -radius; i <= radius; ++i) {
        kernel[std::size_t(i + radius)] = std::exp(-0.5 * i * i / (sigma * sigma));
        total += kernel[std::size_t(i + radius)];
    }
    for (double& k : kernel)
        k /= total;
    auto mirror = [](int i, int n) {
        if (i < 0)
            i = -i - 1;
        if (i >= n)
            i = 2 * n - i - 1;
        return std::clamp(i, 0, n - 1);
    };
    const int w = src.cols;
    const int h = src.rows;
    cv::Mat tmp(h, w, CV_32FC3);
    cv::Mat dst(h, w, CV_32FC3);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            double acc[3] = {0, 0, 0};
            for (int i = -radius; i <= radius; ++i) {
                const cv::Vec3f& p = src.at<cv::Vec3f>(y, mirror(x + i, w));
                const double k = kernel[std::size_t(i + radius)];
                for (int c = 0; c < 3; ++c)
                    acc[c] += k * p[c];
            }
            tmp.at<cv::Vec3f>(y, x) = cv::Vec3f(float(acc[0]), float(acc[1]), float(acc[2]));
        }
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            double acc[3] = {0, 0, 0};
            for (int i = -radius; i <= radius; ++i) {
                const cv::Vec3f& p = tmp.at<cv::Vec3f>(mirror(y + i, h), x);
                const double k = kernel[std::size_t(i + radius)];
                for (int c = 0; c < 3; ++c)
                    acc[c] += k * p[c];
            }
            dst.at<cv::Vec3f>(y, x) = cv::Vec3f(float(acc[0]), float(acc[1]), float(acc[2]));
        }
    }
    return dst;
}

} // namespace

double lineCoverage(double x, double y, const Eigen::Vector2d& step_x,
                    const Eigen::Vector2d& step_y)
{
    constexpr double hw = FieldGeometry::kLineWidth / 2;
    if (std::abs(x) > FieldGeometry::kLength / 2 + 0.5 ||
        std::abs(y) > FieldGeometry::kWidth / 2 + 0.5)
        return 0;
    // A band of half width hw around a centre line, seen through a footprint whose extent across
    // the band is e: the overlap of [s - e/2, s + e/2] with [-hw, hw], as a share of e.
    auto band = [&](double s, const Eigen::Vector2d& normal) {
        const double e = std::abs(normal.dot(step_x)) + std::abs(normal.dot(step_y));
        if (e < 1e-9)
            return std::abs(s) <= hw ? 1.0 : 0.0;
        const double lo = std::max(s - e / 2, -hw);
        const double hi = std::min(s + e / 2, hw);
        return std::clamp((hi - lo) / e, 0.0, 1.0);
    };
    // No band reaches a point further across it than hw plus half the footprint's extent (at
    // most half the steps' lengths): most of the carpet is, and skips the band's arithmetic.
    const double reach = hw + 0.5 * (step_x.norm() + step_y.norm()) + 1e-9;
    double coverage = 0;
    for (const Feature& f : paintedFeatures()) {
        // In plain doubles: an Eigen vector here went through the stack on every feature (a
        // stalled load that took half of a frame's rendering in -O1 builds).
        const double ax = x - f.a.x();
        const double ay = y - f.a.y();
        const double across = ax * f.normal.x() + ay * f.normal.y();
        if (std::abs(across) > reach)
            continue;
        const double along = ax * f.direction.x() + ay * f.direction.y();
        if (along < -hw || along > f.length + hw)
            continue;
        coverage = std::max(coverage, band(across, f.normal));
        if (coverage >= 1)
            return 1;
    }
    const double r = std::hypot(x, y);
    if (r > 1e-9)
        coverage = std::max(coverage,
                            band(r - FieldGeometry::kCircleRadius, Eigen::Vector2d(x / r, y / r)));
    return coverage;
}

bool onFieldLine(double x, double y)
{
    return lineCoverage(x, y, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()) >= 0.5;
}

RenderedFrame renderScene(const Scene& scene, const CameraModel& camera,
                          const CameraEffects& effects, std::uint64_t noise_seed)
{
    const int w = camera.width();
    const int h = camera.height();
    const Vec3 origin = camera.pose().position;

    // Which primitives can cover each row, nearest first, so a pixel only tests plausible ones
    // and stops at the first whose bounding sphere lies beyond the nearest hit so far.
    std::vector<ScreenRect> rects(scene.primitives.size());
    std::vector<RayBound> bounds(scene.primitives.size());
    std::vector<int> order;
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        rects[i] = screenRect(scene.primitives[i], camera);
        bounds[i] = rayBound(scene.primitives[i], origin);
        if (rects[i].left <= rects[i].right)
            order.push_back(int(i));
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return bounds[std::size_t(a)].nearest < bounds[std::size_t(b)].nearest;
    });
    std::vector<std::vector<int>> rows;
    rows.resize(std::size_t(h));
    for (const int i : order)
        for (int y = rects[std::size_t(i)].top; y <= rects[std::size_t(i)].bottom; ++y)
            rows[std::size_t(y)].push_back(i);

    cv::Mat image(h, w, CV_32FC3);
    RenderedFrame out;
    out.labels.create(h, w, CV_8U);
    out.primitive.create(h, w, CV_32S);
    constexpr std::array<double, 3> kOffsets = {-1.0 / 3, 0.0, 1.0 / 3};
    const GroundSteps steps{camera.directionToWorld(Vec3(1, 0, 0)) / (3 * camera.fx()),
                            camera.directionToWorld(Vec3(0, 1, 0)) / (3 * camera.fy()),
                            camera.directionToWorld(Vec3(0, 0, 1))};
    std::vector<int> column;
    for (int y = 0; y < h; ++y) {
        const std::vector<int>& row = rows[std::size_t(y)];
        for (int x = 0; x < w; ++x) {
            // The row's primitives whose rectangle holds this column, in the row's order, once
            // for the nine samples.
            column.clear();
            for (const int i : row) {
                const ScreenRect& r = rects[std::size_t(i)];
                if (x >= r.left && x <= r.right)
                    column.push_back(i);
            }
            Rgbf sum(0, 0, 0);
            int first_label = -1;
            bool mixed = false;
            int centre_primitive = -1;
            for (int sy = 0; sy < 3; ++sy) {
                for (int sx = 0; sx < 3; ++sx) {
                    const Vec3 d = camera.rayDirection(x + kOffsets[std::size_t(sx)],
                                                       y + kOffsets[std::size_t(sy)]);
                    // The surroundings are shaded only where no primitive stands in front.
                    const EnvironmentHit env = environmentHit(scene.surroundings, origin, d);
                    Sample s;
                    double best = env.t;
                    int best_index = -1;
                    Hit best_hit;
                    for (const int i : column) {
                        if (bounds[std::size_t(i)].nearest >= best)
                            break;
                        if (missesBound(bounds[std::size_t(i)], d))
                            continue;
                        const auto hit = intersect(scene.primitives[std::size_t(i)], origin, d);
                        if (hit && hit->t < best) {
                            best = hit->t;
                            best_index = i;
                            best_hit = *hit;
                        }
                    }
                    if (best_index >= 0) {
                        const Primitive& p = scene.primitives[std::size_t(best_index)];
                        s.colour = shadePrimitive(scene, p, origin + best * d, best_hit.normal, d);
                        s.label = p.label;
                        s.primitive = best_index;
                    } else {
                        s = environment(scene, origin, d, steps, env);
                    }
                    sum += s.colour;
                    if (first_label < 0)
                        first_label = int(s.label);
                    else if (first_label != int(s.label))
                        mixed = true;
                    mixed = mixed || s.partial;
                    if (sx == 1 && sy == 1)
                        centre_primitive = s.primitive;
                }
            }
            sum /= 9.0;
            image.at<cv::Vec3f>(y, x) = cv::Vec3f(float(sum.x()), float(sum.y()), float(sum.z()));
            out.labels.at<std::uint8_t>(y, x) = mixed ? kMixedLabel : std::uint8_t(first_label);
            out.primitive.at<std::int32_t>(y, x) = centre_primitive;
        }
    }

    if (effects.blur_sigma > 0)
        image = gaussianBlur(image, effects.blur_sigma);

    // Sensor: vignetting and white balance, noise in YCbCr, then 4:2:2 chroma as the camera's YUYV.
    Rng rng(noise_seed);
    cv::Mat ycc(h, w, CV_32FC3);
    const double r_max2 = double(w) * w / 4.0 + double(h) * h / 4.0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const cv::Vec3f c = image.at<cv::Vec3f>(y, x);
            const double dx = x - w / 2.0;
            const double dy = y - h / 2.0;
            const double v = 1.0 - effects.vignette * (dx * dx + dy * dy) / r_max2;
            const double r = c[0] * v * effects.gain.x();
            const double g = c[1] * v * effects.gain.y();
            const double b = c[2] * v * effects.gain.z();
            const double luma = 0.299 * r + 0.587 * g + 0.114 * b;
            const double cb = 128 + 0.564 * (b - luma);
            const double cr = 128 + 0.713 * (r - luma);
            // Drawn one by one, Cr first: as arguments of one call their order would be the
            // compiler's (scenario_cast.cpp says why it matters).
            const double n_cr = rng.normal();
            const double n_cb = rng.normal();
            const double n_y = rng.normal();
            ycc.at<cv::Vec3f>(y, x) =
                cv::Vec3f(float(luma + effects.noise_y * n_y), float(cb + effects.noise_c * n_cb),
                          float(cr + effects.noise_c * n_cr));
        }
    }
    if (effects.chroma_422) {
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x + 1 < w; x += 2) {
                cv::Vec3f& a = ycc.at<cv::Vec3f>(y, x);
                cv::Vec3f& b = ycc.at<cv::Vec3f>(y, x + 1);
                const float cb = 0.5f * (a[1] + b[1]);
                const float cr = 0.5f * (a[2] + b[2]);
                a[1] = b[1] = cb;
                a[2] = b[2] = cr;
            }
        }
    }
    out.bgr.create(h, w, CV_8UC3);
    auto to8 = [](double v) { return std::uint8_t(std::clamp(std::lround(v), 0L, 255L)); };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const cv::Vec3f c = ycc.at<cv::Vec3f>(y, x);
            const double r = c[0] + (c[2] - 128.0) / 0.713;
            const double b = c[0] + (c[1] - 128.0) / 0.564;
            const double g = (c[0] - 0.299 * r - 0.114 * b) / 0.587;
            out.bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(to8(b), to8(g), to8(r));
        }
    }
    out.ycbcr = bgrToYcbcr(out.bgr);
    return out;
}

} // namespace fieldsight::synth
