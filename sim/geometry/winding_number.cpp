#include "sim/geometry/winding_number.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/check.h"
#include "core/error.h"

namespace recoil::sim {
namespace {

// Leaves hold at most this many triangles: below it, summing them exactly
// costs less than descending further.
constexpr int kWindingLeafSize = 8;
// A median-split tree over at most 2^31 triangles is at most 32 levels deep,
// so a traversal never holds more than this many pending nodes.
constexpr int kWindingStackSize = 128;

Eigen::Vector3d winding_corner(const TriMesh& mesh, int f, int k) {
  return mesh.vertices.row(mesh.triangles(f, k)).transpose();
}

}  // namespace

double triangle_solid_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                            const Eigen::Vector3d& q) {
  const Eigen::Vector3d x = a - q, y = b - q, z = c - q;
  const double lx = x.norm(), ly = y.norm(), lz = z.norm();
  // tan(omega / 2) = det[x y z] / (|x||y||z| + (x.y)|z| + (x.z)|y| + (y.z)|x|);
  // atan2 keeps the quadrant, so omega covers (-2 pi, 2 pi].
  const double det = x.dot(y.cross(z));
  const double denominator = lx * ly * lz + x.dot(y) * lz + x.dot(z) * ly + y.dot(z) * lx;
  return 2.0 * std::atan2(det, denominator);
}

double winding_number(const TriMesh& surface, const Eigen::Vector3d& q) {
  double omega = 0.0;
  for (int f = 0; f < surface.num_triangles(); ++f)
    omega += triangle_solid_angle(winding_corner(surface, f, 0), winding_corner(surface, f, 1),
                                  winding_corner(surface, f, 2), q);
  return omega / (4.0 * std::numbers::pi);
}

WindingNumberTree::WindingNumberTree(const TriMesh& surface, double accuracy) : m_accuracy(accuracy) {
  if (!(accuracy > 0.0)) throw bad_input("winding number: accuracy must be > 0");
  const int n = surface.num_triangles();
  std::vector<Corners> triangles(static_cast<size_t>(n));
  std::vector<Eigen::Vector3d> centers(static_cast<size_t>(n));
  std::vector<int> order(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    const size_t i = static_cast<size_t>(f);
    triangles[i] = {winding_corner(surface, f, 0), winding_corner(surface, f, 1), winding_corner(surface, f, 2)};
    centers[i] = (triangles[i][0] + triangles[i][1] + triangles[i][2]) / 3.0;
    order[i] = f;
  }
  if (n == 0) return;
  m_nodes.reserve(static_cast<size_t>(2 * (n / kWindingLeafSize + 1)));
  build(order, 0, n, triangles, centers);
  m_triangles.reserve(static_cast<size_t>(n));
  for (int f : order) m_triangles.push_back(triangles[static_cast<size_t>(f)]);
}

int WindingNumberTree::build(std::vector<int>& order, int first, int count, const std::vector<Corners>& triangles,
                             const std::vector<Eigen::Vector3d>& centers) {
  const int id = static_cast<int>(m_nodes.size());
  m_nodes.emplace_back();
  // The cluster's dipole: area vectors summed, centroid weighted by area (the
  // plain mean when the cluster has no area at all).
  Eigen::Vector3d area_normal = Eigen::Vector3d::Zero(), weighted = Eigen::Vector3d::Zero(),
                  mean = Eigen::Vector3d::Zero();
  double area = 0.0;
  Aabb box;
  for (int i = first; i < first + count; ++i) {
    const Corners& t = triangles[static_cast<size_t>(order[static_cast<size_t>(i)])];
    const Eigen::Vector3d v = 0.5 * (t[1] - t[0]).cross(t[2] - t[0]);
    const Eigen::Vector3d& c = centers[static_cast<size_t>(order[static_cast<size_t>(i)])];
    area_normal += v;
    weighted += v.norm() * c;
    area += v.norm();
    mean += c;
    box.extend(c);
  }
  const Eigen::Vector3d centroid = area > 0.0 ? Eigen::Vector3d(weighted / area) : Eigen::Vector3d(mean / count);
  // Second-order term: a triangle's own first moment about its centre is
  // zero, so offsetting whole triangles by their centres is exact to this order.
  double radius = 0.0;
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for (int i = first; i < first + count; ++i) {
    const int f = order[static_cast<size_t>(i)];
    const Corners& t = triangles[static_cast<size_t>(f)];
    for (const Eigen::Vector3d& v : t) radius = std::max(radius, (v - centroid).norm());
    moment += (0.5 * (t[1] - t[0]).cross(t[2] - t[0])) * (centers[static_cast<size_t>(f)] - centroid).transpose();
  }
  {
    Node& node = m_nodes[static_cast<size_t>(id)];
    node.centroid = centroid;
    node.area_normal = area_normal;
    node.moment = moment;
    node.radius = radius;
  }
  if (count <= kWindingLeafSize) {
    // Leaf ranges index the final order, which is the order of `order` itself.
    m_nodes[static_cast<size_t>(id)].first = first;
    m_nodes[static_cast<size_t>(id)].count = count;
    return id;
  }
  // Median split along the longest side of the centres' box; ties broken by
  // triangle id so the tree does not depend on the sort's internals.
  int axis = 0;
  box.extent().maxCoeff(&axis);
  const int half = count / 2;
  const auto begin = order.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](int p, int q) {
    const double cp = centers[static_cast<size_t>(p)][axis], cq = centers[static_cast<size_t>(q)][axis];
    return cp < cq || (cp == cq && p < q);
  });
  const int left = build(order, first, half, triangles, centers);
  const int right = build(order, first + half, count - half, triangles, centers);
  m_nodes[static_cast<size_t>(id)].left = left;
  m_nodes[static_cast<size_t>(id)].right = right;
  return id;
}

double WindingNumberTree::operator()(const Eigen::Vector3d& q) const {
  if (m_nodes.empty()) return 0.0;
  int stack[kWindingStackSize];
  int top = 0;
  stack[top++] = 0;
  double omega = 0.0;
  while (top > 0) {
    const Node& node = m_nodes[static_cast<size_t>(stack[--top])];
    const Eigen::Vector3d d = node.centroid - q;
    const double distance = d.norm();
    if (distance > m_accuracy * node.radius) {
      // Far field: the flux of x / |x|^3 (x = p - q) through the patch, to
      // second order: N.x / r^3 + sum_jk M_jk J_jk with J = I / r^3 - 3 x x^T / r^5
      // its Jacobian and M the moment (area vector by offset).
      const double r2 = distance * distance, r3 = r2 * distance;
      omega += node.area_normal.dot(d) / r3 + node.moment.trace() / r3 - 3.0 * d.dot(node.moment * d) / (r3 * r2);
    } else if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const Corners& t = m_triangles[static_cast<size_t>(i)];
        omega += triangle_solid_angle(t[0], t[1], t[2], q);
      }
    } else {
      RECOIL_CHECK(top + 2 <= kWindingStackSize);
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
  }
  return omega / (4.0 * std::numbers::pi);
}

}  // namespace recoil::sim
