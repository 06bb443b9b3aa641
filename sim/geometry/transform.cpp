#include "sim/geometry/transform.h"

#include <Eigen/Geometry>
#include <numbers>

namespace recoil::sim {

Eigen::Matrix3d Transform::rotation_matrix() const {
  constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(rotation.z() * kRadiansPerDegree, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rotation.y() * kRadiansPerDegree, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rotation.x() * kRadiansPerDegree, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace recoil::sim
