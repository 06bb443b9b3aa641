#include "sim/collision/exact_distance.h"

#include <algorithm>
#include <cmath>

namespace recoil::sim {

double closest_parameter_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double dd = d.squaredNorm();
  if (!(dd > 0.0)) return 0.0;  // a point: the first end
  const double s = (p - a).dot(d) / dd;
  return s <= 0.0 ? 0.0 : (s >= 1.0 ? 1.0 : s);
}

TriangleClosestPoint closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                               const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  // A triangle whose normal is lost in rounding is treated as its three edges.
  const double scale = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  if (nn > 1e-24 * scale * scale) {
    const Eigen::Vector3d q = p - n * (n.dot(p - a) / nn);
    const double wa = n.dot((b - q).cross(c - q)) / nn;
    const double wb = n.dot((c - q).cross(a - q)) / nn;
    const double wc = 1.0 - wa - wb;
    // Points within rounding of an edge go to the edge branch, which gives
    // exact zero weights, so the two faces of an edge report the same feature.
    constexpr double kSnap = 1e-12;
    if (wa > kSnap && wb > kSnap && wc > kSnap) return {wa * a + wb * b + wc * c, {wa, wb, wc}};
  }
  // Outside the face (or a degenerate face): the nearest of the three edges.
  TriangleClosestPoint best;
  double best_d2 = std::numeric_limits<double>::infinity();
  const std::array<const Eigen::Vector3d*, 3> v = {&a, &b, &c};
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = (e + 1) % 3;
    const double s = closest_parameter_on_segment(p, *v[i], *v[j]);
    const Eigen::Vector3d q = (1.0 - s) * *v[i] + s * *v[j];
    const double d2 = (p - q).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.point = q;
      best.weight = {0.0, 0.0, 0.0};
      best.weight[i] = 1.0 - s;
      best.weight[j] = s;
    }
  }
  return best;
}

SegmentClosestPoints closest_points_on_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                                const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  auto clamp01 = [](double x) { return x <= 0.0 ? 0.0 : (x >= 1.0 ? 1.0 : x); };
  if (!(a > 0.0) && !(e > 0.0)) return {0.0, 0.0};
  if (!(a > 0.0)) return {0.0, clamp01(f / e)};
  const double c = d1.dot(r);
  if (!(e > 0.0)) return {clamp01(-c / a), 0.0};
  const double b = d1.dot(d2);
  const double denom = a * e - b * b;  // >= 0, zero for parallel segments
  double s = 0.0;
  if (denom > 1e-14 * a * e) s = clamp01((b * f - c * e) / denom);
  // t for that s, then s again if t had to be clamped (Ericson, RTCD 5.1.9).
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = clamp01(-c / a);
  } else if (t > 1.0) {
    t = 1.0;
    s = clamp01((b - c) / a);
  }
  return {s, t};
}

Eigen::Vector3d face_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double scale = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return n.squaredNorm() > 1e-24 * scale * scale ? n : Eigen::Vector3d::Zero();
}

}  // namespace recoil::sim
