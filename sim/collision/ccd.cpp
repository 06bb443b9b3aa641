#include "sim/collision/ccd.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "sim/collision/exact_distance.h"

namespace recoil::sim {
namespace {

double eval_cubic(const std::array<double, 4>& c, double s) { return ((c[3] * s + c[2]) * s + c[1]) * s + c[0]; }

// Bisection on a bracket [lo, hi] with a sign change: the root to full
// double resolution, deterministic (no tolerance-dependent stopping).
double bisect(const std::array<double, 4>& c, double lo, double hi) {
  double f_lo = eval_cubic(c, lo);
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double f_mid = eval_cubic(c, mid);
    if (f_mid == 0.0) return mid;
    if ((f_mid < 0.0) == (f_lo < 0.0)) {
      lo = mid;
      f_lo = f_mid;
    } else {
      hi = mid;
    }
  }
  return lo;  // the earlier end, so an impact is never reported late
}

// Coefficients of det(u(s), v(s), w(s)) = u.(v x w) with u = u0 + s u1 etc.
std::array<double, 4> triple_product_cubic(const Eigen::Vector3d& u0, const Eigen::Vector3d& u1,
                                           const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                           const Eigen::Vector3d& w0, const Eigen::Vector3d& w1) {
  return {u0.dot(v0.cross(w0)), u1.dot(v0.cross(w0)) + u0.dot(v1.cross(w0)) + u0.dot(v0.cross(w1)),
          u1.dot(v1.cross(w0)) + u1.dot(v0.cross(w1)) + u0.dot(v1.cross(w1)), u1.dot(v1.cross(w1))};
}

// Runs `touches` on the coplanarity roots in order; returns the first accepted.
std::optional<double> first_touching_root(const std::array<double, 4>& c, double scale3,
                                          const std::function<bool(double)>& touches) {
  const double max_coeff = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2]), std::abs(c[3])});
  if (!(max_coeff > 1e-13 * scale3)) {
    // Coplanar for the whole step: only an initial touch is reported.
    if (touches(0.0)) return 0.0;
    return std::nullopt;
  }
  for (double s : cubic_roots_in_unit_interval(c[0], c[1], c[2], c[3], 1e-13 * scale3))
    if (touches(s)) return s;
  return std::nullopt;
}

double scale_of(std::initializer_list<const Eigen::Vector3d*> points) {
  // Characteristic length of the pair: the spread of all positions involved.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d* p : points) {
    lo = lo.cwiseMin(*p);
    hi = hi.cwiseMax(*p);
  }
  return (hi - lo).maxCoeff();
}

}  // namespace

std::vector<double> cubic_roots_in_unit_interval(double c0, double c1, double c2, double c3, double zero_tol) {
  const std::array<double, 4> c = {c0, c1, c2, c3};
  // Split [0, 1] at the extrema (roots of the derivative) into monotone pieces.
  std::vector<double> knots = {0.0, 1.0};
  const double qa = 3.0 * c3, qb = 2.0 * c2, qc = c1;
  if (qa != 0.0) {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0) {
      const double sq = std::sqrt(disc);
      // Stable form of the two quadratic roots.
      const double q = -0.5 * (qb + (qb >= 0.0 ? sq : -sq));
      if (q != 0.0) {
        knots.push_back(q / qa);
        knots.push_back(qc / q);
      } else {
        knots.push_back(0.0);
      }
    }
  } else if (qb != 0.0) {
    knots.push_back(-qc / qb);
  }
  std::vector<double> inside;
  for (double k : knots)
    if (k >= 0.0 && k <= 1.0) inside.push_back(k);
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());

  std::vector<double> roots;
  for (size_t i = 0; i < inside.size(); ++i) {
    const double s = inside[i];
    const double f = eval_cubic(c, s);
    if (std::abs(f) <= zero_tol) roots.push_back(s);  // an end or a tangent root
    if (i + 1 < inside.size()) {
      const double hi = inside[i + 1];
      const double f_hi = eval_cubic(c, hi);
      if (std::abs(f) > zero_tol && std::abs(f_hi) > zero_tol && (f < 0.0) != (f_hi < 0.0))
        roots.push_back(bisect(c, s, hi));
    }
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

std::optional<double> vertex_triangle_toi(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                          const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                          const Eigen::Vector3d& b0, const Eigen::Vector3d& b1,
                                          const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                                          double tolerance) {
  const double scale = scale_of({&p0, &p1, &a0, &a1, &b0, &b1, &c0, &c1});
  if (!(scale > 0.0)) return 0.0;  // everything at one point
  const auto cubic = triple_product_cubic(b0 - a0, (b1 - a1) - (b0 - a0), c0 - a0, (c1 - a1) - (c0 - a0), p0 - a0,
                                          (p1 - a1) - (p0 - a0));
  return first_touching_root(cubic, scale * scale * scale, [&](double s) {
    const Eigen::Vector3d p = lerp(p0, p1, s);
    const TriangleClosestPoint q = closest_point_on_triangle(p, lerp(a0, a1, s), lerp(b0, b1, s), lerp(c0, c1, s));
    return (p - q.point).norm() <= tolerance;
  });
}

std::optional<double> edge_edge_toi(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                    const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
                                    const Eigen::Vector3d& r0, const Eigen::Vector3d& r1,
                                    const Eigen::Vector3d& t0, const Eigen::Vector3d& t1, double tolerance) {
  const double scale = scale_of({&p0, &p1, &q0, &q1, &r0, &r1, &t0, &t1});
  if (!(scale > 0.0)) return 0.0;
  const auto cubic = triple_product_cubic(q0 - p0, (q1 - p1) - (q0 - p0), r0 - p0, (r1 - p1) - (r0 - p0), t0 - p0,
                                          (t1 - p1) - (t0 - p0));
  return first_touching_root(cubic, scale * scale * scale, [&](double s) {
    const Eigen::Vector3d p = lerp(p0, p1, s), q = lerp(q0, q1, s), r = lerp(r0, r1, s), t = lerp(t0, t1, s);
    const SegmentClosestPoints cp = closest_points_on_segments(p, q, r, t);
    return ((p + cp.s * (q - p)) - (r + cp.t * (t - r))).norm() <= tolerance;
  });
}

}  // namespace recoil::sim
