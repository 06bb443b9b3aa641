#include "sim/geometry/mesh_stats.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>
#include <vector>

namespace recoil::sim {
namespace {

Eigen::Vector3d corner(const TriMesh& mesh, int f, int k) { return mesh.vertices.row(mesh.triangles(f, k)).transpose(); }

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

double enclosed_volume(const TriMesh& mesh) {
  // Sum of signed tetrahedra (origin, a, b, c); summed about the centroid of the
  // bounds to keep the terms small and the result accurate far from the origin.
  const Eigen::Vector3d centre = bounding_box(mesh).center();
  double six_volume = 0.0;
  for (int f = 0; f < mesh.num_triangles(); ++f) {
    const Eigen::Vector3d a = corner(mesh, f, 0) - centre, b = corner(mesh, f, 1) - centre,
                          c = corner(mesh, f, 2) - centre;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

double surface_area(const TriMesh& mesh) {
  double area = 0.0;
  for (int f = 0; f < mesh.num_triangles(); ++f)
    area += 0.5 * (corner(mesh, f, 1) - corner(mesh, f, 0)).cross(corner(mesh, f, 2) - corner(mesh, f, 0)).norm();
  return area;
}

MeshStats compute_mesh_stats(const TriMesh& mesh) {
  MeshStats stats;
  stats.vertices = mesh.num_vertices();
  stats.triangles = mesh.num_triangles();
  stats.bounds = bounding_box(mesh);
  stats.area = surface_area(mesh);
  stats.volume = enclosed_volume(mesh);

  // Directed half-edges grouped by their lower vertex (a counting sort: a
  // vertex has a handful, a full sort of millions cost a second), then by
  // the upper one: a closed, consistently oriented surface pairs every
  // (a, b) with exactly one (b, a).
  struct HalfEdge {
    int hi;
    bool forward;  // traversed lo -> hi
  };
  const size_t num_vertices = static_cast<size_t>(mesh.num_vertices());
  std::vector<size_t> start(num_vertices + 1, 0);  // half-edges of lower vertex v: [start[v], start[v + 1])
  for (int f = 0; f < mesh.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) ++start[static_cast<size_t>(std::min(mesh.triangles(f, k), mesh.triangles(f, (k + 1) % 3))) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<HalfEdge> edges(start.back());
  std::vector<size_t> fill(start.begin(), start.end() - 1);
  for (int f = 0; f < mesh.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      edges[fill[static_cast<size_t>(std::min(a, b))]++] = {std::max(a, b), a < b};
    }
  for (size_t v = 0; v < num_vertices; ++v) {
    const auto first = edges.begin() + static_cast<long>(start[v]), last = edges.begin() + static_cast<long>(start[v + 1]);
    std::sort(first, last, [](const HalfEdge& x, const HalfEdge& y) { return x.hi < y.hi; });
    for (auto i = first; i != last;) {
      auto j = i;
      int forward = 0;
      while (j != last && j->hi == i->hi) forward += (j++)->forward;
      const long count = j - i;
      if (count == 1) ++stats.boundary_edges;
      else if (count > 2) ++stats.non_manifold_edges;
      else if (forward != 1) ++stats.inconsistent_edges;
      i = j;
    }
  }
  stats.watertight = stats.triangles > 0 && stats.boundary_edges == 0 && stats.non_manifold_edges == 0 &&
                     stats.inconsistent_edges == 0;

  // Components: union-find over triangle corners; unused vertices do not count.
  std::vector<int> parent(static_cast<size_t>(mesh.num_vertices()));
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < mesh.num_triangles(); ++f)
    for (int k = 1; k < 3; ++k) {
      const int a = find_root(parent, mesh.triangles(f, 0)), b = find_root(parent, mesh.triangles(f, k));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<char> used(parent.size(), 0);
  for (int f = 0; f < mesh.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) used[mesh.triangles(f, k)] = 1;
  for (size_t v = 0; v < parent.size(); ++v)
    if (used[v] && find_root(parent, static_cast<int>(v)) == static_cast<int>(v)) ++stats.components;
  return stats;
}

}  // namespace recoil::sim
