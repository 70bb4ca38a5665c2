// The cast and the set of each scenario: the hall around the carpet (walls, banners, people,
// scenery) and the objects on it (robots, the ball, their paths); scenario_script.cpp moves
// them, lights them and points the camera.
//
// A stream is the same bytes whichever compiler built the generator: no two random draws are
// arguments of one call (or operands of one operator), whose order of evaluation C++ leaves to
// the compiler. They are drawn into named values first, in the order GCC took them when they
// were arguments (the last first), so that the streams GCC made before stay as they were; a
// clang build made other scenes until then (tests/core/test_synth.cpp checks a stream's bytes).
#include "synth/scenario_script.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace fieldsight::synth {

namespace {

constexpr double kPi = 3.14159265358979323846;
using Vec2 = Eigen::Vector2d;

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

/// x uniform in [lo, hi] and y at +-side, a coin's toss (drawn first).
Vec2 drawnPoint(Rng& rng, double lo, double hi, double side)
{
    const double y = rng.chance(0.5) ? side : -side;
    return Vec2(rng.uniform(lo, hi), y);
}

/// A point in the band between the carpet and the walls, `margin` m clear of both.
Vec2 offFieldPoint(Rng& rng, const Surroundings& s, double margin)
{
    const double cx = FieldGeometry::kCarpetHalfLength + margin;
    const double cy = FieldGeometry::kCarpetHalfWidth + margin;
    for (;;) {
        const double y = rng.uniform(-s.half_y + margin, s.half_y - margin);
        const double x = rng.uniform(-s.half_x + margin, s.half_x - margin);
        const Vec2 p(x, y);
        if (std::abs(p.x()) > cx || std::abs(p.y()) > cy)
            return p;
    }
}

} // namespace

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
            const Rgbf colour = rng.chance(0.5) ? Rgbf(126, 130, 160) : Rgbf(150, 108, 74);
            const double top = rng.uniform(1.2, 1.9);
            m_static.primitives.push_back(sceneryBox(p, 0, 0.3, 0.3, 0.0, top, colour));
        }
        if (m_scenario == Scenario::Lab1) {
            for (int i = 0; i < 4; ++i) { // boxes and bags on the floor: the background noise
                const Vec2 p = offFieldPoint(rng, s, 0.2);
                const Rgbf colour = rng.chance(0.5) ? Rgbf(172, 140, 100) : Rgbf(120, 60, 96);
                const double top = rng.uniform(0.2, 0.5);
                const double yaw = rng.uniform(0, kPi);
                m_static.primitives.push_back(sceneryBox(p, yaw, 0.2, 0.15, 0.0, top, colour));
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
        const double y = side * rng.uniform(3.3, 4.2);
        const Vec2 p(rng.uniform(-4.5, 4.5), y);
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
        const PersonLook look = randomPerson(rng);
        addPerson(m_static, p, std::atan2(-p.y(), -p.x()) + rng.uniform(-0.6, 0.6), look, false);
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
    const double ball_y = rng.uniform(-0.7, 0.7);
    m_ball_home = Vec2(rng.uniform(-1.2, 1.2), ball_y);
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
        const double y = rng.uniform(-1.6, 1.6);
        r.home = Vec2(rng.uniform(-2.4, 2.4), y);
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
        const double y = rng.chance(0.5) ? 1.9 : -1.9;
        r.home = Vec2(rng.uniform(-1.5, 1.5), y);
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
        person(drawnPoint(rng, -1.5, 1.5, 2.3), 0.8, true);
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
        {
            const double y = rng.uniform(-0.5, 0.5);
            person(Vec2(rng.uniform(-1, 1), y), 1.8, true);
        }
        m_people.back().follows_play = true;             // the referee
        person(drawnPoint(rng, -2, 2, 2.35), 1.0, true); // captain
        break;
    case Scenario::Crowded: {
        const double close = rng.uniform(0.15, 0.35);
        occluder(rng.chance(0.5), close); // close to the camera, and in view
        m_robots.back().wy.a1 *= 0.3;     // more often than not
        m_robots.back().wy.a2 *= 0.3;
        const double further = rng.uniform(0.45, 0.7);
        occluder(rng.chance(0.5), further);
        crowd(true, rng.uniform(-0.8, -0.3), 0.3, 0.8);
        crowd(false, rng.uniform(0.2, 0.7), 0.4, 1.0);
        follower(rng.chance(0.5), 0.5, 1.2);
        break;
    }
    }
}

} // namespace fieldsight::synth
