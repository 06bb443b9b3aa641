#include "render/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/check.h"

namespace recoil::render {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

Eigen::Matrix4d Camera::view_matrix() const {
  const Eigen::Vector3d forward = (target - eye).normalized();
  Eigen::Vector3d right = forward.cross(up);
  // Looking along `up` leaves no horizon: pick any perpendicular instead.
  if (right.squaredNorm() < 1e-20) right = forward.cross(Eigen::Vector3d::UnitZ());
  if (right.squaredNorm() < 1e-20) right = forward.cross(Eigen::Vector3d::UnitX());
  right.normalize();
  const Eigen::Vector3d true_up = right.cross(forward);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = true_up.transpose();
  view.block<1, 3>(2, 0) = -forward.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -true_up.dot(eye);
  view(2, 3) = forward.dot(eye);
  return view;
}

Eigen::Matrix4d Camera::projection_matrix(double aspect, double near_plane, double far_plane) const {
  RECOIL_CHECK(near_plane > 0 && far_plane > near_plane && aspect > 0,
               "near=" << near_plane << " far=" << far_plane << " aspect=" << aspect);
  const double f = 1.0 / std::tan(radians(fov_y_degrees) / 2.0);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  p(2, 3) = 2.0 * far_plane * near_plane / (near_plane - far_plane);
  p(3, 2) = -1.0;
  return p;
}

DepthRange depth_range(const Camera& camera, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
  double nearest = std::numeric_limits<double>::infinity();
  double farthest = -std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                            (corner & 4) ? hi.z() : lo.z());
    const double depth = (p - camera.eye).dot(forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  DepthRange range;
  const double slack = 0.01 * std::max(farthest - nearest, 1e-6);
  range.far_plane = std::max(farthest + slack, 1e-3);
  range.near_plane = std::max(nearest - slack, range.far_plane * 1e-4);
  return range;
}

Camera frame_bounding_sphere(const Eigen::Vector3d& center, double radius, double azimuth_deg,
                             double elevation_deg, double fov_y_deg, double aspect, double margin) {
  RECOIL_CHECK(radius > 0 && fov_y_deg > 0 && fov_y_deg < 180 && aspect > 0,
               "radius=" << radius << " fov=" << fov_y_deg << " aspect=" << aspect);
  const double half_v = radians(fov_y_deg) / 2.0;
  const double half_h = std::atan(std::tan(half_v) * aspect);
  // The sphere touches the frustum's sides when sin(half angle) = r / d.
  const double distance = margin * radius / std::sin(std::min(half_v, half_h));
  const double az = radians(azimuth_deg);
  const double el = radians(elevation_deg);
  Camera camera;
  camera.target = center;
  camera.eye = center + distance * Eigen::Vector3d(std::cos(el) * std::sin(az), std::sin(el),
                                                   std::cos(el) * std::cos(az));
  camera.fov_y_degrees = fov_y_deg;
  return camera;
}

double orbit_azimuth_deg(int frame, int frame_count, double turns, double start_deg) {
  RECOIL_CHECK(frame_count > 0, "frame_count=" << frame_count);
  return start_deg + 360.0 * turns * static_cast<double>(frame) / static_cast<double>(frame_count);
}

Camera orbit(const Camera& camera, double azimuth_deg) {
  const Eigen::AngleAxisd rotation(radians(azimuth_deg), Eigen::Vector3d::UnitY());
  Camera result = camera;
  result.eye = camera.target + rotation * (camera.eye - camera.target);
  return result;
}

}  // namespace recoil::render
