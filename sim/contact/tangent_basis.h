#pragma once
// A deterministic orthonormal tangent basis (t1, t2) for a unit normal n with
// (n, t1, t2) right-handed, continuous in n except across n.z = 0 from below
// (Duff et al. 2017, "Building an orthonormal basis, revisited"): the ground
// normal +y and every normal near it get one smooth basis.
#include <Eigen/Core>
#include <cmath>

namespace recoil::sim {

struct TangentBasis {
  Eigen::Vector3d t1, t2;
};

inline TangentBasis tangent_basis(const Eigen::Vector3d& n) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  TangentBasis out;
  out.t1 = Eigen::Vector3d(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  out.t2 = Eigen::Vector3d(b, sign + n.y() * n.y() * a, -n.y());
  return out;
}

}  // namespace recoil::sim
