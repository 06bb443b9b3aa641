// The self-contact broad phase's rest clearances and rigid-fit displacements,
// and the detector skipping what they rule out without changing a candidate.
#include "sim/collision/rest_clearance.h"

#include <gtest/gtest.h>

#include <random>

#include "sim/collision/brute_force.h"
#include "sim/collision/collision_detector.h"
#include "sim/collision/embree_scene.h"
#include "sim/collision/narrow_phase.h"
#include "tests/sim/collision/collision_candidate_checks.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::sim {
namespace {

constexpr double kSelfMargin = 0.002;  // m

// A 3 cm sphere of 1280 triangles (edges about 5 mm, a few margins).
TriMesh fine_sphere() {
  TriMesh s = testing::icosphere(3);
  s.vertices *= 0.03;
  return s;
}

TEST(RestClearance, IsTheNearestContactablePrimitiveUpToTheReach) {
  const TriMesh s = fine_sphere();
  const std::vector<std::array<int, 2>> edges = unique_edges(s.triangles);
  EmbreeDevice device;
  const double reach = clearance_reach(kSelfMargin);
  const RestClearance c = rest_clearance(device, s.vertices, s.triangles, edges, kSelfMargin, reach);
  // Every pair, directly: the clearance is min(reach, nearest rest distance above the margin).
  for (int v = 0; v < s.num_vertices(); ++v) {
    double nearest = reach;
    for (int t = 0; t < s.num_triangles(); ++t) {
      const double d = rest_distance(s.vertices, v, {s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)});
      if (d > kSelfMargin) nearest = std::min(nearest, d);
    }
    ASSERT_NEAR(c.vertex[static_cast<size_t>(v)], nearest, 1e-15) << "vertex " << v;
  }
  int below_reach = 0;
  for (size_t e = 0; e < edges.size(); ++e) {
    double nearest = reach;
    for (size_t f = 0; f < edges.size(); ++f) {
      const auto& a = edges[e];
      const auto& b = edges[f];
      if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
      const double d = rest_distance(s.vertices, a, b);
      if (d > kSelfMargin) nearest = std::min(nearest, d);
    }
    ASSERT_NEAR(c.edge[e], nearest, 1e-15) << "edge " << e;
    below_reach += nearest < reach;
  }
  EXPECT_GT(below_reach, 0);  // the second ring lies within the reach
}

TEST(RestClearance, RigidMotionDisplacesNothing) {
  std::mt19937 rng(7);
  const TriMesh s = fine_sphere();
  const Eigen::Matrix3d r = testing::random_rotation(rng);
  Points moved = s.vertices * r.transpose();
  moved.rowwise() += Eigen::RowVector3d(3.0, -1.0, 0.5);
  for (double d : fit_rigid_motion(s.vertices, moved).residual) EXPECT_LT(d, 1e-12);
  // One vertex pushed in by 1 mm: it moves by about that, the rest by far less.
  moved.row(5) -= 0.001 * (moved.row(5) - Eigen::RowVector3d(3.0, -1.0, 0.5)).normalized();
  const std::vector<double> d = fit_rigid_motion(s.vertices, moved).residual;
  EXPECT_NEAR(d[5], 0.001, 2e-5);
  for (size_t v = 0; v < d.size(); ++v)
    if (v != 5) {
      EXPECT_LT(d[v], 2e-5);
    }
}

CollisionSurface self_surface(const TriMesh& mesh, const Points& x0, const Points& x1) {
  CollisionSurface s;
  s.body = 1;
  s.kind = BodyKind::deformable;
  s.triangles = mesh.triangles;
  s.x0 = x0;
  s.x1 = x1;
  s.self_contact = true;
  s.rest = &mesh.vertices;
  return s;
}

TEST(RestClearance, TheDetectorSearchesOnlyWhatDeformationMayBringClose) {
  std::mt19937 rng(3);
  const TriMesh s = fine_sphere();
  CollisionDetector detector({kSelfMargin, 1});

  // Tumbling and falling as a whole: not one self pair offered.
  const Eigen::Matrix3d r = testing::random_rotation(rng);
  Points x0 = s.vertices * r.transpose();
  Points x1 = x0 * Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()).toRotationMatrix().transpose();
  x1.rowwise() += Eigen::RowVector3d(0.0, -0.004, 0.0);
  EXPECT_TRUE(detector.detect({self_surface(s, x0, x1)}, {}).empty());
  EXPECT_EQ(detector.last_stats().self_pairs, 0);

  // A dent pressed 3 mm into one side: searched near there, and every candidate
  // the oracle finds over all pairs is still found.
  Points dented = s.vertices;
  for (int v = 0; v < dented.rows(); ++v)
    if (dented(v, 0) > 0.027) dented(v, 0) -= 0.003 + 0.5 * (dented(v, 0) - 0.027);
  const CollisionSurface small = self_surface(s, dented, dented);
  const auto found = detector.detect({small}, {});
  testing::expect_same_candidates(found, brute_force_candidates({small}, {}, {kSelfMargin, 1}), 1e-9);
  const long long searched = detector.last_stats().self_pairs;
  EXPECT_GT(searched, 0);

  // Folded through itself: everything is searched, and still the oracle's set.
  Points folded = s.vertices;
  for (int v = 0; v < folded.rows(); ++v)
    if (folded(v, 0) > 0.018) folded(v, 0) -= 0.045;
  const CollisionSurface fold = self_surface(s, folded, folded);
  const auto found_fold = detector.detect({fold}, {});
  testing::expect_same_candidates(found_fold, brute_force_candidates({fold}, {}, {kSelfMargin, 1}), 1e-9);
  EXPECT_FALSE(found_fold.empty());
  EXPECT_GT(detector.last_stats().self_pairs, searched);
}

}  // namespace
}  // namespace recoil::sim
