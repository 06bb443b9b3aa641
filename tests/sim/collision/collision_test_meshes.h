#pragma once
// Small meshes and poses for the collision tests and benchmarks. Header-only
// so that tests/bench can use it too; spheres come from sim/geometry/primitives.
#include <Eigen/Geometry>
#include <map>
#include <random>

#include "sim/collision/collision_types.h"
#include "sim/geometry/primitives.h"

namespace recoil::sim::testing {

// icosphere: unit radius about the origin, split `subdivisions` times (20 * 4^n triangles).
// box: axis-aligned with the given half extents, 12 outward triangles.
// grid: z-up square sheet of n by n cells of size `cell`, centred at the origin.
// moving_surface: x1 is x0 rotated about its centroid, then translated.


inline TriMesh icosphere(int subdivisions) { return make_sphere(1.0, subdivisions); }

inline TriMesh box(const Eigen::Vector3d& h) {
  TriMesh m;
  m.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    m.vertices.row(i) << ((i & 1) ? h.x() : -h.x()), ((i & 2) ? h.y() : -h.y()), ((i & 4) ? h.z() : -h.z());
  m.triangles.resize(12, 3);
  m.triangles << 0, 2, 1, 1, 2, 3,  // -z
      4, 5, 6, 5, 7, 6,             // +z
      0, 1, 4, 1, 5, 4,             // -y
      2, 6, 3, 3, 6, 7,             // +y
      0, 4, 2, 2, 4, 6,             // -x
      1, 3, 5, 3, 7, 5;             // +x
  return m;
}

inline TriMesh grid(int n, double cell) {
  TriMesh m;
  m.vertices.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      m.vertices.row(j * (n + 1) + i) << (i - 0.5 * n) * cell, (j - 0.5 * n) * cell, 0.0;
  m.triangles.resize(2 * n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.triangles.row(2 * (j * n + i)) << a, b, d;
      m.triangles.row(2 * (j * n + i) + 1) << a, d, c;
    }
  return m;
}

inline Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

inline void perturb(TriMesh& mesh, double amount, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-amount, amount);
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
    for (int k = 0; k < 3; ++k) mesh.vertices(i, k) += u(rng);
}

inline CollisionSurface moving_surface(const TriMesh& mesh, int body, BodyKind kind, const Eigen::Vector3d& translation,
                                const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  CollisionSurface s;
  s.body = body;
  s.kind = kind;
  s.x0 = mesh.vertices;
  s.triangles = mesh.triangles;
  const Eigen::RowVector3d centroid = mesh.vertices.colwise().mean();
  s.x1.resize(mesh.vertices.rows(), 3);
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
    s.x1.row(i) = (mesh.vertices.row(i) - centroid) * rotation.transpose() + centroid + translation.transpose();
  return s;
}

}  // namespace recoil::sim::testing
