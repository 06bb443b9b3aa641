#include "sim/collision/rest_clearance.h"

#include <Eigen/SVD>
#include <algorithm>

#include "core/check.h"
#include "sim/collision/embree_scene.h"
#include "sim/collision/exact_distance.h"

namespace recoil::sim {

namespace {

// Each edge's rest box padded by half the reach: boxes of edges within the
// reach of each other overlap.
std::vector<Aabb> padded_edge_boxes(const Points& rest, const std::vector<std::array<int, 2>>& edges, double reach) {
  std::vector<Aabb> boxes(edges.size());
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(0.5 * reach);
  for (size_t e = 0; e < edges.size(); ++e) {
    const Eigen::Vector3d p = point_at(rest, edges[e][0]), q = point_at(rest, edges[e][1]);
    boxes[e].min = p.cwiseMin(q) - pad;
    boxes[e].max = p.cwiseMax(q) + pad;
  }
  return boxes;
}
}  // namespace

double rest_distance(const Points& rest, int vertex, const std::array<int, 3>& triangle) {
  const Eigen::Vector3d p = point_at(rest, vertex);
  const TriangleClosestPoint q = closest_point_on_triangle(p, point_at(rest, triangle[0]), point_at(rest, triangle[1]),
                                                           point_at(rest, triangle[2]));
  return (p - q.point).norm();
}

double rest_distance(const Points& rest, const std::array<int, 2>& e, const std::array<int, 2>& f) {
  const Eigen::Vector3d a0 = point_at(rest, e[0]), a1 = point_at(rest, e[1]);
  const Eigen::Vector3d b0 = point_at(rest, f[0]), b1 = point_at(rest, f[1]);
  const SegmentClosestPoints c = closest_points_on_segments(a0, a1, b0, b1);
  return ((a0 + c.s * (a1 - a0)) - (b0 + c.t * (b1 - b0))).norm();
}

RestClearance rest_clearance(EmbreeDevice& device, const Points& rest, const Triangles& triangles,
                             const std::vector<std::array<int, 2>>& edges, double margin, double reach) {
  RECOIL_CHECK(reach >= margin, "reach " << reach << " must be at least the margin " << margin);
  RestClearance out;
  out.vertex.assign(static_cast<size_t>(rest.rows()), reach);
  out.edge.assign(edges.size(), reach);
  if (triangles.rows() == 0) return out;

  const TriangleScene scene(device, rest, triangles, /*dynamic=*/false);
  std::vector<int> near;
  for (int v = 0; v < rest.rows(); ++v) {
    near.clear();
    scene.triangles_near(point_at(rest, v), reach, near);
    for (int t : near) {
      const double d = rest_distance(rest, v, {triangles(t, 0), triangles(t, 1), triangles(t, 2)});
      if (d > margin) out.vertex[static_cast<size_t>(v)] = std::min(out.vertex[static_cast<size_t>(v)], d);
    }
  }

  BoxScene boxes(device);
  boxes.set_boxes(padded_edge_boxes(rest, edges, reach), edges);  // edges sharing a vertex never pair
  for (const auto& [e, f] : boxes.overlapping_pairs(boxes)) {
    const double d = rest_distance(rest, edges[static_cast<size_t>(e)], edges[static_cast<size_t>(f)]);
    if (!(d > margin)) continue;
    out.edge[static_cast<size_t>(e)] = std::min(out.edge[static_cast<size_t>(e)], d);
    out.edge[static_cast<size_t>(f)] = std::min(out.edge[static_cast<size_t>(f)], d);
  }
  return out;
}

RigidFit fit_rigid_motion(const Points& from, const Points& to) {
  RECOIL_CHECK(from.rows() == to.rows(), "from has " << from.rows() << " rows, to " << to.rows());
  RigidFit fit;
  fit.residual.assign(static_cast<size_t>(to.rows()), 0.0);
  if (to.rows() == 0) return fit;
  const Eigen::RowVector3d from_mean = from.colwise().mean(), to_mean = to.colwise().mean();
  // Kabsch: R maximises trace(R^T H) with H = sum (x - mean x)(X - mean X)^T.
  const Eigen::Matrix3d h = (to.rowwise() - to_mean).transpose() * (from.rowwise() - from_mean);
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
  flip(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  fit.rotation = svd.matrixU() * flip * svd.matrixV().transpose();
  fit.translation = to_mean.transpose() - fit.rotation * from_mean.transpose();
  for (int v = 0; v < to.rows(); ++v)
    fit.residual[static_cast<size_t>(v)] =
        (to.row(v).transpose() - fit.rotation * from.row(v).transpose() - fit.translation).norm();
  return fit;
}

}  // namespace recoil::sim
