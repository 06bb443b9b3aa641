#include "sim/collision/local_deformation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/check.h"
#include "sim/collision/rest_clearance.h"

namespace recoil::sim {
namespace {

// Integer cell coordinates of the grid laid from `origin` with side `size`.
struct Grid {
  Eigen::Vector3d origin;
  double size = 0.0;
  Eigen::Matrix<int64_t, 3, 1> cells;  // along x, y, z

  int64_t axis(double x, int a) const {
    const int64_t c = static_cast<int64_t>(std::floor((x - origin[a]) / size));
    return std::clamp<int64_t>(c, 0, cells[a] - 1);
  }
  int64_t key(int64_t i, int64_t j, int64_t k) const { return i + cells[0] * (j + cells[1] * k); }
  Eigen::Matrix<int64_t, 3, 1> coordinates(int64_t key) const {
    return {key % cells[0], key / cells[0] % cells[1], key / (cells[0] * cells[1])};
  }
};

}  // namespace

RestCells rest_cells(const Points& rest, const Triangles& triangles, const std::vector<std::array<int, 2>>& edges,
                     double reach) {
  RestCells out;
  out.reach = reach;
  const double size = 2.0 * reach;
  const int nv = static_cast<int>(rest.rows());
  // No cells: every primitive in cell -1, excused by the whole-surface bound alone.
  auto without_cells = [&] {
    out.vertex_cell.assign(static_cast<size_t>(nv), -1);
    out.edge_start.resize(edges.size() + 1);
    for (size_t e = 0; e <= edges.size(); ++e) out.edge_start[e] = static_cast<int>(e);
    out.edge_cells.assign(edges.size(), -1);
    out.near_start = {0};
    return out;
  };
  if (nv == 0 || !(reach > 0.0) || !std::isfinite(reach)) return without_cells();
  const Aabb box = bounding_box(rest);
  Grid grid{box.min, size, {}};
  double numbered = 1.0;  // cells in the grid's box, which the int64 keys must number
  for (int a = 0; a < 3; ++a) {
    const double along = std::floor(box.extent()[a] / size) + 1.0;
    numbered *= along;
    grid.cells[a] = static_cast<int64_t>(std::min(along, 1e15));
  }
  if (!(numbered < 1e15)) return without_cells();
  auto key_at = [&](const Eigen::Vector3d& p) {
    return grid.key(grid.axis(p.x(), 0), grid.axis(p.y(), 1), grid.axis(p.z(), 2));
  };
  // Each edge is sampled at points at most `reach` apart, ends included.
  std::vector<int> pieces(edges.size());
  double sampled = 0.0;
  for (size_t e = 0; e < edges.size(); ++e) {
    const double length = (point_at(rest, edges[e][0]) - point_at(rest, edges[e][1])).norm();
    pieces[e] = static_cast<int>(std::min(std::ceil(length / reach), 1e9));
    sampled += pieces[e] + 1.0;
  }
  // Edges much longer than the reach (a margin far finer than the mesh) would
  // need more samples than the search could ever save: no local bound then.
  if (!(sampled <= 64.0 * static_cast<double>(nv + static_cast<int>(edges.size())))) return without_cells();

  // The grid keys of the vertices, then of every edge's samples, edge after edge.
  std::vector<int64_t> point_keys;
  point_keys.reserve(static_cast<size_t>(nv + sampled));
  for (int v = 0; v < nv; ++v) point_keys.push_back(key_at(point_at(rest, v)));
  for (size_t e = 0; e < edges.size(); ++e) {
    const Eigen::Vector3d p = point_at(rest, edges[e][0]), q = point_at(rest, edges[e][1]);
    const int n = pieces[e];
    for (int i = 0; i <= n; ++i)
      point_keys.push_back(key_at(n == 0 ? p : Eigen::Vector3d(p + (q - p) * (static_cast<double>(i) / n))));
  }
  // The occupied cells, ascending by key: cell index = position in `keys`.
  std::vector<int64_t> keys = point_keys;
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  auto cell_of = [&](int64_t key) {
    const auto it = std::lower_bound(keys.begin(), keys.end(), key);
    return it != keys.end() && *it == key ? static_cast<int>(it - keys.begin()) : -1;
  };
  out.vertex_cell.resize(static_cast<size_t>(nv));
  for (int v = 0; v < nv; ++v) out.vertex_cell[static_cast<size_t>(v)] = cell_of(point_keys[static_cast<size_t>(v)]);
  std::vector<std::vector<int>> near(keys.size());
  // A vertex no triangle uses is still a primitive of its own cell.
  for (int v = 0; v < nv; ++v) near[static_cast<size_t>(out.vertex_cell[static_cast<size_t>(v)])].push_back(v);
  out.edge_start.push_back(0);
  size_t next = static_cast<size_t>(nv);  // the first sample key of the edge
  for (size_t e = 0; e < edges.size(); ++e) {
    const auto first = out.edge_cells.end() - out.edge_cells.begin();
    for (int i = 0; i <= pieces[e]; ++i) out.edge_cells.push_back(cell_of(point_keys[next++]));
    std::sort(out.edge_cells.begin() + first, out.edge_cells.end());
    out.edge_cells.erase(std::unique(out.edge_cells.begin() + first, out.edge_cells.end()), out.edge_cells.end());
    out.edge_start.push_back(static_cast<int>(out.edge_cells.size()));
  }

  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    Aabb tri;
    for (int k = 0; k < 3; ++k) tri.extend(point_at(rest, triangles(f, k)));
    // A cell [c, c + size) comes within 1.5 reach of the box when c + size > min - 1.5 reach and c <= max + 1.5 reach.
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = grid.axis(tri.min[a] - 1.5 * reach, a);
      hi[a] = grid.axis(tri.max[a] + 1.5 * reach, a);
    }
    auto add = [&](int c) {
      for (int m = 0; m < 3; ++m) near[static_cast<size_t>(c)].push_back(triangles(f, m));
    };
    double span = 1.0;  // cells in the range
    for (int a = 0; a < 3; ++a) span *= static_cast<double>(hi[a] - lo[a] + 1);
    if (span > static_cast<double>(keys.size())) {
      // A sliver across much of the grid: fewer occupied cells than cells in its range.
      for (size_t c = 0; c < keys.size(); ++c) {
        const Eigen::Matrix<int64_t, 3, 1> at = grid.coordinates(keys[c]);
        bool inside = true;
        for (int a = 0; a < 3; ++a) inside = inside && at[a] >= lo[a] && at[a] <= hi[a];
        if (inside) add(static_cast<int>(c));
      }
      continue;
    }
    for (int64_t k = lo[2]; k <= hi[2]; ++k)
      for (int64_t j = lo[1]; j <= hi[1]; ++j)
        for (int64_t i = lo[0]; i <= hi[0]; ++i) {
          const int c = cell_of(grid.key(i, j, k));
          if (c >= 0) add(c);
        }
  }
  out.near_start.assign(keys.size() + 1, 0);
  for (size_t c = 0; c < near.size(); ++c) {
    std::vector<int>& list = near[c];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    out.near_start[c + 1] = out.near_start[c] + static_cast<int>(list.size());
    out.near_vertices.insert(out.near_vertices.end(), list.begin(), list.end());
  }
  return out;
}

LocalDeformation::LocalDeformation(const RestCells& cells, const Points& rest, const Points& x0, const Points& x1)
    : m_cells(cells), m_rest(rest), m_x0(x0), m_x1(x1), m_known(static_cast<size_t>(cells.num_cells()), -1.0) {
  RECOIL_CHECK(rest.rows() == x0.rows() && x0.rows() == x1.rows() &&
                   static_cast<size_t>(rest.rows()) == cells.vertex_cell.size(),
               "rest " << rest.rows() << ", x0 " << x0.rows() << ", x1 " << x1.rows() << " rows, cells for "
                       << cells.vertex_cell.size());
}

double LocalDeformation::operator()(int cell) {
  double& known = m_known[static_cast<size_t>(cell)];
  if (known >= 0.0) return known;
  const int begin = m_cells.near_start[static_cast<size_t>(cell)];
  const int end = m_cells.near_start[static_cast<size_t>(cell) + 1];
  m_from.resize(end - begin, 3);
  m_to.resize(end - begin, 3);
  Eigen::Vector3d mean_motion = Eigen::Vector3d::Zero();
  for (int i = begin; i < end; ++i) {
    const int v = m_cells.near_vertices[static_cast<size_t>(i)];
    m_from.row(i - begin) = m_rest.row(v);
    m_to.row(i - begin) = m_x0.row(v);
    mean_motion += (m_x1.row(v) - m_x0.row(v)).transpose();
  }
  if (end > begin) mean_motion /= static_cast<double>(end - begin);
  const RigidFit fit = fit_rigid_motion(m_from, m_to);
  double largest_residual = 0.0, largest_deviation = 0.0;
  for (int i = begin; i < end; ++i) {
    const int v = m_cells.near_vertices[static_cast<size_t>(i)];
    largest_residual = std::max(largest_residual, fit.residual[static_cast<size_t>(i - begin)]);
    largest_deviation = std::max(largest_deviation, ((m_x1.row(v) - m_x0.row(v)).transpose() - mean_motion).norm());
  }
  known = largest_residual + largest_deviation;
  return known;
}

}  // namespace recoil::sim
