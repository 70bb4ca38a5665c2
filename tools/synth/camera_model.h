// The generator's pinhole camera: a robot's head camera with a pose in the field frame.
#pragma once

#include "visioncore/basics/geometry.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace fieldsight::synth {

/// Where the camera is and where it looks. Field frame: origin at the centre spot, x towards the
/// +x goal, y to the left, z up, metres.
struct CameraPose
{
    Eigen::Vector3d position{0, 0, 0.45}; ///< m
    double yaw = 0;   ///< rad, heading of the optical axis, counter-clockwise from +x
    double pitch = 0; ///< rad, positive looks down
    double roll = 0;  ///< rad, about the optical axis; positive lowers the image's right side
};

/// Pinhole model matching the original Transformer (design §2.9): the optical axis meets the image
/// at (width/2, height/2), f_x = (width/2) / tan(fov_x/2), f_y = (height/2) / tan(fov_y/2), with
/// fov_y that of a 4:3 frame: a frame of another shape has f_y = (3/8 width) / tan(fov_y/2), the
/// 4:3 frame's pixel shape (a 1280x720 frame sees 62.8 x 37.58 degrees).
/// Image coordinates are continuous px with pixel (x, y)'s centre at (x, y).
class CameraModel
{
public:
    CameraModel(int width, int height, double fov_x_deg = 62.8, double fov_y_deg = 48.8);

    void setPose(const CameraPose& pose);
    const CameraPose& pose() const { return m_pose; }

    int width() const { return m_width; }
    double fovYDeg() const; ///< the vertical field of view this frame size sees
    int height() const { return m_height; }
    double fx() const { return m_fx; } ///< px
    double fy() const { return m_fy; } ///< px
    double cx() const { return m_cx; } ///< px
    double cy() const { return m_cy; } ///< px

    /// World point in camera coordinates: x right, y down, z forward (m).
    Eigen::Vector3d toCamera(const Eigen::Vector3d& world) const;
    /// Camera-frame direction to world direction.
    Eigen::Vector3d directionToWorld(const Eigen::Vector3d& camera_direction) const;
    /// Image position of a world point, or nothing when it is not in front of the camera.
    std::optional<PointF> project(const Eigen::Vector3d& world) const;
    /// Image position of a camera-frame point with z > 0.
    PointF projectCamera(const Eigen::Vector3d& camera) const;
    /// Unit world direction of the ray through image point (u, v).
    Eigen::Vector3d rayDirection(double u, double v) const;
    /// Apparent radius (px) of a sphere: f_x * radius / distance from the camera centre.
    double apparentRadius(const Eigen::Vector3d& centre, double radius) const;
    /// The image outline of a sphere (where its tangent cone from the camera meets the image):
    /// `points` image points, a convex loop. Empty when the sphere is not wholly in front.
    std::vector<PointF> sphereOutline(const Eigen::Vector3d& centre, double radius,
                                      int points = 360) const;
    /// Where the ground plane at infinity projects: image y at x = 0 and x = width-1.
    Horizon horizon() const;

private:
    int m_width;
    int m_height;
    double m_fx;
    double m_fy;
    double m_cx;
    double m_cy;
    CameraPose m_pose;
    Eigen::Matrix3d m_camera_to_world; ///< columns: the camera's right, down and forward axes
};

} // namespace fieldsight::synth
