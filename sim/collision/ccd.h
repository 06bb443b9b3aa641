#pragma once
// Continuous collision checks in double precision: every point moves linearly
// from its start (x0) to its end (x1) position over the step, s in [0, 1].
// The four points of a vertex-triangle or edge-edge pair are coplanar at an
// impact, so candidates are the roots of a cubic in s; each root is accepted
// only if the primitives really touch there (distance <= tolerance).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <optional>
#include <vector>

namespace recoil::sim {

// The position at fraction s of a straight move from x0 to x1.
inline Eigen::Vector3d lerp(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, double s) { return x0 + s * (x1 - x0); }

// First s in [0, 1] at which vertex p touches triangle (a, b, c), if any.
// Pairs that stay coplanar for the whole step report s = 0 only when touching
// at the start (sliding within the plane is left to the distance query).
std::optional<double> vertex_triangle_toi(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                          const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                          const Eigen::Vector3d& b0, const Eigen::Vector3d& b1,
                                          const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                                          double tolerance);

// First s in [0, 1] at which segment (p, q) touches segment (r, t), if any.
std::optional<double> edge_edge_toi(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                    const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
                                    const Eigen::Vector3d& r0, const Eigen::Vector3d& r1,
                                    const Eigen::Vector3d& t0, const Eigen::Vector3d& t1, double tolerance);

// Real roots in [0, 1] of c0 + c1 s + c2 s^2 + c3 s^3, ascending, including
// tangent (double) roots located at a local extremum whose |value| <= zero_tol.
// Exposed for tests.
std::vector<double> cubic_roots_in_unit_interval(double c0, double c1, double c2, double c3, double zero_tol);

}  // namespace recoil::sim
