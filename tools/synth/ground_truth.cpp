// Exact ground truth for a rendered frame; the rules are in ground_truth.h.
#include "synth/ground_truth.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fieldsight::synth {

namespace {

using Vec3 = Eigen::Vector3d;

double round2(double v)
{
    return std::round(v * 100.0) / 100.0;
}

struct PixelBox
{
    int left = std::numeric_limits<int>::max();
    int right = std::numeric_limits<int>::min();
    int top = std::numeric_limits<int>::max();
    int bottom = std::numeric_limits<int>::min();
    long count = 0;
    void add(int x, int y)
    {
        left = std::min(left, x);
        right = std::max(right, x);
        top = std::min(top, y);
        bottom = std::max(bottom, y);
        ++count;
    }
    int width() const { return count ? right - left + 1 : 0; }
    int height() const { return count ? bottom - top + 1 : 0; }
};

/// Seen pixels per object: all parts, and the parts that decide visibility.
struct Seen
{
    std::vector<PixelBox> all;
    std::vector<long> visibility_parts;
};

Seen seenPixels(const Scene& scene, const cv::Mat& primitive)
{
    Seen seen;
    seen.all.resize(scene.objects.size());
    seen.visibility_parts.resize(scene.objects.size(), 0);
    for (int y = 0; y < primitive.rows; ++y) {
        for (int x = 0; x < primitive.cols; ++x) {
            const int i = primitive.at<std::int32_t>(y, x);
            if (i < 0)
                continue;
            const Primitive& p = scene.primitives[std::size_t(i)];
            if (p.object < 0)
                continue;
            seen.all[std::size_t(p.object)].add(x, y);
            if (p.counts_for_visibility)
                ++seen.visibility_parts[std::size_t(p.object)];
        }
    }
    return seen;
}

/// Pixels the object's visibility parts would cover with nothing in front and no image border,
/// counted over a window three images wide and high around the image.
long unoccludedPixels(const Scene& scene, int object, const CameraModel& camera)
{
    const int w = camera.width();
    const int h = camera.height();
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    bool straddles = false;
    std::vector<const Primitive*> parts;
    for (const Primitive& p : scene.primitives) {
        if (p.object != object || !p.counts_for_visibility)
            continue;
        parts.push_back(&p);
        const double ex =
            p.shape == Primitive::Shape::Box ? std::hypot(p.half_x, p.half_y) : p.radius;
        const double z0 = p.shape == Primitive::Shape::Sphere ? p.centre.z() - p.radius : p.z0;
        const double z1 = p.shape == Primitive::Shape::Sphere ? p.centre.z() + p.radius : p.z1;
        for (int i = 0; i < 8; ++i) {
            const Vec3 corner(p.centre.x() + ((i & 1) ? ex : -ex),
                              p.centre.y() + ((i & 2) ? ex : -ex), (i & 4) ? z1 : z0);
            const Vec3 c = camera.toCamera(corner);
            if (c.z() < 0.02) {
                straddles = true;
                continue;
            }
            const PointF q = camera.projectCamera(c);
            u0 = std::min(u0, q.x);
            u1 = std::max(u1, q.x);
            v0 = std::min(v0, q.y);
            v1 = std::max(v1, q.y);
        }
    }
    if (parts.empty())
        return 0;
    if (straddles) {
        u0 = v0 = -1e300;
        u1 = v1 = 1e300;
    }
    const int left = int(std::max(double(-w), std::floor(u0)));
    const int right = int(std::min(double(2 * w - 1), std::ceil(u1)));
    const int top = int(std::max(double(-h), std::floor(v0)));
    const int bottom = int(std::min(double(2 * h - 1), std::ceil(v1)));
    const Vec3 origin = camera.pose().position;
    long count = 0;
    for (int y = top; y <= bottom; ++y) {
        for (int x = left; x <= right; ++x) {
            const Vec3 d = camera.rayDirection(x, y);
            for (const Primitive* p : parts) {
                if (intersect(*p, origin, d)) {
                    ++count;
                    break;
                }
            }
        }
    }
    return count;
}

/// Liang-Barsky clip of a segment to [0, w-1] x [0, h-1]; false when nothing is left.
bool clipToImage(PointF& a, PointF& b, int w, int h)
{
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    double t0 = 0;
    double t1 = 1;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x, (w - 1) - a.x, a.y, (h - 1) - a.y};
    for (int i = 0; i < 4; ++i) {
        if (std::abs(p[i]) < 1e-12) {
            if (q[i] < 0)
                return false;
            continue;
        }
        const double r = q[i] / p[i];
        if (p[i] < 0)
            t0 = std::max(t0, r);
        else
            t1 = std::min(t1, r);
    }
    if (t0 > t1)
        return false;
    const PointF start{a.x + t0 * dx, a.y + t0 * dy};
    const PointF end{a.x + t1 * dx, a.y + t1 * dy};
    a = start;
    b = end;
    return true;
}

/// Douglas-Peucker on a per-column polyline, keeping both ends.
void simplify(const std::vector<PointF>& points, std::size_t first, std::size_t last,
              double tolerance, std::vector<bool>& keep)
{
    if (last <= first + 1)
        return;
    const PointF& a = points[first];
    const PointF& b = points[last];
    double worst = -1;
    std::size_t worst_index = first;
    for (std::size_t i = first + 1; i < last; ++i) {
        const double t = (points[i].x - a.x) / (b.x - a.x);
        const double d = std::abs(points[i].y - (a.y + t * (b.y - a.y)));
        if (d > worst) {
            worst = d;
            worst_index = i;
        }
    }
    if (worst > tolerance) {
        keep[worst_index] = true;
        simplify(points, first, worst_index, tolerance, keep);
        simplify(points, worst_index, last, tolerance, keep);
    }
}

/// Calls f(x, y) for every pixel centre inside a convex image polygon.
template <class F> void forEachPixelInside(const std::vector<PointF>& polygon, F&& f)
{
    double top = 1e300;
    double bottom = -1e300;
    for (const PointF& p : polygon) {
        top = std::min(top, p.y);
        bottom = std::max(bottom, p.y);
    }
    for (int y = int(std::ceil(top)); y <= int(std::floor(bottom)); ++y) {
        double left = 1e300;
        double right = -1e300;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const PointF& a = polygon[i];
            const PointF& b = polygon[(i + 1) % polygon.size()];
            if ((a.y <= y && b.y >= y) || (b.y <= y && a.y >= y)) {
                const double x =
                    std::abs(b.y - a.y) < 1e-12 ? a.x : a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                left = std::min(left, x);
                right = std::max(right, x);
            }
        }
        for (int x = int(std::ceil(left)); x <= int(std::floor(right)); ++x)
            f(x, y);
    }
}

} // namespace

std::optional<BallImage> ballImage(const CameraModel& camera, const Eigen::Vector3d& centre,
                                   double radius)
{
    BallImage image;
    image.outline = camera.sphereOutline(centre, radius);
    if (image.outline.size() < 3)
        return std::nullopt;
    // Shoelace area and centroid of the outline polygon.
    double area2 = 0;
    double cx = 0;
    double cy = 0;
    for (std::size_t i = 0; i < image.outline.size(); ++i) {
        const PointF& a = image.outline[i];
        const PointF& b = image.outline[(i + 1) % image.outline.size()];
        const double cross = a.x * b.y - b.x * a.y;
        area2 += cross;
        cx += (a.x + b.x) * cross;
        cy += (a.y + b.y) * cross;
    }
    image.centre = {cx / (3 * area2), cy / (3 * area2)};
    image.radius = std::sqrt(std::abs(area2) / 2 / 3.14159265358979323846);
    return image;
}

std::vector<double> fieldTopPerColumn(const CameraModel& camera)
{
    const int w = camera.width();
    const int h = camera.height();
    // The carpet rectangle in camera coordinates, clipped to the half-space in front of the camera.
    constexpr double kNear = 0.01;
    const double hx = FieldGeometry::kCarpetHalfLength;
    const double hy = FieldGeometry::kCarpetHalfWidth;
    const Vec3 corners[4] = {Vec3(-hx, -hy, 0), Vec3(hx, -hy, 0), Vec3(hx, hy, 0),
                             Vec3(-hx, hy, 0)};
    std::vector<Vec3> polygon;
    for (int i = 0; i < 4; ++i) {
        const Vec3 a = camera.toCamera(corners[i]);
        const Vec3 b = camera.toCamera(corners[(i + 1) % 4]);
        if (a.z() >= kNear)
            polygon.push_back(a);
        if ((a.z() >= kNear) != (b.z() >= kNear)) {
            const double t = (kNear - a.z()) / (b.z() - a.z());
            polygon.push_back(a + t * (b - a));
        }
    }
    std::vector<PointF> image;
    for (const Vec3& p : polygon)
        image.push_back(camera.projectCamera(p));

    std::vector<double> top(std::size_t(w), double(h - 1));
    if (image.size() < 3)
        return top;
    for (int x = 0; x < w; ++x) {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < image.size(); ++i) {
            const PointF& a = image[i];
            const PointF& b = image[(i + 1) % image.size()];
            const double lo = std::min(a.x, b.x);
            const double hi = std::max(a.x, b.x);
            if (x < lo || x > hi)
                continue;
            if (hi - lo < 1e-9) {
                best = std::min({best, a.y, b.y});
                continue;
            }
            best = std::min(best, a.y + (x - a.x) * (b.y - a.y) / (b.x - a.x));
        }
        if (std::isfinite(best))
            top[std::size_t(x)] = std::clamp(best, 0.0, double(h - 1));
    }
    return top;
}

/// m in front of the camera: a field line's part nearer than this is not listed or judged.
constexpr double kLineNear = 0.05;

double seenLineShare(const LineSegment& line, const CameraModel& camera, const cv::Mat& primitive)
{
    // Points every centimetre along the line's centre, each weighted by the image length to the
    // next one: the share is of the line's length in the image, not on the field.
    const Eigen::Vector2d along = line.b - line.a;
    const double length = along.norm();
    if (length <= 0)
        return 0.0;
    const Eigen::Vector2d normal = Eigen::Vector2d(-along.y(), along.x()) / length;
    const double half_width = FieldGeometry::kLineWidth / 2;
    const int steps = std::max(1, int(std::ceil(length / 0.01)));
    const auto imageOf = [&camera](const Eigen::Vector2d& p) -> std::optional<PointF> {
        const Vec3 c = camera.toCamera(Vec3(p.x(), p.y(), 0));
        if (c.z() < kLineNear)
            return std::nullopt;
        return camera.projectCamera(c);
    };
    double in_image = 0, seen = 0;
    std::optional<PointF> previous;
    for (int i = 0; i <= steps; ++i) {
        const Eigen::Vector2d p = line.a + along * (double(i) / steps);
        const std::optional<PointF> at = imageOf(p);
        const std::optional<PointF> left = imageOf(p + half_width * normal);
        const std::optional<PointF> right = imageOf(p - half_width * normal);
        if (!at || !left || !right) {
            previous.reset();
            continue;
        }
        const int x = int(std::lround(at->x)), y = int(std::lround(at->y));
        const bool inside = x >= 0 && y >= 0 && x < primitive.cols && y < primitive.rows;
        if (previous && inside) {
            const double dx = at->x - previous->x, dy = at->y - previous->y;
            const double step = std::hypot(dx, dy);
            in_image += step;
            // The line's width across itself in the image: its edges' distance, less what runs
            // along the line.
            const double wx = left->x - right->x, wy = left->y - right->y;
            const double width = step > 0 ? std::abs(wx * dy - wy * dx) / step : 0.0;
            if (width >= kMinLineWidth && primitive.at<std::int32_t>(y, x) < 0)
                seen += step;
        }
        previous = at;
    }
    return in_image > 0 ? seen / in_image : 0.0;
}

std::vector<ProjectedLine> projectedFieldLines(const CameraModel& camera)
{
    std::vector<ProjectedLine> out;
    for (const LineSegment& s : straightFieldLines()) {
        Vec3 a = camera.toCamera(Vec3(s.a.x(), s.a.y(), 0));
        Vec3 b = camera.toCamera(Vec3(s.b.x(), s.b.y(), 0));
        if (a.z() < kLineNear && b.z() < kLineNear)
            continue;
        if (a.z() < kLineNear)
            a = a + (kLineNear - a.z()) / (b.z() - a.z()) * (b - a);
        else if (b.z() < kLineNear)
            b = b + (kLineNear - b.z()) / (a.z() - b.z()) * (a - b);
        PointF pa = camera.projectCamera(a);
        PointF pb = camera.projectCamera(b);
        if (!clipToImage(pa, pb, camera.width(), camera.height()))
            continue;
        if (std::hypot(pb.x - pa.x, pb.y - pa.y) < 3.0)
            continue;
        out.push_back({{round2(pa.x), round2(pa.y), round2(pb.x), round2(pb.y)}, &s});
    }
    return out;
}

namespace {

/// A ball or robot with less than this share of itself seen is not listed at all.
constexpr double kConcealedShare = 0.1;
/// A field line with less than this share of its image length seen is listed as concealed.
constexpr double kSeenLineShare = 0.5;

/// Whether post `object` stands with its foot in the image but hidden behind something nearer
/// (a robot close to the camera): the post's box then ends at the occluder, not at its base. The
/// foot is seen when a pixel of the post's columns (`box`) shows the post within 2 px above it.
bool footHidden(const Scene& scene, int object, const PixelBox& box, const CameraModel& camera,
                const cv::Mat& primitive)
{
    const SceneObject& post = scene.objects[std::size_t(object)];
    const auto foot = camera.project(post.position);
    if (!foot)
        return false;
    const int y = int(std::lround(foot->y));
    if (foot->x < 0 || y < 0 || foot->x > primitive.cols - 1 || y >= primitive.rows)
        return false; // cut by the frame: the box's bottom at the border says so
    for (int row = std::max(0, y - 2); row <= y; ++row)
        for (int x = std::max(0, box.left); x <= std::min(primitive.cols - 1, box.right); ++x) {
            const int i = primitive.at<std::int32_t>(row, x);
            if (i >= 0 && scene.primitives[std::size_t(i)].object == object)
                return false;
        }
    return true;
}

/// `objects` (each with whether it is concealed) sorted left to right into `out`, their flags
/// set in `annotation` under `truth_key`.
template <class Object>
void sortedInto(std::vector<std::pair<Object, bool>>& objects, std::vector<Object>& out,
                FrameAnnotation& annotation, std::string_view truth_key)
{
    std::stable_sort(objects.begin(), objects.end(),
                     [](const auto& a, const auto& b) { return a.first.left < b.first.left; });
    for (const auto& [object, concealed] : objects) {
        if (concealed)
            annotation.setFlags(truth_key, out.size(), {.concealed = true});
        out.push_back(object);
    }
}

} // namespace

FrameAnnotation groundTruth(const Scene& scene, const CameraModel& camera, const cv::Mat& primitive)
{
    const int w = camera.width();
    const int h = camera.height();
    FrameAnnotation annotation;
    annotation.done = true;
    std::vector<Ball>& balls = annotation.truth.output<Ball>();
    std::vector<Goalpost>& goalposts = annotation.truth.output<Goalpost>();
    std::vector<Obstacle>& obstacles = annotation.truth.output<Obstacle>();
    const Seen seen = seenPixels(scene, primitive);
    std::vector<bool> ball_concealed;
    std::vector<std::pair<Goalpost, bool>> posts; // and whether concealed
    std::vector<std::pair<Obstacle, bool>> robots;

    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const SceneObject& object = scene.objects[o];
        const PixelBox& box = seen.all[o];
        switch (object.kind) {
        case ObjectKind::Ball: {
            const auto image = ballImage(camera, object.position, object.radius);
            if (!image || image->radius < 3.0)
                break;
            const bool centre_in_image = image->centre.x >= 0 && image->centre.x <= w - 1 &&
                                         image->centre.y >= 0 && image->centre.y <= h - 1;
            long disc = 0;
            long visible = 0;
            forEachPixelInside(image->outline, [&](int x, int y) {
                ++disc;
                if (x < 0 || y < 0 || x >= w || y >= h)
                    return;
                const int i = primitive.at<std::int32_t>(y, x);
                if (i >= 0 && scene.primitives[std::size_t(i)].object == int(o))
                    ++visible;
            });
            // In view but mostly hidden or cut by the frame: listed as concealed, so that a
            // detector finding what is seen of it scores neither a hit nor a false ball.
            if (disc > 0 && visible > 0 && double(visible) >= kConcealedShare * double(disc)) {
                balls.push_back(
                    {round2(image->centre.x), round2(image->centre.y), round2(image->radius)});
                ball_concealed.push_back(!centre_in_image || double(visible) < 0.6 * double(disc));
            }
            break;
        }
        case ObjectKind::Post:
            if (box.count > 0) {
                Goalpost post;
                post.left = box.left;
                post.right = box.right;
                post.top = box.top;
                post.bottom = box.bottom;
                post.base_x = (box.left + box.right) / 2.0;
                post.base_y = box.bottom;
                posts.push_back({post, box.height() < 8 || box.width() < 2 ||
                                           footHidden(scene, int(o), box, camera, primitive)});
            }
            break;
        case ObjectKind::Robot:
        case ObjectKind::Person: {
            if (box.width() < 6 || seen.visibility_parts[o] == 0)
                break;
            // At least half of it in view, or (close to the camera, cut by the frame) filling
            // a quarter of the frame: an obstacle either way. Less of it seen: concealed.
            const long full = unoccludedPixels(scene, int(o), camera);
            const long seen_px = seen.visibility_parts[o];
            const bool plain = (full > 0 && double(seen_px) >= 0.5 * double(full)) ||
                               4 * seen_px >= long(w) * long(h);
            if (plain || double(seen_px) >= kConcealedShare * double(full))
                robots.push_back({{box.left, box.right, box.top, box.bottom}, !plain});
            break;
        }
        default:
            break;
        }
    }
    for (std::size_t i = 0; i < ball_concealed.size(); ++i)
        if (ball_concealed[i])
            annotation.setFlags(PerceptTraits<Ball>::truth_key, i, {.concealed = true});
    sortedInto(posts, goalposts, annotation, PerceptTraits<Goalpost>::truth_key);
    sortedInto(robots, obstacles, annotation, PerceptTraits<Obstacle>::truth_key);

    const std::vector<double> top = fieldTopPerColumn(camera);
    std::vector<PointF> column_points;
    for (int x = 0; x < w; ++x)
        column_points.push_back({double(x), top[std::size_t(x)]});
    std::vector<bool> keep(column_points.size(), false);
    keep.front() = keep.back() = true;
    simplify(column_points, 0, column_points.size() - 1, 0.25, keep);
    FieldBoundary boundary;
    for (std::size_t i = 0; i < column_points.size(); ++i)
        if (keep[i])
            boundary.points.push_back({column_points[i].x, round2(column_points[i].y)});
    annotation.truth.output<FieldBoundary>().push_back(std::move(boundary));

    std::vector<FieldLine>& lines = annotation.truth.output<FieldLine>();
    for (const ProjectedLine& projected : projectedFieldLines(camera)) {
        if (seenLineShare(*projected.source, camera, primitive) < kSeenLineShare)
            annotation.setFlags(PerceptTraits<FieldLine>::truth_key, lines.size(),
                                {.concealed = true});
        lines.push_back(projected.line);
    }
    return annotation;
}

} // namespace fieldsight::synth
