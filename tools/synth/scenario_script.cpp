// The five modelled streams and the crowded test scene: surroundings, motion, light and camera
// quality per scenario.
#include "synth/scenario_script.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace fieldsight::synth {

namespace {

constexpr double kPi = 3.14159265358979323846;
using Vec2 = Eigen::Vector2d;

double wrapAngle(double a)
{
    return std::remainder(a, 2 * kPi);
}

double smoothstep(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3 - 2 * x);
}

/// A wander of total amplitude <= amplitude, the main period within [w_lo, w_hi] rad/s.
Wander randomWander(Rng& rng, double amplitude, double w_lo, double w_hi)
{
    Wander w;
    w.a1 = amplitude * rng.uniform(0.6, 0.75);
    w.w1 = rng.uniform(w_lo, w_hi);
    w.p1 = rng.uniform(0, 2 * kPi);
    w.a2 = amplitude * rng.uniform(0.1, 0.25);
    w.w2 = w.w1 * rng.uniform(1.7, 2.9);
    w.p2 = rng.uniform(0, 2 * kPi);
    return w;
}

template <std::size_t N> Rgbf pick(Rng& rng, const std::array<Rgbf, N>& palette)
{
    return palette[std::size_t(rng.below(int(N)))];
}

// Background colours are all chromatic and far from the field classes, so that a grey line in
// dim light, a robot's black or the ball's orange never shares a LUT cell with the surroundings
// by majority. The Difficult scenario adds deliberate near-misses (distractors).
const std::array<Rgbf, 10> kShirts = {Rgbf(170, 40, 48),   Rgbf(35, 45, 100),   Rgbf(100, 55, 122),
                                      Rgbf(122, 40, 58),   Rgbf(125, 88, 62),   Rgbf(168, 122, 100),
                                      Rgbf(150, 170, 205), Rgbf(112, 120, 155), Rgbf(182, 158, 202),
                                      Rgbf(200, 120, 150)};
const std::array<Rgbf, 4> kTrousers = {Rgbf(62, 76, 118), Rgbf(38, 42, 78), Rgbf(152, 136, 102),
                                       Rgbf(96, 72, 56)};
const std::array<Rgbf, 4> kSkin = {Rgbf(226, 182, 152), Rgbf(202, 152, 122), Rgbf(152, 106, 80),
                                   Rgbf(112, 76, 56)};
const std::array<Rgbf, 6> kBanners = {Rgbf(36, 60, 150),   Rgbf(178, 40, 46), Rgbf(112, 50, 132),
                                      Rgbf(176, 150, 220), Rgbf(30, 40, 92),  Rgbf(150, 60, 110)};
const std::array<Rgbf, 5> kPosters = {Rgbf(172, 52, 52), Rgbf(52, 82, 162), Rgbf(122, 72, 142),
                                      Rgbf(200, 160, 170), Rgbf(96, 110, 170)};

const Rgbf kTeamBlue(40, 110, 215);
const Rgbf kTeamPink(225, 45, 150);

PersonLook randomPerson(Rng& rng)
{
    PersonLook look;
    look.shirt = pick(rng, kShirts);
    look.trousers = pick(rng, kTrousers);
    look.skin = pick(rng, kSkin);
    look.shoes = Rgbf(92, 70, 60);
    look.height = rng.uniform(1.55, 1.92);
    return look;
}

RobotLook robotLook(Rng& rng, bool blue)
{
    RobotLook look;
    const double body = rng.uniform(50, 64);
    const double limbs = rng.uniform(30, 40);
    look.body = Rgbf(body, body, body);
    look.limbs = Rgbf(limbs, limbs, limbs);
    look.marker = blue ? kTeamBlue : kTeamPink;
    look.marker_label = blue ? Colour::Blue : Colour::Pink;
    return look;
}

Primitive sceneryBox(const Vec2& centre, double yaw, double hx, double hy, double z0, double z1,
                     const Rgbf& colour)
{
    Primitive p = makeBox(centre, yaw, hx, hy, z0, z1, colour, Colour::Unclassified);
    p.field_lit = false;
    p.ambient = 0.65;
    return p;
}

/// A point in the band between the carpet and the walls, `margin` m clear of both.
Vec2 offFieldPoint(Rng& rng, const Surroundings& s, double margin)
{
    const double cx = FieldGeometry::kCarpetHalfLength + margin;
    const double cy = FieldGeometry::kCarpetHalfWidth + margin;
    for (;;) {
        const Vec2 p(rng.uniform(-s.half_x + margin, s.half_x - margin),
                     rng.uniform(-s.half_y + margin, s.half_y - margin));
        if (std::abs(p.x()) > cx || std::abs(p.y()) > cy)
            return p;
    }
}

} // namespace

double Wander::at(double t) const
{
    return a1 * std::sin(w1 * t + p1) + a2 * std::sin(w2 * t + p2);
}

ScenarioScript::ScenarioScript(Scenario scenario, std::uint64_t seed, int width, int height)
    : m_scenario(scenario), m_seed(mixSeed(seed, 1000 + std::uint64_t(scenario))), m_width(width),
      m_height(height)
{
    Rng rng(m_seed);
    Style& s = m_style;
    switch (scenario) {
    case Scenario::Lab1:
        s.spots = 0.07;
        s.light_changes = true;
        s.track_bias = 0.15;
        s.camera_distance_max = 2.6;
        s.robot_clearance = 0.9;
        s.effects = {0.75, 0.2, 1.4, 1.2, true, {1, 1, 1}};
        m_carpet = Rgbf(45, 125, 50);
        break;
    case Scenario::Lab2:
        s.spots = 0.04;
        s.track_bias = 0.85;
        s.camera_distance_max = 2.0;
        s.bob = 0.7;
        s.robot_clearance = 1.0;
        // Stable, high-quality images: no visible sensor noise (this also keeps the bundled
        // PNGs small; per-pixel noise triples their size).
        s.effects = {0.65, 0.15, 0.0, 0.0, true, {1, 1, 1}};
        m_carpet = Rgbf(45, 125, 50);
        break;
    case Scenario::Difficult:
        s.level = 0.62;
        s.gradient_x = 0.03;
        s.spots = 0.18;
        s.track_bias = 0.1;
        s.camera_distance_min = 0.6;
        s.bob = 1.3;
        s.effects = {1.05, 0.32, 2.6, 2.0, true, {1.06, 1.0, 0.88}};
        m_carpet = Rgbf(42, 116, 48);
        break;
    case Scenario::RC2012:
        s.gradient_x = -0.14; // 1.5x the light at one end, 0.5x at the other
        s.spots = 0.06;
        s.track_bias = 0.1;
        s.camera_distance_max = 2.8;
        s.robot_clearance = 0.6;
        s.effects = {0.8, 0.22, 1.6, 1.4, true, {1, 1, 1}};
        m_carpet = Rgbf(40, 118, 54);
        break;
    case Scenario::RC2013:
        s.level = 1.05;
        s.gradient_x = 0.015;
        s.spots = 0.03;
        s.track_bias = 0.5;
        s.camera_distance_min = 0.8;
        s.camera_distance_max = 2.6;
        s.effects = {0.6, 0.15, 0.0, 0.0, true, {1, 1, 1}}; // "predominantly high quality"
        m_carpet = Rgbf(50, 132, 48);
        break;
    case Scenario::Crowded:
        // Five robots in a competition hall, two of them between the camera and the ball and
        // allowed close enough to fill the frame; the camera scans often, so the ball and the
        // posts are cut by the frame's sides.
        s.level = 1.0;
        s.spots = 0.05;
        s.track_bias = 0.4;
        s.camera_distance_min = 0.6;
        s.camera_distance_max = 2.2;
        s.robot_clearance = 0.2;
        s.effects = {0.7, 0.18, 1.0, 0.8, true, {1, 1, 1}};
        m_carpet = Rgbf(44, 126, 50);
        break;
    }
    buildSurroundings(rng);
    addGoal(m_static, FieldGeometry::kLength / 2);
    addGoal(m_static, -FieldGeometry::kLength / 2);
    planObjects(rng);
}

void ScenarioScript::buildSurroundings(Rng& rng)
{
    Surroundings& s = m_static.surroundings;
    const bool lab = m_scenario == Scenario::Lab1 || m_scenario == Scenario::Lab2;
    if (lab) {
        s.half_x = 4.9;
        s.half_y = 4.0;
        s.ceiling = 3.0;
        s.floor = Rgbf(104, 110, 138);
        s.wall = Rgbf(198, 184, 160);
        s.ceiling_colour = Rgbf(190, 186, 200);
        // A door, windows, a whiteboard and posters.
        s.patches.push_back({2, rng.uniform(-3.5, -1.5), 0, 0, 2.05, Rgbf(122, 86, 60), false});
        s.patches.back().u1 = s.patches.back().u0 + 0.9;
        for (int i = 0; i < 3; ++i) {
            const double u = -3.0 + 2.2 * i + rng.uniform(-0.2, 0.2);
            s.patches.push_back({3, u, u + 1.4, 0.95, 2.3, Rgbf(168, 188, 214), false});
        }
        const double wb = rng.uniform(-1.5, 0.5);
        s.patches.push_back({0, wb, wb + 2.0, 0.9, 1.9, Rgbf(204, 212, 230), false});
        const int posters = m_scenario == Scenario::Lab1 ? 7 : 3;
        for (int i = 0; i < posters; ++i) {
            const int wall = rng.below(4);
            const double extent = wall < 2 ? s.half_y : s.half_x;
            const double u = rng.uniform(-extent + 0.3, extent - 1.0);
            const double z = rng.uniform(0.9, 1.5);
            s.patches.push_back({wall, u, u + rng.uniform(0.4, 0.8), z, z + rng.uniform(0.5, 0.8),
                                 pick(rng, kPosters), false});
        }
        // Furniture along the walls: desks and cupboards.
        const int desks = m_scenario == Scenario::Lab1 ? 5 : 3;
        for (int i = 0; i < desks; ++i) {
            const Vec2 p = offFieldPoint(rng, s, 0.5);
            const double yaw = std::abs(p.x()) > FieldGeometry::kCarpetHalfLength ? kPi / 2 : 0;
            m_static.primitives.push_back(
                sceneryBox(p, yaw, 0.6, 0.35, 0.7, 0.75, Rgbf(156, 118, 88)));
            m_static.primitives.push_back(
                sceneryBox(p, yaw, 0.55, 0.3, 0.0, 0.7, Rgbf(84, 86, 122)));
        }
        const int cupboards = m_scenario == Scenario::Lab1 ? 4 : 2;
        for (int i = 0; i < cupboards; ++i) {
            const Vec2 p = offFieldPoint(rng, s, 0.35);
            m_static.primitives.push_back(
                sceneryBox(p, 0, 0.3, 0.3, 0.0, rng.uniform(1.2, 1.9),
                           rng.chance(0.5) ? Rgbf(126, 130, 160) : Rgbf(150, 108, 74)));
        }
        if (m_scenario == Scenario::Lab1) {
            for (int i = 0; i < 4; ++i) { // boxes and bags on the floor: the background noise
                const Vec2 p = offFieldPoint(rng, s, 0.2);
                m_static.primitives.push_back(
                    sceneryBox(p, rng.uniform(0, kPi), 0.2, 0.15, 0.0, rng.uniform(0.2, 0.5),
                               rng.chance(0.5) ? Rgbf(172, 140, 100) : Rgbf(120, 60, 96)));
            }
        }
        return;
    }
    s.half_x = 6.2;
    s.half_y = 4.8;
    s.ceiling = 6.0;
    s.floor = Rgbf(74, 70, 116);
    s.wall = Rgbf(50, 54, 102); // dark blue curtains
    s.ceiling_colour = Rgbf(56, 50, 84);
    s.skirting = false;
    for (int wall = 0; wall < 4; ++wall) {
        const double extent = wall < 2 ? s.half_y : s.half_x;
        for (double u = -extent; u < extent - 1.0; u += rng.uniform(2.0, 3.2)) {
            const double len = rng.uniform(1.2, 2.2);
            s.patches.push_back(
                {wall, u, u + len, 0.4, rng.uniform(1.1, 1.6), pick(rng, kBanners), true});
        }
    }
    // Team tables behind the touch lines.
    for (int i = 0; i < 4; ++i) {
        const double side = i % 2 ? 1 : -1;
        const Vec2 p(rng.uniform(-4.5, 4.5), side * rng.uniform(3.3, 4.2));
        m_static.primitives.push_back(sceneryBox(p, 0, 0.8, 0.4, 0.72, 0.76, Rgbf(158, 118, 86)));
        m_static.primitives.push_back(sceneryBox(p, 0, 0.75, 0.35, 0.0, 0.72, Rgbf(70, 74, 120)));
        m_static.primitives.push_back(sceneryBox(p + Vec2(rng.uniform(-0.4, 0.4), 0), 0, 0.17, 0.12,
                                                 0.76, 0.79, Rgbf(150, 160, 190)));
    }
    int crowd = 10;
    if (m_scenario == Scenario::RC2012)
        crowd = 14;
    if (m_scenario == Scenario::RC2013)
        crowd = 28;
    for (int i = 0; i < crowd; ++i) {
        const Vec2 p = offFieldPoint(rng, s, 0.35);
        addPerson(m_static, p, std::atan2(-p.y(), -p.x()) + rng.uniform(-0.6, 0.6),
                  randomPerson(rng), false);
    }
    if (m_scenario == Scenario::Difficult) {
        // Distractors: ball-orange-ish and goal-yellow-ish things off the field.
        PersonLook orange = randomPerson(rng);
        orange.shirt = Rgbf(226, 118, 80);
        addPerson(m_static, Vec2(rng.uniform(-2.5, 2.5), FieldGeometry::kCarpetHalfWidth + 0.5),
                  -kPi / 2, orange, false);
        PersonLook yellow = randomPerson(rng);
        yellow.shirt = Rgbf(214, 190, 86);
        addPerson(m_static, Vec2(FieldGeometry::kCarpetHalfLength + 0.6, rng.uniform(-2.0, 2.0)),
                  kPi, yellow, false);
        m_static.primitives.push_back(
            sceneryBox(Vec2(-FieldGeometry::kCarpetHalfLength - 0.4, rng.uniform(-1.5, 1.5)), 0.3,
                       0.2, 0.2, 0.0, 0.55, Rgbf(228, 104, 72)));
        s.patches.push_back({1, -1.5, 0.5, 0.5, 1.4, Rgbf(216, 188, 80), false});
        s.patches.push_back({3, 0.5, 2.5, 0.5, 1.3, Rgbf(230, 128, 86), true});
    }
}

void ScenarioScript::planObjects(Rng& rng)
{
    const bool slow = m_scenario == Scenario::Lab2;
    m_ball_home = Vec2(rng.uniform(-1.2, 1.2), rng.uniform(-0.7, 0.7));
    m_ball_x = randomWander(rng, slow ? 0.9 : 1.5, slow ? 0.1 : 0.15, slow ? 0.2 : 0.35);
    m_ball_y = randomWander(rng, slow ? 0.6 : 0.9, slow ? 0.1 : 0.15, slow ? 0.2 : 0.35);
    m_cam_distance = randomWander(rng, 1.0, 0.2, 0.5);
    m_cam_angle = randomWander(rng, 1.2, 0.1, 0.3);
    m_cam_angle_home = rng.chance(0.5) ? kPi : 0.0;
    m_track = randomWander(rng, 1.0, 0.5, 1.0);
    m_pan = randomWander(rng, 1.1, 1.5, 2.5);
    m_tilt = randomWander(rng, 0.14, 1.0, 2.0);
    m_jitter_yaw = randomWander(rng, 0.07, 3.0, 5.0);
    m_jitter_pitch = randomWander(rng, 0.05, 3.0, 5.0);
    m_step_hz = rng.uniform(1.6, 2.0);
    m_step_phase = rng.uniform(0, 2 * kPi);

    if (m_style.light_changes) {
        double t = rng.uniform(0.25, 0.75);
        bool dim = true;
        while (t < 4000) {
            m_light_times.push_back(t);
            m_light_levels.push_back(dim ? rng.uniform(0.66, 0.8) : rng.uniform(0.95, 1.08));
            dim = !dim;
            t += rng.uniform(2.0, 6.0);
        }
    }

    auto robot = [&](RobotRole role, bool blue) {
        RobotPlan r;
        r.role = role;
        r.wx = randomWander(rng, 1.0, 0.15, 0.4);
        r.wy = randomWander(rng, 1.0, 0.15, 0.4);
        r.turn = randomWander(rng, 1.0, 0.1, 0.3);
        r.look = robotLook(rng, blue);
        return r;
    };
    auto follower = [&](bool blue, double r_lo, double r_hi) {
        RobotPlan r = robot(RobotRole::FollowBall, blue);
        r.radius = rng.uniform(r_lo, r_hi);
        r.lag = rng.uniform(0.3, 1.2);
        r.bearing = rng.uniform(0, 2 * kPi);
        m_robots.push_back(r);
    };
    auto crowd = [&](bool blue, double bearing, double r_lo, double r_hi) {
        RobotPlan r = robot(RobotRole::Crowd, blue);
        r.radius = rng.uniform(r_lo, r_hi);
        r.lag = rng.uniform(0.3, 1.0);
        r.bearing = bearing;
        m_robots.push_back(r);
    };
    auto wanderer = [&](bool blue, double amplitude) {
        RobotPlan r = robot(RobotRole::Wander, blue);
        r.home = Vec2(rng.uniform(-2.4, 2.4), rng.uniform(-1.6, 1.6));
        r.radius = amplitude;
        r.bearing = rng.uniform(0, 2 * kPi);
        m_robots.push_back(r);
    };
    auto keeper = [&](bool blue, double goal_x) {
        RobotPlan r = robot(RobotRole::Keeper, blue);
        r.home = Vec2(goal_x - std::copysign(0.3, goal_x), 0);
        m_robots.push_back(r);
    };
    auto occluder = [&](bool blue, double fraction) {
        RobotPlan r = robot(RobotRole::Occlude, blue);
        r.radius = fraction;
        r.wy = randomWander(rng, 1.0, 0.5, 0.9); // crosses the line of sight now and then
        m_robots.push_back(r);
    };
    auto person = [&](Vec2 home, double amplitude, bool on_field) {
        PersonPlan p;
        p.home = home;
        p.wx = randomWander(rng, amplitude, 0.1, 0.3);
        p.wy = randomWander(rng, on_field ? 0.2 : 0.3, 0.1, 0.3);
        p.look = randomPerson(rng);
        p.on_field = on_field;
        m_people.push_back(p);
    };
    const double goal = FieldGeometry::kLength / 2;
    switch (m_scenario) {
    case Scenario::Lab1:
        wanderer(true, 0.8);
        wanderer(false, 0.8);
        person(Vec2(rng.uniform(-2, 2), FieldGeometry::kCarpetHalfWidth + 0.7), 1.6, false);
        person(Vec2(FieldGeometry::kCarpetHalfLength + 0.6, rng.uniform(-1, 1)), 0.4, false);
        break;
    case Scenario::Lab2: {
        RobotPlan r = robot(RobotRole::Wander, true);
        r.home = Vec2(rng.uniform(-1.5, 1.5), rng.chance(0.5) ? 1.9 : -1.9);
        r.radius = 0.25;
        r.bearing = rng.uniform(0, 2 * kPi);
        m_robots.push_back(r);
        break;
    }
    case Scenario::Difficult:
        occluder(false, 0.4);
        occluder(true, 0.65);
        follower(true, 0.45, 0.8);
        follower(false, 0.5, 0.9);
        keeper(false, goal);
        person(Vec2(rng.uniform(-1.5, 1.5), rng.chance(0.5) ? 2.3 : -2.3), 0.8, true);
        break;
    case Scenario::RC2012:
        follower(true, 0.7, 1.4);
        follower(false, 0.8, 1.6);
        keeper(true, -goal);
        break;
    case Scenario::RC2013:
        crowd(true, -0.7, 0.4, 0.8);
        crowd(false, -0.1, 0.5, 1.0);
        crowd(true, 0.6, 0.4, 0.9);
        crowd(false, 0.3, 1.2, 1.9);
        follower(true, 0.5, 1.1);
        follower(false, 0.8, 1.5);
        wanderer(false, 0.8);
        keeper(true, goal);
        keeper(false, -goal);
        person(Vec2(rng.uniform(-1, 1), rng.uniform(-0.5, 0.5)), 1.8, true);
        m_people.back().follows_play = true;                                         // the referee
        person(Vec2(rng.uniform(-2, 2), rng.chance(0.5) ? 2.35 : -2.35), 1.0, true); // captain
        break;
    case Scenario::Crowded:
        occluder(rng.chance(0.5), rng.uniform(0.15, 0.35)); // close to the camera, and in view
        m_robots.back().wy.a1 *= 0.3;                       // more often than not
        m_robots.back().wy.a2 *= 0.3;
        occluder(rng.chance(0.5), rng.uniform(0.45, 0.7));
        crowd(true, rng.uniform(-0.8, -0.3), 0.3, 0.8);
        crowd(false, rng.uniform(0.2, 0.7), 0.4, 1.0);
        follower(rng.chance(0.5), 0.5, 1.2);
        break;
    }
}

Eigen::Vector2d ScenarioScript::ballAt(double t) const
{
    const Vec2 p = m_ball_home + Vec2(m_ball_x.at(t), m_ball_y.at(t));
    return Vec2(std::clamp(p.x(), -2.9, 2.9), std::clamp(p.y(), -1.9, 1.9));
}

Eigen::Vector2d ScenarioScript::cameraAt(double t) const
{
    const Vec2 ball = ballAt(t);
    const double s = std::clamp(0.5 + 0.5 * m_cam_distance.at(t), 0.0, 1.0);
    const double d = m_style.camera_distance_min +
                     (m_style.camera_distance_max - m_style.camera_distance_min) * s;
    const double a = m_cam_angle_home + m_cam_angle.at(t);
    Vec2 cam = ball + d * Vec2(std::cos(a), std::sin(a));
    cam = Vec2(std::clamp(cam.x(), -3.3, 3.3), std::clamp(cam.y(), -2.3, 2.3));
    const Vec2 to_cam = cam - ball;
    if (to_cam.norm() < 0.45)
        cam = ball + 0.45 * (to_cam.norm() > 1e-6 ? to_cam.normalized() : Vec2(-1, 0));
    for (const double x : {-FieldGeometry::kLength / 2, FieldGeometry::kLength / 2}) {
        for (const double y : {-0.8, 0.8}) { // keep the camera out of the goalposts
            const Vec2 away = cam - Vec2(x, y);
            if (away.norm() < 0.35)
                cam = Vec2(x, y) + 0.35 * (away.norm() > 1e-6 ? away.normalized() : Vec2(0, 1));
        }
    }
    return cam;
}

CameraPose ScenarioScript::poseAt(double t, const Eigen::Vector2d& ball) const
{
    const Vec2 cam = cameraAt(t);
    const double step = 2 * kPi * m_step_hz * t + m_step_phase;
    CameraPose pose;
    pose.position =
        Eigen::Vector3d(cam.x(), cam.y(), m_camera_height + m_style.bob * 0.006 * std::sin(step));
    const double r = FieldGeometry::kBallDiameter / 2;
    const Vec2 to_ball = ball - cam;
    const double yaw_ball = std::atan2(to_ball.y(), to_ball.x());
    const double pitch_ball = std::atan2(pose.position.z() - r, to_ball.norm());
    const double track = smoothstep(0.5 + 1.2 * (m_track.at(t) + m_style.track_bias));
    const double yaw_scan = yaw_ball + m_pan.at(t);
    const double pitch_scan = 0.22 + m_tilt.at(t);
    pose.yaw = yaw_scan + track * wrapAngle(yaw_ball - yaw_scan) + m_jitter_yaw.at(t);
    pose.pitch = pitch_scan + track * (pitch_ball - pitch_scan) + m_jitter_pitch.at(t) +
                 m_style.bob * 0.012 * std::sin(step + 1.0);
    pose.pitch = std::clamp(pose.pitch, -0.05, 0.8);
    pose.roll = m_style.bob * 0.025 * std::sin(0.5 * step);
    return pose;
}

double ScenarioScript::lightLevelAt(double t) const
{
    if (m_light_times.empty())
        return m_style.level;
    constexpr double kRamp = 0.25; // s for a lamp to settle
    double level = m_style.level;
    for (std::size_t i = 0; i < m_light_times.size() && m_light_times[i] <= t; ++i) {
        const double k = std::min(1.0, (t - m_light_times[i]) / kRamp);
        level += (m_light_levels[i] - level) * k;
    }
    return level;
}

Scene ScenarioScript::sceneAt(int index) const
{
    const double t = index / 30.0;
    Scene scene = m_static;
    scene.carpet = m_carpet;
    scene.texture_seed = m_seed;
    scene.lighting.level = lightLevelAt(t);
    scene.lighting.gradient_x = m_style.gradient_x;
    scene.lighting.spot_strength = m_style.spots;
    scene.lighting.spot_seed = m_seed + 17;

    const Vec2 ball = ballAt(t);
    const Vec2 cam = cameraAt(t);

    // Where everyone wants to be, then pushed apart so nothing overlaps.
    struct Body
    {
        Vec2 p;
        double radius;
        double heading;
    };
    std::vector<Body> bodies;
    for (const RobotPlan& r : m_robots) {
        Vec2 p = r.home;
        switch (r.role) {
        case RobotRole::FollowBall: {
            const Vec2 b = ballAt(t - r.lag);
            const double bearing = r.bearing + 1.2 * r.turn.at(t);
            p = b + (r.radius + 0.25 * r.wx.at(t)) * Vec2(std::cos(bearing), std::sin(bearing));
            break;
        }
        case RobotRole::Crowd: {
            const Vec2 b = ballAt(t - r.lag);
            const Vec2 away = b - cam;
            const double bearing = std::atan2(away.y(), away.x()) + r.bearing + 0.35 * r.turn.at(t);
            p = b + (r.radius + 0.25 * r.wx.at(t)) * Vec2(std::cos(bearing), std::sin(bearing));
            break;
        }
        case RobotRole::Wander:
            p = r.home + r.radius * Vec2(r.wx.at(t), r.wy.at(t));
            break;
        case RobotRole::Occlude: {
            const Vec2 along = ball - cam;
            const Vec2 across = Vec2(-along.y(), along.x()).normalized();
            p = cam + (r.radius + 0.1 * r.wx.at(t)) * along + 0.6 * r.wy.at(t) * across;
            break;
        }
        case RobotRole::Keeper:
            p = r.home + Vec2(0.1 * r.wx.at(t), 0.5 * r.wy.at(t));
            break;
        }
        const Vec2 to_ball = ball - p;
        double heading = std::atan2(to_ball.y(), to_ball.x()) + 0.3 * r.turn.at(t);
        if (r.role == RobotRole::Wander)
            heading = r.bearing + 2.0 * r.turn.at(t);
        bodies.push_back({p, 0.13, heading});
    }
    for (const PersonPlan& q : m_people) {
        Vec2 p = q.home + Vec2(q.wx.at(t), q.wy.at(t));
        if (q.follows_play)
            p.x() = 0.6 * ball.x() + q.wx.at(t); // the referee follows play
        const Vec2 to_ball = ball - p;
        bodies.push_back({p, 0.3, std::atan2(to_ball.y(), to_ball.x())});
    }
    const std::array<Vec2, 4> posts = {Vec2(3, 0.8), Vec2(3, -0.8), Vec2(-3, 0.8), Vec2(-3, -0.8)};
    auto pushFrom = [](Body& b, const Vec2& fixed, double min_distance) {
        Vec2 d = b.p - fixed;
        const double n = d.norm();
        if (n >= min_distance)
            return;
        d = n > 1e-9 ? Vec2(d / n) : Vec2(1, 0);
        b.p = fixed + min_distance * d;
    };
    for (int pass = 0; pass < 6; ++pass) {
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            for (std::size_t j = i + 1; j < bodies.size(); ++j) {
                Vec2 d = bodies[j].p - bodies[i].p;
                const double n = d.norm();
                const double need = bodies[i].radius + bodies[j].radius + 0.05;
                if (n < need) {
                    d = n > 1e-9 ? Vec2(d / n) : Vec2(0, 1);
                    bodies[i].p -= 0.5 * (need - n) * d;
                    bodies[j].p += 0.5 * (need - n) * d;
                }
            }
        }
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            Body& b = bodies[i];
            for (const Vec2& post : posts)
                pushFrom(b, post, b.radius + 0.08);
            pushFrom(b, ball, b.radius + FieldGeometry::kBallDiameter / 2 + 0.03);
            pushFrom(b, cam, b.radius < 0.2 ? m_style.robot_clearance : 0.8);
            const bool person = i >= m_robots.size();
            const bool on_carpet = !person || m_people[i - m_robots.size()].on_field;
            if (on_carpet) {
                b.p.x() = std::clamp(b.p.x(), -3.45, 3.45);
                b.p.y() = std::clamp(b.p.y(), -2.45, 2.45);
            } else {
                const Surroundings& room = m_static.surroundings;
                b.p.x() = std::clamp(b.p.x(), -room.half_x + 0.3, room.half_x - 0.3);
                b.p.y() = std::clamp(b.p.y(), -room.half_y + 0.3, room.half_y - 0.3);
            }
        }
    }

    addBall(scene, Eigen::Vector3d(ball.x(), ball.y(), FieldGeometry::kBallDiameter / 2));
    for (std::size_t i = 0; i < m_robots.size(); ++i)
        addRobot(scene, bodies[i].p, bodies[i].heading, m_robots[i].look);
    for (std::size_t i = 0; i < m_people.size(); ++i) {
        const Body& b = bodies[m_robots.size() + i];
        addPerson(scene, b.p, b.heading, m_people[i].look, m_people[i].on_field);
    }
    scene.camera = poseAt(t, ball);
    return scene;
}

CameraEffects ScenarioScript::effectsAt(int index) const
{
    CameraEffects e = m_style.effects;
    // Darker scenes need more sensor gain, hence more noise.
    const double level = lightLevelAt(index / 30.0);
    const double boost = std::sqrt(std::max(1.0, m_style.level / level));
    e.noise_y *= boost;
    e.noise_c *= boost;
    if (m_drift != 0)
        e.gain = e.gain.cwiseProduct(driftGain(m_drift, driftPhase(index)));
    return e;
}

void ScenarioScript::setLightDrift(double drift, int frames, std::optional<double> held)
{
    m_drift = drift;
    m_drift_frames = std::max(1, frames);
    m_drift_held = held;
}

double ScenarioScript::driftPhase(int index) const
{
    if (m_drift_held)
        return std::clamp(*m_drift_held, 0.0, 1.0);
    if (m_drift_frames < 2)
        return 0;
    return std::clamp(double(index) / double(m_drift_frames - 1), 0.0, 1.0);
}

Eigen::Vector3d driftGain(double drift, double phase)
{
    const double d = drift * phase;
    const double level = 1.0 - 0.5 * d;
    return level * Eigen::Vector3d(1.0 + d, 1.0, 1.0 - d);
}

std::uint64_t ScenarioScript::noiseSeed(int index) const
{
    return mixSeed(m_seed ^ 0x5EEDF00Dull, std::uint64_t(index));
}

} // namespace fieldsight::synth
