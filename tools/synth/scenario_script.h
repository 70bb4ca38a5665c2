// What happens in each modelled stream: the surroundings, how the ball, robots, people and the
// camera move, and the light and camera quality, all as pure functions of (scenario, seed, frame).
#pragma once

#include "synth/camera_model.h"
#include "synth/renderer.h"
#include "synth/scene.h"
#include "synth/synth.h"
#include "synth/synth_random.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace fieldsight::synth {

/// Two summed sinusoids: smooth, bounded wandering.
struct Wander
{
    double a1 = 0, w1 = 0, p1 = 0; ///< amplitude, rad/s, rad
    double a2 = 0, w2 = 0, p2 = 0;
    double at(double t) const;
};

class ScenarioScript
{
public:
    static constexpr double kFramePeriodMs = 1000.0 / 30.0; ///< the paper's streams ran at 30 fps

    ScenarioScript(Scenario scenario, std::uint64_t seed, int width, int height);

    Scenario scenario() const { return m_scenario; }
    int width() const { return m_width; }
    int height() const { return m_height; }

    /// The world and camera pose at frame `index` (time index / 30 s).
    Scene sceneAt(int index) const;
    CameraEffects effectsAt(int index) const;
    /// The light's colour temperature and level drift by `drift` (0..0.5, driftGain) from frame
    /// 0 to frame `frames` - 1 and stay there after it; `held` (0..1) keeps every frame at that
    /// point of the drift instead (a stream lit as one moment of the drifting one).
    void setLightDrift(double drift, int frames, std::optional<double> held = std::nullopt);
    /// How far frame `index` is along the drift, 0..1.
    double driftPhase(int index) const;
    /// m, the camera's height above the carpet (0.45 unless set).
    void setCameraHeight(double metres) { m_camera_height = metres; }
    /// Seed for the sensor noise of frame `index`.
    std::uint64_t noiseSeed(int index) const;

private:
    /// FollowBall: around the ball at any bearing; Crowd: beyond the ball as the camera sees it;
    /// Occlude: between the camera and the ball; Keeper: in front of a goal.
    enum class RobotRole { FollowBall, Crowd, Wander, Occlude, Keeper };
    struct RobotPlan
    {
        RobotRole role = RobotRole::Wander;
        Eigen::Vector2d home{0, 0};
        double radius = 1.0; ///< m from the ball (FollowBall), wander amplitude, or share of
                             ///< the way from the camera to the ball (Occlude)
        double bearing = 0;  ///< rad, from the ball (FollowBall) or base heading (Wander)
        double lag = 0.5;    ///< s behind the ball (FollowBall)
        Wander wx, wy, turn;
        RobotLook look;
    };
    struct PersonPlan
    {
        Eigen::Vector2d home{0, 0};
        Wander wx, wy;
        PersonLook look;
        bool on_field = true;
        bool follows_play = false; ///< a referee: keeps level with the ball along x
    };
    struct Style
    {
        double level = 1.0;
        double gradient_x = 0;
        double spots = 0.05;
        bool light_changes = false;
        double track_bias = 0.3; ///< > 0 tracks the ball more often than it scans
        double camera_distance_min = 0.7;
        double camera_distance_max = 2.2;
        double bob = 1.0;
        double robot_clearance = 0.42; ///< m, closest a robot comes to the camera
        CameraEffects effects;
    };

    Eigen::Vector2d ballAt(double t) const;
    Eigen::Vector2d cameraAt(double t) const;
    CameraPose poseAt(double t, const Eigen::Vector2d& ball) const;
    double lightLevelAt(double t) const;
    void buildSurroundings(Rng& rng);
    void planObjects(Rng& rng);

    Scenario m_scenario;
    std::uint64_t m_seed;
    int m_width;
    int m_height;
    Style m_style;
    Scene m_static; ///< surroundings, goals and fixed scenery
    Rgbf m_carpet;
    Wander m_ball_x, m_ball_y;
    Eigen::Vector2d m_ball_home{0, 0};
    Wander m_cam_distance, m_cam_angle;
    double m_cam_angle_home = 3.14159;
    Wander m_track, m_pan, m_tilt, m_jitter_yaw, m_jitter_pitch;
    double m_step_hz = 1.8;
    double m_step_phase = 0;
    std::vector<double> m_light_times;  ///< s, Lab1 light changes
    std::vector<double> m_light_levels; ///< level after each change
    std::vector<RobotPlan> m_robots;
    std::vector<PersonPlan> m_people; ///< moving people, on the field or behind it
    double m_drift = 0;
    int m_drift_frames = 1;
    std::optional<double> m_drift_held;
    double m_camera_height = 0.45;
};

/// The R, G, B gains of a light drifted by `drift` at `phase` (0..1) of the drift: warmer (red
/// up, blue down by drift * phase) and dimmer (by drift * phase / 2), as late afternoon sun
/// through a hall's windows.
Eigen::Vector3d driftGain(double drift, double phase);

} // namespace fieldsight::synth
