#pragma once
// TriMesh: an indexed triangle surface, the common currency of import,
// primitives, rendering hand-off and collision surfaces.
#include <Eigen/Core>
#include <limits>
#include <memory>

#include "sim/geometry/surface_look.h"

namespace recoil::sim {

// Row-major so that a row is one contiguous xyz / ijk triple (Embree and GL
// buffers copy straight from it).
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct TriMesh {
  Points vertices;       // #V by 3, metres
  Triangles triangles;   // #F by 3, counter-clockwise seen from outside
  // How an imported surface is drawn, one entry per triangle; null for
  // surfaces that are not drawn as imported (primitives, collision copies).
  std::shared_ptr<const SurfaceLook> look;

  int num_vertices() const { return static_cast<int>(vertices.rows()); }
  int num_triangles() const { return static_cast<int>(triangles.rows()); }
  bool empty() const { return triangles.rows() == 0; }
};

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  void extend(const Eigen::Vector3d& p) { min = min.cwiseMin(p); max = max.cwiseMax(p); }
  Eigen::Vector3d center() const { return 0.5 * (min + max); }
  Eigen::Vector3d extent() const { return max - min; }
  bool valid() const { return (min.array() <= max.array()).all(); }
};

// The box around a #N by 3 point list (invalid when it is empty).
Aabb bounding_box(const Points& points);
inline Aabb bounding_box(const TriMesh& mesh) { return bounding_box(mesh.vertices); }

// Row i of a #V by 3 point list as a column vector.
inline Eigen::Vector3d point_at(const Points& points, int i) { return points.row(i).transpose(); }

// Applies p -> R * (s .* p) + t to every vertex; flips winding (and the
// look's corners) when the scale has a negative determinant so triangles stay
// outward-facing.
void transform_in_place(TriMesh& mesh, const Eigen::Matrix3d& rotation,
                        const Eigen::Vector3d& scale, const Eigen::Vector3d& translation);

// Turns every triangle over (corners 1 and 2 swapped, the look's with them).
void flip_winding(TriMesh& mesh);

// Appends `other` to `mesh`, re-indexing its triangles; the result has no look.
void append(TriMesh& mesh, const TriMesh& other);

}  // namespace recoil::sim
