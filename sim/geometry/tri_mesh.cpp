#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

Aabb bounding_box(const Points& points) {
  Aabb box;
  for (Eigen::Index i = 0; i < points.rows(); ++i) box.extend(points.row(i).transpose());
  return box;
}

void transform_in_place(TriMesh& mesh, const Eigen::Matrix3d& rotation,
                        const Eigen::Vector3d& scale, const Eigen::Vector3d& translation) {
  for (int i = 0; i < mesh.num_vertices(); ++i) {
    const Eigen::Vector3d p = mesh.vertices.row(i).transpose();
    mesh.vertices.row(i) = (rotation * scale.cwiseProduct(p) + translation).transpose();
  }
  if (scale.prod() < 0.0) flip_winding(mesh);
}

void flip_winding(TriMesh& mesh) {
  mesh.triangles.col(1).swap(mesh.triangles.col(2));
  if (mesh.look) mesh.look = std::make_shared<const SurfaceLook>(with_swapped_corners(*mesh.look));
}

void append(TriMesh& mesh, const TriMesh& other) {
  const int v0 = mesh.num_vertices();
  const int f0 = mesh.num_triangles();
  mesh.vertices.conservativeResize(v0 + other.num_vertices(), 3);
  mesh.vertices.bottomRows(other.num_vertices()) = other.vertices;
  mesh.triangles.conservativeResize(f0 + other.num_triangles(), 3);
  mesh.triangles.bottomRows(other.num_triangles()) = other.triangles.array() + v0;
  mesh.look.reset();
}

}  // namespace recoil::sim
