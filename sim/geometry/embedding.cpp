#include "sim/geometry/embedding.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/check.h"

namespace recoil::sim {

namespace {

// A uniform grid of buckets holding the tets whose bounding box touches them.
class TetGrid {
 public:
  explicit TetGrid(const TetMesh& mesh) : m_box(bounding_box(mesh.nodes)) {
    const double cells_per_axis = std::max(1.0, std::cbrt(static_cast<double>(mesh.num_tets()) / 2.0));
    m_h = std::max(m_box.extent().maxCoeff() / cells_per_axis, 1e-12);
    for (int a = 0; a < 3; ++a) m_n[a] = std::max(1, static_cast<int>(std::ceil(m_box.extent()[a] / m_h)));
    m_buckets.resize(static_cast<size_t>(m_n.cast<long>().prod()));
    for (int t = 0; t < mesh.num_tets(); ++t) {
      Aabb tb;
      for (int k = 0; k < 4; ++k) tb.extend(mesh.nodes.row(mesh.tets(t, k)).transpose());
      const Eigen::Vector3i lo = cell_of(tb.min), hi = cell_of(tb.max);
      for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
          for (int x = lo[0]; x <= hi[0]; ++x) m_buckets[index(x, y, z)].push_back(t);
    }
  }

  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    Eigen::Vector3i c;
    for (int a = 0; a < 3; ++a) {
      const double f = std::floor((p[a] - m_box.min[a]) / m_h);
      c[a] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(m_n[a] - 1)));
    }
    return c;
  }
  size_t index(int x, int y, int z) const {
    return static_cast<size_t>((static_cast<long>(z) * m_n[1] + y) * m_n[0] + x);
  }
  const std::vector<int>& bucket(int x, int y, int z) const { return m_buckets[index(x, y, z)]; }
  const Eigen::Vector3i& size() const { return m_n; }

 private:
  Aabb m_box;
  double m_h = 1.0;
  Eigen::Vector3i m_n;
  std::vector<std::vector<int>> m_buckets;
};

// Distance outside tet t measured by its face planes (0 inside); a cheap
// stand-in for the exact point-tet distance, exact in face regions.
double plane_distance(const TetMesh& mesh, int t, const Eigen::Vector3d& p) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  double d = 0.0;
  for (const auto& f : kFaces) {
    const Eigen::Vector3d a = mesh.nodes.row(mesh.tets(t, f[0])).transpose();
    const Eigen::Vector3d b = mesh.nodes.row(mesh.tets(t, f[1])).transpose();
    const Eigen::Vector3d c = mesh.nodes.row(mesh.tets(t, f[2])).transpose();
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    const double len = normal.norm();
    if (len > 0.0) d = std::max(d, normal.dot(p - a) / len);
  }
  return d;
}

// What barycentric coordinates in one tet need: its first node and the LU
// of its edge matrix [x1 - x0, x2 - x0, x3 - x0] (3x3, m), factored once
// per tet rather than once per point tested against it.
struct TetFrame {
  Eigen::Vector3d x0;
  Eigen::PartialPivLU<Eigen::Matrix3d> lu;
};

TetFrame tet_frame(const Points& nodes, const Tets& tets, int t) {
  TetFrame f;
  f.x0 = nodes.row(tets(t, 0)).transpose();
  Eigen::Matrix3d dm;
  for (int k = 0; k < 3; ++k) dm.col(k) = nodes.row(tets(t, k + 1)).transpose() - f.x0;
  f.lu.compute(dm);
  return f;
}

Eigen::Vector4d weights_in(const TetFrame& f, const Eigen::Vector3d& p) {
  const Eigen::Vector3d l = f.lu.solve(p - f.x0);
  return {1.0 - l.sum(), l[0], l[1], l[2]};
}

}  // namespace

Eigen::Vector4d barycentric(const Points& nodes, const Tets& tets, int t, const Eigen::Vector3d& p) {
  return weights_in(tet_frame(nodes, tets, t), p);
}

Embedding embed_points(const TetMesh& mesh, const Points& points) {
  RECOIL_CHECK(!mesh.empty());
  const TetGrid grid(mesh);
  std::vector<TetFrame> frames;
  frames.reserve(static_cast<size_t>(mesh.num_tets()));
  for (int t = 0; t < mesh.num_tets(); ++t) frames.push_back(tet_frame(mesh.nodes, mesh.tets, t));
  Embedding e;
  e.tet.resize(points.rows());
  e.weights.resize(points.rows(), 4);
  for (Eigen::Index v = 0; v < points.rows(); ++v) {
    const Eigen::Vector3d p = points.row(v).transpose();
    const Eigen::Vector3i c = grid.cell_of(p);
    // Containing tet: the one whose smallest weight is largest (ties: lowest index).
    int best = -1;
    double best_min = -std::numeric_limits<double>::infinity();
    for (int t : grid.bucket(c[0], c[1], c[2])) {
      const double m = weights_in(frames[static_cast<size_t>(t)], p).minCoeff();
      if (m > best_min) { best_min = m; best = t; }
    }
    if (best_min < -1e-10) {
      // Outside every tet of the bucket: nearest tet by plane distance over
      // growing shells of buckets, one shell past the first that had any.
      double best_d = std::numeric_limits<double>::infinity();
      best = -1;
      const int max_r = grid.size().maxCoeff();
      int found_at = -1;
      for (int r = 0; r <= max_r && (found_at < 0 || r <= found_at + 1); ++r) {
        for (int z = c[2] - r; z <= c[2] + r; ++z)
          for (int y = c[1] - r; y <= c[1] + r; ++y)
            for (int x = c[0] - r; x <= c[0] + r; ++x) {
              if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != r) continue;
              if (x < 0 || y < 0 || z < 0 || x >= grid.size()[0] || y >= grid.size()[1] || z >= grid.size()[2])
                continue;
              for (int t : grid.bucket(x, y, z)) {
                const double d = plane_distance(mesh, t, p);
                if (d < best_d || (d == best_d && t < best)) { best_d = d; best = t; }
              }
            }
        if (best >= 0 && found_at < 0) found_at = r;
      }
      ++e.outside;
    }
    RECOIL_CHECK(best >= 0, "vertex " << v);
    e.tet[v] = best;
    e.weights.row(v) = weights_in(frames[static_cast<size_t>(best)], p).transpose();
  }
  return e;
}

void embedded_positions(const Embedding& embedding, const Tets& tets, const Points& nodes, Points& out) {
  out.resize(embedding.tet.size(), 3);
  for (Eigen::Index v = 0; v < embedding.tet.size(); ++v) {
    const int t = embedding.tet[v];
    Eigen::RowVector3d p = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) p += embedding.weights(v, k) * nodes.row(tets(t, k));
    out.row(v) = p;
  }
}

}  // namespace recoil::sim
