#include "sim/geometry/tetrahedralize.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "sim/geometry/winding_number.h"

namespace recoil::sim {

namespace {

// Corner c of a cell: bit 0 -> +x, bit 1 -> +y, bit 2 -> +z. The six tets walk
// from corner 0 to corner 7 along the three axes in every order.
constexpr int kKuhnTets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                 {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

}  // namespace

bool triangle_overlaps_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                           const Eigen::Vector3d& box_center, const Eigen::Vector3d& half_extent) {
  const Eigen::Vector3d v[3] = {a - box_center, b - box_center, c - box_center};
  const Eigen::Vector3d e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  auto separated = [&](const Eigen::Vector3d& axis) {
    const double p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
    const double r = half_extent.cwiseProduct(axis.cwiseAbs()).sum();
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
  };
  for (int i = 0; i < 3; ++i)
    if (separated(Eigen::Vector3d::Unit(i))) return false;
  if (separated(e[0].cross(e[1]))) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d axis = Eigen::Vector3d::Unit(i).cross(e[j]);
      if (axis.squaredNorm() > 0.0 && separated(axis)) return false;
    }
  return true;
}

CubicGrid cubic_grid(const Aabb& box, int resolution) {
  CubicGrid grid;
  grid.cell = box.extent().maxCoeff() / resolution;
  for (int a = 0; a < 3; ++a)
    grid.cells[a] = std::max(1, static_cast<int>(std::ceil(box.extent()[a] / grid.cell - 1e-9)));
  grid.origin = box.center() - 0.5 * grid.cell * grid.cells.cast<double>();
  return grid;
}

bool inside_by_winding_number(double winding_number) { return std::abs(winding_number) > 0.5; }

TetMesh tetrahedralize(const TriMesh& surface, int resolution, TetrahedralizeStats* stats) {
  if (surface.empty()) throw bad_input("tetrahedralize: the surface has no triangles");
  if (resolution < 1 || resolution > 512)
    throw bad_input("tets.resolution must be in [1, 512], got " + std::to_string(resolution));
  const Aabb box = bounding_box(surface);
  const double longest = box.extent().maxCoeff();
  if (!(longest > 0.0) || !std::isfinite(longest)) throw bad_input("tetrahedralize: the surface has no extent");
  const CubicGrid grid = cubic_grid(box, resolution);
  const double h = grid.cell;
  const Eigen::Vector3i n = grid.cells;
  const Eigen::Vector3d origin = grid.origin;
  auto cell_id = [&](int i, int j, int k) { return (static_cast<long>(k) * n[1] + j) * n[0] + i; };
  const long num_cells = static_cast<long>(n[0]) * n[1] * n[2];

  // Cells crossed by the surface: each triangle visits the cells of its box.
  std::vector<char> keep(static_cast<size_t>(num_cells), 0);
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5 * h * (1.0 + 1e-9));
  int crossing = 0;
  for (int f = 0; f < surface.num_triangles(); ++f) {
    const Eigen::Vector3d p[3] = {surface.vertices.row(surface.triangles(f, 0)).transpose(),
                                  surface.vertices.row(surface.triangles(f, 1)).transpose(),
                                  surface.vertices.row(surface.triangles(f, 2)).transpose()};
    Eigen::Vector3i lo, hi;
    for (int a = 0; a < 3; ++a) {
      const double mn = std::min({p[0][a], p[1][a], p[2][a]}), mx = std::max({p[0][a], p[1][a], p[2][a]});
      lo[a] = std::clamp(static_cast<int>(std::floor((mn - origin[a]) / h)) - 1, 0, n[a] - 1);
      hi[a] = std::clamp(static_cast<int>(std::floor((mx - origin[a]) / h)) + 1, 0, n[a] - 1);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          char& kept = keep[static_cast<size_t>(cell_id(i, j, k))];
          if (kept) continue;
          const Eigen::Vector3d c = grid.center(i, j, k);
          if (triangle_overlaps_box(p[0], p[1], p[2], c, half)) {
            kept = 1;
            ++crossing;
          }
        }
  }

  // The remaining cells: inside by the winding number at their centre. A
  // centre is at least h/2 from every triangle (none overlaps its cell), so
  // the tree's far-field clusters are never the ones it lies against.
  const WindingNumberTree winding(surface);
  int inside = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        char& kept = keep[static_cast<size_t>(cell_id(i, j, k))];
        if (kept) continue;
        if (inside_by_winding_number(winding(grid.center(i, j, k)))) {
          kept = 2;
          ++inside;
        }
      }

  // Number the used grid vertices in grid order, then emit six tets per cell.
  const Eigen::Vector3i nv = n + Eigen::Vector3i::Ones();
  auto vertex_id = [&](int i, int j, int k) { return (static_cast<long>(k) * nv[1] + j) * nv[0] + i; };
  std::vector<int> node_of(static_cast<size_t>(nv.cast<long>().prod()), -1);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        if (keep[static_cast<size_t>(cell_id(i, j, k))])
          for (int c = 0; c < 8; ++c)
            node_of[static_cast<size_t>(vertex_id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)))] = 0;
  int num_nodes = 0;
  for (int& id : node_of)
    if (id == 0) id = num_nodes++;
    else id = -1;
  // The loop above sets unused entries to -1 and used ones to their number.

  TetMesh mesh;
  mesh.nodes.resize(num_nodes, 3);
  for (int k = 0; k < nv[2]; ++k)
    for (int j = 0; j < nv[1]; ++j)
      for (int i = 0; i < nv[0]; ++i) {
        const int id = node_of[static_cast<size_t>(vertex_id(i, j, k))];
        if (id >= 0) mesh.nodes.row(id) = (origin + h * Eigen::Vector3d(i, j, k)).transpose();
      }
  mesh.tets.resize(6 * static_cast<Eigen::Index>(crossing + inside), 4);
  Eigen::Index t = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        if (!keep[static_cast<size_t>(cell_id(i, j, k))]) continue;
        int corner[8];
        for (int c = 0; c < 8; ++c)
          corner[c] = node_of[static_cast<size_t>(vertex_id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)))];
        // A cell odd along an axis takes the split mirrored across it (corner
        // index XOR the parity bits), so the lattice prefers no direction; a
        // face's diagonal depends only on the parities of the two axes it
        // spans, which both its cells share, so neighbours agree on it.
        const int parity = (i & 1) | ((j & 1) << 1) | ((k & 1) << 2);
        for (const auto& tet : kKuhnTets) {
          for (int q = 0; q < 4; ++q) mesh.tets(t, q) = corner[tet[q] ^ parity];
          if (tet_volume(mesh, static_cast<int>(t)) < 0.0) std::swap(mesh.tets(t, 2), mesh.tets(t, 3));
          ++t;
        }
      }
  if (stats) *stats = {crossing, inside, h};
  return mesh;
}

}  // namespace recoil::sim
