// Exact closest points and continuous checks against dense sampling and
// analytic answers, including degenerate input.
#include "sim/collision/exact_distance.h"

#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "sim/collision/ccd.h"

namespace recoil::sim {
namespace {

Eigen::Vector3d random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {u(rng), u(rng), u(rng)};
}

double sampled_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& c) {
  const int n = 300;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      best = std::min(best, (p - ((1 - u - v) * a + u * b + v * c)).norm());
    }
  return best;
}

TEST(ExactDistance, TriangleClosestPointMatchesSampling) {
  std::mt19937 rng(11);
  double worst = 0.0;
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Vector3d a = random_point(rng), b = random_point(rng);
    // Every fourth triangle is degenerate: collinear, or with a repeated vertex.
    Eigen::Vector3d c = random_point(rng);
    if (trial % 4 == 1) c = a + 0.3 * (b - a);
    if (trial % 4 == 2) c = b;
    const Eigen::Vector3d p = random_point(rng);
    const TriangleClosestPoint q = closest_point_on_triangle(p, a, b, c);
    ASSERT_TRUE(q.point.allFinite());
    const double w_sum = q.weight[0] + q.weight[1] + q.weight[2];
    EXPECT_NEAR(w_sum, 1.0, 1e-12);
    for (double w : q.weight) EXPECT_GE(w, 0.0);
    EXPECT_LT((q.weight[0] * a + q.weight[1] * b + q.weight[2] * c - q.point).norm(), 1e-12);
    const double exact = (p - q.point).norm(), sampled = sampled_triangle_distance(p, a, b, c);
    // Sampling only over-estimates; the grid spacing bounds how much.
    EXPECT_LE(exact, sampled + 1e-12);
    EXPECT_GE(exact, sampled - 0.02);
    worst = std::max(worst, sampled - exact);
  }
  std::cout << "largest (sampled - exact) triangle distance: " << worst << " m\n";
}

TEST(ExactDistance, SegmentClosestPointsMatchSampling) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Vector3d p0 = random_point(rng), p1 = random_point(rng), q0 = random_point(rng);
    Eigen::Vector3d q1 = random_point(rng);
    if (trial % 4 == 1) q1 = q0 + (p1 - p0);  // parallel
    if (trial % 4 == 2) q1 = q0;              // a point
    const SegmentClosestPoints cp = closest_points_on_segments(p0, p1, q0, q1);
    ASSERT_TRUE(std::isfinite(cp.s) && std::isfinite(cp.t));
    const double exact = ((p0 + cp.s * (p1 - p0)) - (q0 + cp.t * (q1 - q0))).norm();
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 400; ++i)
      for (int j = 0; j <= 400; ++j)
        sampled = std::min(sampled, ((p0 + (i / 400.0) * (p1 - p0)) - (q0 + (j / 400.0) * (q1 - q0))).norm());
    EXPECT_LE(exact, sampled + 1e-12);
    EXPECT_GE(exact, sampled - 0.01);
  }
}

TEST(Ccd, CubicRootsAreFoundInOrder) {
  // (s - 0.2)(s - 0.5)(s - 0.9) and a tangent root at 0.4: (s - 0.4)^2 (s + 1).
  const auto r = cubic_roots_in_unit_interval(-0.09, 0.73, -1.6, 1.0, 1e-15);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 0.2, 1e-12);
  EXPECT_NEAR(r[1], 0.5, 1e-12);
  EXPECT_NEAR(r[2], 0.9, 1e-12);
  const auto t = cubic_roots_in_unit_interval(0.16, -0.64, 0.2, 1.0, 1e-15);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NEAR(t[0], 0.4, 1e-7);
}

TEST(Ccd, VertexThroughMovingTriangle) {
  // The triangle rises from z = -1 to z = 1 while the vertex falls from 1 to -1:
  // they meet at s = 0.5 inside the triangle.
  const Eigen::Vector3d a(0, 0, -1), b(1, 0, -1), c(0, 1, -1), up(0, 0, 2);
  const auto toi = vertex_triangle_toi({0.2, 0.2, 1}, {0.2, 0.2, -1}, a, a + up, b, b + up, c, c + up, 1e-12);
  ASSERT_TRUE(toi.has_value());
  EXPECT_NEAR(*toi, 0.5, 1e-12);
  // Same motion beside the triangle: no impact.
  EXPECT_FALSE(vertex_triangle_toi({2, 2, 1}, {2, 2, -1}, a, a + up, b, b + up, c, c + up, 1e-12).has_value());
  // A rotating triangle (vertex c swings through the fixed vertex's height).
  const auto swing = vertex_triangle_toi({0.1, 0.25, 0.25}, {0.1, 0.25, 0.25}, {0, 0, 0}, {0, 0, 0}, {1, 0, 0},
                                         {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1e-12);
  ASSERT_TRUE(swing.has_value());
  // c(s) = (0, 1-s, s): the plane through x-axis and c contains (y, z) = (0.25, 0.25) at s = 0.5.
  EXPECT_NEAR(*swing, 0.5, 1e-12);
}

TEST(Ccd, CrossingEdges) {
  // Edge along x at z = 1 falls to z = -1 through an edge along y at z = 0: s = 0.5.
  const auto toi = edge_edge_toi({-1, 0, 1}, {-1, 0, -1}, {1, 0, 1}, {1, 0, -1}, {0, -1, 0}, {0, -1, 0}, {0, 1, 0},
                                 {0, 1, 0}, 1e-12);
  ASSERT_TRUE(toi.has_value());
  EXPECT_NEAR(*toi, 0.5, 1e-12);
  // Shifted past the other edge's end: they never meet.
  EXPECT_FALSE(edge_edge_toi({-1, 3, 1}, {-1, 3, -1}, {1, 3, 1}, {1, 3, -1}, {0, -1, 0}, {0, -1, 0}, {0, 1, 0},
                             {0, 1, 0}, 1e-12)
                   .has_value());
}

}  // namespace
}  // namespace recoil::sim
