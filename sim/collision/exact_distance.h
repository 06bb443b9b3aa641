#pragma once
// Exact closest points in double precision, robust to degenerate input
// (zero-area triangles, zero-length or parallel segments): they never divide
// by a vanishing quantity and always return finite weights.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <array>

namespace recoil::sim {

struct TriangleClosestPoint {
  Eigen::Vector3d point;
  // point = w[0] a + w[1] b + w[2] c; weights are exactly 0 off the closest
  // feature (a weight of 0 means "not on that vertex's side").
  std::array<double, 3> weight;
};

// The point of triangle (a, b, c) closest to p. Ties between features of a
// degenerate triangle are broken in the fixed order interior, ab, bc, ca.
TriangleClosestPoint closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                               const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The triangle's normal (b - a) x (c - a), unnormalised, or zero for a
// triangle whose normal is lost in rounding.
Eigen::Vector3d face_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Parameters s, t in [0, 1] of the closest points p0 + s (p1 - p0) and
// q0 + t (q1 - q0) of two segments. A value clamped to an end is exactly 0 or
// 1. For parallel segments (not unique) s is the smallest that attains the
// minimum given the rule t = closest to p(s).
struct SegmentClosestPoints {
  double s = 0.0, t = 0.0;
};
SegmentClosestPoints closest_points_on_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                                const Eigen::Vector3d& q0, const Eigen::Vector3d& q1);

// Closest point on a segment to p, as the parameter in [0, 1].
double closest_parameter_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace recoil::sim
