#pragma once
// A scene body's `transform`, shared by the deformable and rigid descriptions.
#include <Eigen/Core>

namespace recoil::sim {

// p_world = R (scale .* p) + position with R = Rz Ry Rx (Euler degrees
// applied about world x, then y, then z).
struct Transform {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();  // degrees about x, y, z
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  Eigen::Matrix3d rotation_matrix() const;
};

}  // namespace recoil::sim
