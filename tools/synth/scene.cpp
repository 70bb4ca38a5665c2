// The generator's world: field lines, lighting, ray-primitive intersection and object builders.
#include "synth/scene.h"

#include "synth/synth_random.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fieldsight::synth {

namespace {

constexpr double kEpsilon = 1e-9;

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

std::vector<LineSegment> makeStraightLines()
{
    using F = FieldGeometry;
    const double hx = F::kLength / 2;
    const double hy = F::kWidth / 2;
    const double ax = hx - F::kGoalAreaDepth;
    const double ay = F::kGoalAreaWidth / 2;
    std::vector<LineSegment> lines = {
        {{-hx, hy}, {hx, hy}}, {{-hx, -hy}, {hx, -hy}}, // touch lines
        {{hx, -hy}, {hx, hy}}, {{-hx, -hy}, {-hx, hy}}, // goal lines
        {{0, -hy}, {0, hy}},                            // halfway line
    };
    for (const double s : {1.0, -1.0}) {
        lines.push_back({{s * ax, -ay}, {s * ax, ay}});
        lines.push_back({{s * hx, ay}, {s * ax, ay}});
        lines.push_back({{s * hx, -ay}, {s * ax, -ay}});
    }
    return lines;
}

Primitive makeCylinder(const Vec2& centre, double radius, double z0, double z1, const Rgbf& albedo,
                       Colour label)
{
    Primitive p;
    p.shape = Primitive::Shape::Cylinder;
    p.centre = Vec3(centre.x(), centre.y(), 0);
    p.radius = radius;
    p.z0 = z0;
    p.z1 = z1;
    p.albedo = albedo;
    p.label = label;
    return p;
}

Primitive makeSphere(const Vec3& centre, double radius, const Rgbf& albedo, Colour label)
{
    Primitive p;
    p.shape = Primitive::Shape::Sphere;
    p.centre = centre;
    p.radius = radius;
    p.albedo = albedo;
    p.label = label;
    return p;
}

std::optional<Hit> intersectSphere(const Primitive& p, const Vec3& o, const Vec3& d)
{
    const Vec3 oc = o - p.centre;
    const double b = oc.dot(d);
    const double c = oc.squaredNorm() - p.radius * p.radius;
    const double disc = b * b - c;
    if (disc < 0)
        return std::nullopt;
    const double s = std::sqrt(disc);
    double t = -b - s;
    if (t <= kEpsilon)
        t = -b + s;
    if (t <= kEpsilon)
        return std::nullopt;
    return Hit{t, (o + t * d - p.centre) / p.radius};
}

std::optional<Hit> intersectCylinder(const Primitive& p, const Vec3& o, const Vec3& d)
{
    const double px = o.x() - p.centre.x();
    const double py = o.y() - p.centre.y();
    const double r2 = p.radius * p.radius;
    std::optional<Hit> best;
    auto consider = [&](double t, const Vec3& n) {
        if (t > kEpsilon && (!best || t < best->t))
            best = Hit{t, n};
    };
    const double a = d.x() * d.x() + d.y() * d.y();
    if (a > 1e-14) {
        const double b = px * d.x() + py * d.y();
        const double c = px * px + py * py - r2;
        const double disc = b * b - a * c;
        if (disc >= 0) {
            const double s = std::sqrt(disc);
            for (const double t : {(-b - s) / a, (-b + s) / a}) {
                const double z = o.z() + t * d.z();
                if (z >= p.z0 && z <= p.z1) {
                    consider(t, Vec3(px + t * d.x(), py + t * d.y(), 0) / p.radius);
                    break;
                }
            }
        }
    }
    if (std::abs(d.z()) > 1e-14) {
        for (const double zc : {p.z0, p.z1}) {
            const double t = (zc - o.z()) / d.z();
            const double x = px + t * d.x();
            const double y = py + t * d.y();
            if (x * x + y * y <= r2)
                consider(t, Vec3(0, 0, zc == p.z1 ? 1 : -1));
        }
    }
    return best;
}

std::optional<Hit> intersectBox(const Primitive& p, const Vec3& o, const Vec3& d)
{
    const double c = p.cos_yaw;
    const double s = p.sin_yaw;
    const double px = o.x() - p.centre.x();
    const double py = o.y() - p.centre.y();
    const Vec3 lo(c * px + s * py, -s * px + c * py, o.z());
    const Vec3 ld(c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z());
    const double lower[3] = {-p.half_x, -p.half_y, p.z0};
    const double upper[3] = {p.half_x, p.half_y, p.z1};
    double t_near = -1e300;
    double t_far = 1e300;
    int axis = 0;
    double sign = 1;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(ld(i)) < 1e-14) {
            if (lo(i) < lower[i] || lo(i) > upper[i])
                return std::nullopt;
            continue;
        }
        double t0 = (lower[i] - lo(i)) / ld(i);
        double t1 = (upper[i] - lo(i)) / ld(i);
        double face_sign = -1;
        if (t0 > t1) {
            std::swap(t0, t1);
            face_sign = 1;
        }
        if (t0 > t_near) {
            t_near = t0;
            axis = i;
            sign = face_sign;
        }
        t_far = std::min(t_far, t1);
    }
    if (t_near > t_far || t_near <= kEpsilon)
        return std::nullopt;
    Vec3 local_normal(0, 0, 0);
    local_normal(axis) = sign;
    const Vec3 normal(c * local_normal.x() - s * local_normal.y(),
                      s * local_normal.x() + c * local_normal.y(), local_normal.z());
    return Hit{t_near, normal};
}

} // namespace

Primitive makeBox(const Vec2& centre, double heading, double half_x, double half_y, double z0,
                  double z1, const Rgbf& albedo, Colour label)
{
    Primitive p;
    p.shape = Primitive::Shape::Box;
    p.centre = Vec3(centre.x(), centre.y(), 0);
    p.setYaw(heading);
    p.half_x = half_x;
    p.half_y = half_y;
    p.z0 = z0;
    p.z1 = z1;
    p.albedo = albedo;
    p.label = label;
    return p;
}

const std::vector<LineSegment>& straightFieldLines()
{
    static const std::vector<LineSegment> lines = makeStraightLines();
    return lines;
}

double Lighting::fieldFactor(double x, double y) const
{
    double f = level * std::max(0.25, 1.0 + gradient_x * x);
    if (spot_strength > 0)
        f *= 1.0 +
             spot_strength * (2.0 * valueNoise(x / 1.7 + 11.3, y / 1.7 + 5.1, spot_seed) - 1.0);
    return f;
}

std::optional<Hit> intersect(const Primitive& p, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& direction)
{
    switch (p.shape) {
    case Primitive::Shape::Sphere:
        return intersectSphere(p, origin, direction);
    case Primitive::Shape::Cylinder:
        return intersectCylinder(p, origin, direction);
    case Primitive::Shape::Box:
        return intersectBox(p, origin, direction);
    }
    return std::nullopt;
}

int addBall(Scene& scene, const Eigen::Vector3d& centre)
{
    const int object = int(scene.objects.size());
    scene.objects.push_back(
        {ObjectKind::Ball, centre, FieldGeometry::kBallDiameter / 2, FieldGeometry::kBallDiameter});
    Primitive ball =
        makeSphere(centre, FieldGeometry::kBallDiameter / 2, Rgbf(252, 100, 12), Colour::Orange);
    ball.kind = ObjectKind::Ball;
    ball.object = object;
    ball.ambient = 0.5;
    ball.specular = 0.22;
    scene.primitives.push_back(ball);
    return object;
}

void addGoal(Scene& scene, double goal_line_x)
{
    using F = FieldGeometry;
    const Rgbf yellow(238, 210, 28);
    const double post_y = F::kGoalWidth / 2 + F::kPostDiameter / 2;
    for (const double side : {1.0, -1.0}) {
        const int object = int(scene.objects.size());
        const Vec3 base(goal_line_x, side * post_y, 0);
        scene.objects.push_back({ObjectKind::Post, base, F::kPostDiameter / 2, F::kPostHeight});
        Primitive post = makeCylinder(base.head<2>(), F::kPostDiameter / 2, 0, F::kPostHeight,
                                      yellow, Colour::Yellow);
        post.kind = ObjectKind::Post;
        post.object = object;
        post.ambient = 0.72;
        scene.primitives.push_back(post);
    }
    Primitive bar =
        makeBox(Vec2(goal_line_x, 0), 0, F::kPostDiameter / 2, post_y - 0.02,
                F::kPostHeight - F::kPostDiameter, F::kPostHeight, yellow, Colour::Yellow);
    bar.kind = ObjectKind::Crossbar;
    bar.ambient = 0.72;
    scene.primitives.push_back(bar);
    // The goal's frame behind the posts: dark grey supports the vision should not care about.
    const double back = goal_line_x + (goal_line_x > 0 ? 0.4 : -0.4);
    const Rgbf frame(92, 88, 100);
    for (const double side : {1.0, -1.0}) {
        Primitive support = makeBox(Vec2((goal_line_x + back) / 2, side * post_y), 0, 0.2, 0.015,
                                    0.0, 0.03, frame, Colour::Unclassified);
        support.ambient = 0.7;
        scene.primitives.push_back(support);
        Primitive upright = makeCylinder(Vec2(back, side * post_y), 0.015, 0, F::kPostHeight, frame,
                                         Colour::Unclassified);
        upright.ambient = 0.7;
        scene.primitives.push_back(upright);
    }
}

int addRobot(Scene& scene, const Eigen::Vector2d& position, double heading, const RobotLook& look)
{
    const int object = int(scene.objects.size());
    scene.objects.push_back({ObjectKind::Robot, Vec3(position.x(), position.y(), 0), 0.12, 0.45});
    const double c = std::cos(heading);
    const double s = std::sin(heading);
    auto at = [&](double lx, double ly) {
        return Vec2(position.x() + c * lx - s * ly, position.y() + s * lx + c * ly);
    };
    auto box = [&](double lx, double ly, double hx, double hy, double z0, double z1,
                   const Rgbf& albedo, Colour label) {
        Primitive p = makeBox(at(lx, ly), heading, hx, hy, z0, z1, albedo, label);
        p.kind = ObjectKind::Robot;
        p.object = object;
        p.ambient = 0.6;
        scene.primitives.push_back(p);
    };
    const Colour dark = Colour::ShadowObject;
    for (const double side : {1.0, -1.0}) {
        box(0.015, side * 0.045, 0.055, 0.03, 0, 0.025, look.limbs, dark); // foot
        box(0, side * 0.045, 0.028, 0.026, 0.025, 0.21, look.limbs, dark); // leg
        box(0, side * 0.086, 0.02, 0.014, 0.19, 0.35, look.limbs, dark);   // arm
        box(0, side * 0.086, 0.023, 0.017, 0.30, 0.34, look.marker,
            look.marker_label); // arm marker
    }
    box(0, 0, 0.045, 0.07, 0.21, 0.25, look.body, dark);                   // pelvis
    box(0, 0, 0.05, 0.07, 0.25, 0.36, look.body, dark);                    // torso
    box(0, 0, 0.053, 0.073, 0.262, 0.302, look.marker, look.marker_label); // team band
    box(0, 0, 0.015, 0.015, 0.36, 0.376, look.limbs, dark);                // neck
    box(0.005, 0, 0.045, 0.05, 0.376, 0.45, look.body, dark);              // head
    return object;
}

int addPerson(Scene& scene, const Eigen::Vector2d& position, double heading, const PersonLook& look,
              bool on_field)
{
    int object = -1;
    if (on_field) {
        object = int(scene.objects.size());
        scene.objects.push_back(
            {ObjectKind::Person, Vec3(position.x(), position.y(), 0), 0.25, look.height});
    }
    const double k = look.height / 1.75;
    const double c = std::cos(heading);
    const double s = std::sin(heading);
    auto at = [&](double lx, double ly) {
        return Vec2(position.x() + c * lx - s * ly, position.y() + s * lx + c * ly);
    };
    auto add = [&](Primitive p, bool low) {
        p.kind = on_field ? ObjectKind::Person : ObjectKind::Background;
        p.object = object;
        p.counts_for_visibility = low;
        p.field_lit = on_field;
        p.ambient = 0.6;
        scene.primitives.push_back(p);
    };
    const Colour none = Colour::Unclassified;
    for (const double side : {1.0, -1.0}) {
        add(makeBox(at(0.04, side * 0.1), heading, 0.13, 0.05, 0, 0.07, look.shoes, none), true);
        add(makeCylinder(at(0, side * 0.1), 0.065, 0.07, 0.5, look.trousers, none), true);
        add(makeCylinder(at(0, side * 0.1), 0.07, 0.5, 0.88 * k, look.trousers, none), false);
        add(makeCylinder(at(0, side * 0.25), 0.045, 0.86 * k, 1.42 * k, look.shirt, none), false);
        add(makeSphere(Vec3(at(0, side * 0.25).x(), at(0, side * 0.25).y(), 0.82 * k), 0.05,
                       look.skin, none),
            false);
    }
    add(makeBox(at(0, 0), heading, 0.12, 0.21, 0.88 * k, 1.45 * k, look.shirt, none), false);
    add(makeCylinder(at(0, 0), 0.05, 1.45 * k, 1.53 * k, look.skin, none), false);
    add(makeSphere(Vec3(position.x(), position.y(), 1.63 * k), 0.11, look.skin, none), false);
    return object;
}

} // namespace fieldsight::synth
