#include "sim/rigid/mass_properties.h"

#include <Eigen/Geometry>

namespace recoil::sim {

namespace {

// From the solid's volume (m^3), first moment (m^4) and second moment
// integral of x x^T (m^5) about the origin.
MassProperties from_moments(double volume, const Eigen::Vector3d& first, const Eigen::Matrix3d& second,
                            double density) {
  MassProperties out;
  out.volume = volume;
  out.mass = density * volume;
  if (volume == 0.0) return out;
  out.center = first / volume;
  // Second moment about the centre, then I = tr(C) 1 - C.
  const Eigen::Matrix3d c = density * (second - volume * out.center * out.center.transpose());
  out.inertia = c.trace() * Eigen::Matrix3d::Identity() - c;
  out.inertia = 0.5 * (out.inertia + out.inertia.transpose()).eval();
  return out;
}

}  // namespace

MassProperties mass_properties(const TriMesh& mesh, double density) {
  // Per tetrahedron (0, a, b, c) with D = a.(b x c) (six times its signed
  // volume): volume D/6, first moment D/24 (a+b+c), second moment
  // integral of x x^T = D/120 (sum_i v_i v_i^T + s s^T) with s = a+b+c.
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int f = 0; f < mesh.num_triangles(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0)).transpose();
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1)).transpose();
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2)).transpose();
    const double d = a.dot(b.cross(c));
    const Eigen::Vector3d s = a + b + c;
    volume += d / 6.0;
    first += d / 24.0 * s;
    second += d / 120.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  return from_moments(volume, first, second, density);
}

MassProperties mass_properties(const TetMesh& solid, double density) {
  // Per tetrahedron (v0..v3) of volume V: first moment V/4 s, second moment
  // V/20 (sum_i v_i v_i^T + s s^T), with s = v0 + v1 + v2 + v3.
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int t = 0; t < solid.num_tets(); ++t) {
    const double v = tet_volume(solid.nodes, solid.tets, t);
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d p = solid.nodes.row(solid.tets(t, k)).transpose();
      s += p;
      outer += p * p.transpose();
    }
    volume += v;
    first += v / 4.0 * s;
    second += v / 20.0 * (outer + s * s.transpose());
  }
  return from_moments(volume, first, second, density);
}

MassProperties mass_properties(const WindingSolid& solid, double density) {
  // Per cube of side h about centre c: volume h^3, first moment h^3 c, second
  // moment h^3 (c c^T + h^2/12 1).
  const double v = solid.cell * solid.cell * solid.cell;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& c : solid.centers) {
    first += c;
    outer += c * c.transpose();
  }
  const double count = static_cast<double>(solid.centers.size());
  const Eigen::Matrix3d second = v * (outer + count * solid.cell * solid.cell / 12.0 * Eigen::Matrix3d::Identity());
  return from_moments(solid.volume(), v * first, second, density);
}

}  // namespace recoil::sim
