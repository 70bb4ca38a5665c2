// The generator's pinhole camera.
#include "synth/camera_model.h"

#include <Eigen/Geometry>

#include <cmath>

namespace fieldsight::synth {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

CameraModel::CameraModel(int width, int height, double fov_x_deg, double fov_y_deg)
    : m_width(width), m_height(height), m_cx(width / 2.0), m_cy(height / 2.0)
{
    m_fx = m_cx / std::tan(fov_x_deg * kPi / 360.0);
    // fov_y is a 4:3 frame's: another shape (16:9 HD) keeps fov_x and the 4:3 frame's pixel shape,
    // so it sees less above and below rather than stretching the scene. 0.375 * width is exactly
    // height / 2 for 4:3 frames, which come out as they always did.
    m_fy = 0.375 * width / std::tan(fov_y_deg * kPi / 360.0);
    setPose(CameraPose{});
}

double CameraModel::fovYDeg() const
{
    return 360.0 / kPi * std::atan(m_cy / m_fy);
}

void CameraModel::setPose(const CameraPose& pose)
{
    m_pose = pose;
    // With no rotation the camera looks along +x: right = -y, down = -z, forward = +x.
    Eigen::Matrix3d base;
    base.col(0) = Eigen::Vector3d(0, -1, 0);
    base.col(1) = Eigen::Vector3d(0, 0, -1);
    base.col(2) = Eigen::Vector3d(1, 0, 0);
    const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(pose.yaw, Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(pose.pitch, Eigen::Vector3d::UnitY()) *
                                      Eigen::AngleAxisd(pose.roll, Eigen::Vector3d::UnitX()))
                                         .toRotationMatrix();
    m_camera_to_world = rotation * base;
}

Eigen::Vector3d CameraModel::toCamera(const Eigen::Vector3d& world) const
{
    return m_camera_to_world.transpose() * (world - m_pose.position);
}

Eigen::Vector3d CameraModel::directionToWorld(const Eigen::Vector3d& camera_direction) const
{
    return m_camera_to_world * camera_direction;
}

std::optional<PointF> CameraModel::project(const Eigen::Vector3d& world) const
{
    const Eigen::Vector3d c = toCamera(world);
    if (c.z() <= 1e-9)
        return std::nullopt;
    return projectCamera(c);
}

PointF CameraModel::projectCamera(const Eigen::Vector3d& camera) const
{
    return {m_cx + m_fx * camera.x() / camera.z(), m_cy + m_fy * camera.y() / camera.z()};
}

Eigen::Vector3d CameraModel::rayDirection(double u, double v) const
{
    const Eigen::Vector3d d((u - m_cx) / m_fx, (v - m_cy) / m_fy, 1.0);
    return (m_camera_to_world * d).normalized();
}

double CameraModel::apparentRadius(const Eigen::Vector3d& centre, double radius) const
{
    return m_fx * radius / (centre - m_pose.position).norm();
}

std::vector<PointF> CameraModel::sphereOutline(const Eigen::Vector3d& centre, double radius,
                                               int points) const
{
    const Eigen::Vector3d c = toCamera(centre);
    const double d = c.norm();
    if (d <= radius)
        return {};
    const Eigen::Vector3d axis = c / d;
    const double sin_a = radius / d;
    const double cos_a = std::sqrt(1 - sin_a * sin_a);
    if (axis.z() * cos_a - std::sqrt(1 - axis.z() * axis.z()) * sin_a <= 1e-6)
        return {}; // part of the cone is not in front of the camera
    const Eigen::Vector3d e1 = axis.unitOrthogonal();
    const Eigen::Vector3d e2 = axis.cross(e1);
    std::vector<PointF> outline;
    outline.reserve(std::size_t(points));
    for (int i = 0; i < points; ++i) {
        const double phi = 2 * kPi * i / points;
        const Eigen::Vector3d ray =
            cos_a * axis + sin_a * (std::cos(phi) * e1 + std::sin(phi) * e2);
        outline.push_back(projectCamera(ray));
    }
    return outline;
}

Horizon CameraModel::horizon() const
{
    // A ray (a, b, 1) in normalised camera coordinates is horizontal when its world z is 0:
    // m0 a + m1 b + m2 = 0 with m the world-z row of the camera-to-world rotation.
    const Eigen::RowVector3d m = m_camera_to_world.row(2);
    auto yAt = [&](double u) {
        const double a = (u - m_cx) / m_fx;
        if (std::abs(m(1)) < 1e-12) // looking straight up or down: no horizon in the image
            return m(2) < 0 ? -1e6 : 1e6;
        const double b = -(m(0) * a + m(2)) / m(1);
        return m_cy + m_fy * b;
    };
    return {yAt(0), yAt(m_width - 1)};
}

} // namespace fieldsight::synth
