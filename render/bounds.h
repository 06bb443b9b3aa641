#pragma once
// Bounds: the axis-aligned box of a mesh's positions, or of several meshes'.
#include <Eigen/Core>
#include <limits>
#include <vector>

namespace recoil::render {

// [lo, hi] in metres; empty when lo > hi.
struct Bounds {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return lo.x() > hi.x(); }
  void add(const Bounds& other) {
    lo = lo.cwiseMin(other.lo);
    hi = hi.cwiseMax(other.hi);
  }
};

// The box of `positions` (#V*3 floats); empty for no vertex.
Bounds bounds_of(const std::vector<float>& positions);

}  // namespace recoil::render
