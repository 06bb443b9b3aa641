#pragma once
// The cross-product matrix of a 3-vector, [a]x with [a]x b = a x b, used by
// the rigid-body pose update, the rigid contact rows, the Neo-Hookean
// cofactor derivative and the rigid modes of the momentum preconditioner.
#include <Eigen/Core>

namespace recoil::sim {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace recoil::sim
