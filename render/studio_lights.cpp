#include "render/studio_lights.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace recoil::render {
namespace {

// Direction at (azimuth, elevation) in degrees about the subject, azimuth 0
// being the camera's side and positive azimuth to the camera's right.
Eigen::Vector3d around(const Eigen::Vector3d& back, const Eigen::Vector3d& right, double azimuth_deg,
                       double elevation_deg) {
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  const double el = elevation_deg * std::numbers::pi / 180.0;
  const Eigen::Vector3d horizontal = std::cos(az) * back + std::sin(az) * right;
  return (std::cos(el) * horizontal + std::sin(el) * Eigen::Vector3d::UnitY()).normalized();
}

}  // namespace

StudioLights studio_lights(const Camera& camera) {
  // The camera's horizontal frame; a camera looking straight down keeps the
  // rig's orientation from its `up` vector instead.
  Eigen::Vector3d back = camera.eye - camera.target;
  back.y() = 0.0;
  if (back.squaredNorm() < 1e-12 * std::max(1.0, (camera.eye - camera.target).squaredNorm())) {
    back = -Eigen::Vector3d(camera.up.x(), 0.0, camera.up.z());
    if (back.squaredNorm() < 1e-12) back = Eigen::Vector3d::UnitZ();
  }
  back.normalize();
  const Eigen::Vector3d right = Eigen::Vector3d::UnitY().cross(back).normalized();

  StudioLights lights;
  lights.key = {around(back, right, 50.0, 45.0), Eigen::Vector3f(1.00f, 0.96f, 0.90f) * 0.95f};
  lights.fill = {around(back, right, -60.0, 20.0), Eigen::Vector3f(0.80f, 0.88f, 1.00f) * 0.30f};
  lights.rim = {around(back, right, 165.0, 35.0), Eigen::Vector3f(1.00f, 1.00f, 1.00f) * 0.55f};
  lights.sky_ambient = Eigen::Vector3f(0.55f, 0.62f, 0.75f) * 0.16f;
  lights.ground_ambient = Eigen::Vector3f(0.50f, 0.45f, 0.40f) * 0.06f;
  return lights;
}

}  // namespace recoil::render
