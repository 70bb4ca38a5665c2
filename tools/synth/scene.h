// The generator's world at one instant: field, lighting, and the solid primitives standing on it.
#pragma once

#include "synth/camera_model.h"

#include "visioncore/basics/colour.h"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace fieldsight::synth {

/// RoboCup 2013 kid-size field, metres (line positions are line centres).
struct FieldGeometry
{
    static constexpr double kLength = 6.0;        ///< m, goal line to goal line
    static constexpr double kWidth = 4.0;         ///< m, touch line to touch line
    static constexpr double kBorder = 0.7;        ///< m, green strip beyond the lines
    static constexpr double kLineWidth = 0.05;    ///< m
    static constexpr double kCircleRadius = 0.6;  ///< m
    static constexpr double kGoalAreaDepth = 0.6; ///< m
    static constexpr double kGoalAreaWidth = 2.2; ///< m
    static constexpr double kPenaltyMark = 1.8;   ///< m from the goal line
    static constexpr double kGoalWidth = 1.5;     ///< m between the posts' inner faces
    static constexpr double kPostDiameter = 0.1;  ///< m
    static constexpr double kPostHeight = 0.8;    ///< m
    static constexpr double kBallDiameter = 0.14; ///< m (the rules allow 6.5 to 15 cm)
    static constexpr double kCarpetHalfLength = kLength / 2 + kBorder; ///< m
    static constexpr double kCarpetHalfWidth = kWidth / 2 + kBorder;   ///< m
};

struct LineSegment
{
    Eigen::Vector2d a; ///< m, field frame
    Eigen::Vector2d b; ///< m
};
/// The straight field lines: touch, goal and halfway lines and the goal-area lines.
const std::vector<LineSegment>& straightFieldLines();

using Rgbf = Eigen::Vector3d; ///< r, g, b in 0..255 (sRGB values, lit multiplicatively)

/// What a primitive is for the ground truth.
enum class ObjectKind : std::uint8_t { Background, Ball, Post, Crossbar, Robot, Person };

struct Primitive
{
    enum class Shape : std::uint8_t { Sphere, Box, Cylinder };
    Shape shape = Shape::Box;
    Eigen::Vector3d centre{0, 0, 0}; ///< m; sphere centre, or the box/cylinder axis at z = 0
    double radius = 0;               ///< m, sphere and cylinder
    double half_x = 0;               ///< m, box half extent along its heading
    double half_y = 0;               ///< m, box half extent across its heading
    double z0 = 0;                   ///< m, box and cylinder bottom
    double z1 = 0;                   ///< m, box and cylinder top
    double cos_yaw = 1;              ///< box heading as cosine and sine (see setYaw)
    double sin_yaw = 0;
    Rgbf albedo{128, 128, 128};
    Colour label = Colour::Unclassified; ///< class of its pixels for the ideal LUT
    ObjectKind kind = ObjectKind::Background;
    int object = -1;                   ///< index into Scene::objects, or -1 for scenery
    bool counts_for_visibility = true; ///< part of the object's visibility test (obstacles)
    bool field_lit = true; ///< lit by the field lighting (gradient), not just the global level
    double ambient = 0.55; ///< share of light that does not depend on the surface normal
    double specular = 0;   ///< highlight strength

    void setYaw(double yaw) ///< rad
    {
        cos_yaw = std::cos(yaw);
        sin_yaw = std::sin(yaw);
    }
};

/// A box standing on the ground, turned by `heading` (rad), sizes in m.
Primitive makeBox(const Eigen::Vector2d& centre, double heading, double half_x, double half_y,
                  double z0, double z1, const Rgbf& albedo, Colour label);

/// Something the ground truth reports on (ball, posts, robots, people on the field).
struct SceneObject
{
    ObjectKind kind = ObjectKind::Background;
    Eigen::Vector3d position{0, 0, 0}; ///< m; ball centre, or the point where it stands
    double radius = 0;                 ///< m; ball radius, or footprint radius for shadows
    double height = 0;                 ///< m
};

/// A rectangle painted on a wall (poster, door, window, banner).
struct WallPatch
{
    int wall = 0;  ///< 0: +x, 1: -x, 2: +y, 3: -y
    double u0 = 0; ///< m, along the wall (world y for x walls, world x for y walls)
    double u1 = 0; ///< m
    double z0 = 0; ///< m
    double z1 = 0; ///< m
    Rgbf colour{128, 128, 128};
    bool stripes = false; ///< banner text: darker horizontal stripes
};

/// The room or hall around the field.
struct Surroundings
{
    double half_x = 6;  ///< m, walls at x = +-half_x
    double half_y = 5;  ///< m
    double ceiling = 4; ///< m
    Rgbf floor{110, 118, 150};
    Rgbf wall{190, 175, 150};
    Rgbf ceiling_colour{170, 165, 160};
    bool skirting = true; ///< a darker strip along the bottom of the walls
    std::vector<WallPatch> patches;
};

/// Light at one instant: global level times a field-frame gradient times soft spots.
struct Lighting
{
    double level = 1.0;       ///< global multiplier
    double gradient_x = 0;    ///< relative change per metre along +x on the field
    double spot_strength = 0; ///< amplitude of the overhead-lamp pattern
    std::uint64_t spot_seed = 0;
    double fieldFactor(double x, double y) const;
};

struct Scene
{
    CameraPose camera;
    Lighting lighting;
    Rgbf carpet{45, 125, 50};
    Rgbf line{232, 232, 232};
    std::uint64_t texture_seed = 0;
    Surroundings surroundings;
    std::vector<SceneObject> objects;
    std::vector<Primitive> primitives;
};

/// A ray's hit on a primitive: distance along the unit direction and the surface normal.
struct Hit
{
    double t = 0;
    Eigen::Vector3d normal{0, 0, 1};
};
std::optional<Hit> intersect(const Primitive& p, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& direction);

/// Builders for the things on the field; each appends its SceneObject (when it has one) and
/// primitives and returns the object's index.
int addBall(Scene& scene, const Eigen::Vector3d& centre);
/// Two posts (objects) centred on the goal line, the crossbar and the goal's dark back frame.
void addGoal(Scene& scene, double goal_line_x);
struct RobotLook
{
    Rgbf body{58, 58, 62};
    Rgbf limbs{36, 36, 40};
    Rgbf marker{40, 110, 215};
    Colour marker_label = Colour::Blue;
};
/// A DARwIn-OP-sized robot (0.45 m tall, 0.2 m wide) facing `heading` (rad).
int addRobot(Scene& scene, const Eigen::Vector2d& position, double heading, const RobotLook& look);
struct PersonLook
{
    Rgbf shirt{90, 100, 130};
    Rgbf trousers{60, 70, 110};
    Rgbf skin{215, 165, 135};
    Rgbf shoes{70, 60, 55};
    double height = 1.75; ///< m
};
/// A standing person. On the field it is an obstacle whose parts below 0.5 m decide its
/// visibility; off the field it is scenery (returns -1).
int addPerson(Scene& scene, const Eigen::Vector2d& position, double heading, const PersonLook& look,
              bool on_field);

} // namespace fieldsight::synth
