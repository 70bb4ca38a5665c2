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
