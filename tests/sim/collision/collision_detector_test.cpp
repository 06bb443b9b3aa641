// CollisionDetector (Embree) against the brute-force oracle on random meshes
// and poses, plus determinism and refitting.
#include "sim/collision/collision_detector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "sim/collision/brute_force.h"
#include "tests/sim/collision/collision_candidate_checks.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::sim {
namespace {

using testing::icosphere;
using testing::moving_surface;

// A scene with every kind of pair: a deformable self-contacting sphere, a
// rigid sphere pressed against it, a static slab under it, a kinematic box on
// the slab (a skipped pair) and a ground plane.
struct RandomScene {
  std::vector<CollisionSurface> surfaces;
  std::vector<CollisionPlane> planes;
  std::shared_ptr<Points> rest;  // the self-contact surface's rest shape, before the dent
};

RandomScene random_scene(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RandomScene scene;

  TriMesh a = icosphere(2);
  a.vertices *= 0.1;
  testing::perturb(a, 0.004, rng);
  a.vertices = a.vertices * testing::random_rotation(rng).transpose();
  CollisionSurface sa = moving_surface(a, 10, BodyKind::deformable, Eigen::Vector3d(u(rng), u(rng), u(rng)) * 0.003);
  // A deformation on top of the motion, so x1 is not a rigid image of x0.
  for (Eigen::Index i = 0; i < sa.x1.rows(); ++i)
    for (int k = 0; k < 3; ++k) sa.x1(i, k) += 0.002 * u(rng);
  sa.self_contact = true;
  scene.rest = std::make_shared<Points>(sa.x0);
  sa.rest = scene.rest.get();
  // Fold a dent into the sphere so self-contact has something to find.
  for (Eigen::Index i = 0; i < a.vertices.rows(); ++i)
    if (sa.x0(i, 0) > 0.08) {
      sa.x0(i, 0) -= 0.17;
      sa.x1(i, 0) -= 0.17;
    }
  scene.surfaces.push_back(sa);

  TriMesh b = icosphere(1);
  b.vertices *= 0.07;
  testing::perturb(b, 0.003, rng);
  const Eigen::Vector3d dir = Eigen::Vector3d(u(rng), u(rng), 0.5 + 0.5 * std::abs(u(rng))).normalized();
  const Eigen::Vector3d centre = dir * (0.1 + 0.07 + 0.004 * u(rng));
  b.vertices.rowwise() += centre.transpose();
  scene.surfaces.push_back(moving_surface(b, 20, BodyKind::rigid, -dir * 0.004,
                                          Eigen::AngleAxisd(0.05 * u(rng), Eigen::Vector3d::UnitY()).toRotationMatrix()));

  TriMesh slab = testing::box({0.3, 0.3, 0.02});
  slab.vertices.col(2).array() -= 0.1 + 0.02 + 0.002 * std::abs(u(rng));
  scene.surfaces.push_back(moving_surface(slab, 30, BodyKind::fixed, Eigen::Vector3d::Zero()));

  TriMesh lid = testing::box({0.05, 0.05, 0.02});
  lid.vertices.col(0).array() += 0.2;
  lid.vertices.col(2).array() -= 0.1 - 0.0005;  // resting on the slab
  scene.surfaces.push_back(moving_surface(lid, 40, BodyKind::kinematic, Eigen::Vector3d(0.001, 0, 0)));

  scene.planes.push_back({50, Eigen::Vector3d(0, 0, -0.099), Eigen::Vector3d(0, 0, 2.0)});
  return scene;
}

TEST(CollisionDetector, MatchesBruteForceOnRandomScenes) {
  std::array<int, 3> totals = {0, 0, 0};
  long self_total = 0;
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    const RandomScene scene = random_scene(seed);
    for (double margin : {0.002, 0.006}) {
      CollisionDetector detector({margin, 1});
      const auto fast = detector.detect(scene.surfaces, scene.planes);
      const auto oracle = brute_force_candidates(scene.surfaces, scene.planes, {margin, 1});
      const double diff = testing::expect_same_candidates(fast, oracle, 1e-9);
      testing::expect_consistent(fast, scene.surfaces, scene.planes, margin);
      std::array<int, 3> count = testing::count_by_kind(fast);
      self_total += std::count_if(fast.begin(), fast.end(), [](const auto& c) {
        return c.kind != ContactKind::vertex_plane && c.surface_a == 0 && c.surface_b == 0;
      });
      for (int k = 0; k < 3; ++k) totals[k] += count[k];
      std::cout << "seed " << seed << " margin " << margin << ": " << fast.size() << " candidates (vt " << count[0]
                << ", ee " << count[1] << ", vp " << count[2] << "), with toi "
                << std::count_if(fast.begin(), fast.end(), [](const auto& c) { return c.toi.has_value(); })
                << ", largest gap difference to brute force " << diff << " m\n";
      // The kinematic lid rests on the static slab: never tested (surfaces 2, 3).
      for (const ContactCandidate& c : fast)
        EXPECT_FALSE(c.kind != ContactKind::vertex_plane && c.surface_a >= 2 && c.surface_b >= 2);
    }
  }
  // The scenes really exercise every kind of pair (lower counts since the
  // candidate rule bounds approach by relative motion, narrow_phase.h, and
  // since between closed surfaces a vertex is a candidate only where the
  // surfaces meet, feature_cone.h).
  std::cout << "self-contact candidates over all scenes: " << self_total << "\n";
  EXPECT_GT(totals[0], 150);
  EXPECT_GT(totals[1], 400);
  EXPECT_GT(totals[2], 20);
  EXPECT_GT(self_total, 20);
}

TEST(CollisionDetector, RefitGivesTheSameAsFreshBuild) {
  RandomScene scene = random_scene(7);
  CollisionDetector detector({0.004, 1});
  detector.detect(scene.surfaces, scene.planes);
  EXPECT_EQ(detector.last_stats().rebuilt_surfaces, 4);
  // Next step: everything has moved to its predicted position and on.
  for (CollisionSurface& s : scene.surfaces) {
    const Points step = s.x1 - s.x0;
    s.x0 = s.x1;
    s.x1 += step;
  }
  const auto refitted = detector.detect(scene.surfaces, scene.planes);
  EXPECT_EQ(detector.last_stats().rebuilt_surfaces, 0);
  CollisionDetector fresh({0.004, 1});
  testing::expect_same_candidates(refitted, fresh.detect(scene.surfaces, scene.planes), 0.0);
  testing::expect_same_candidates(refitted, brute_force_candidates(scene.surfaces, scene.planes, {0.004, 1}), 1e-9);
}

TEST(CollisionDetector, SameOutputRunAfterRunAndAtAnyThreadCount) {
  const RandomScene scene = random_scene(9);
  CollisionDetector one({0.006, 1});
  const auto reference = one.detect(scene.surfaces, scene.planes);
  ASSERT_GT(reference.size(), 60u);
  testing::expect_same_candidates(one.detect(scene.surfaces, scene.planes), reference, 0.0);
  for (int threads : {2, 3, 8}) {
    CollisionDetector many({0.006, threads});
    testing::expect_same_candidates(many.detect(scene.surfaces, scene.planes), reference, 0.0);
  }
}

TEST(CollisionDetector, AnInputOfEitherOfTheLastTwoCallsIsAnsweredAgainWithoutASearch) {
  const RandomScene a = random_scene(11);
  RandomScene b = a, c = a;
  for (RandomScene* next : {&b, &c}) {
    for (CollisionSurface& s : next->surfaces) {
      const Points step = s.x1 - s.x0;
      s.x0 = s.x1;
      s.x1 += step;
    }
    if (next == &b) c = b;
  }
  CollisionDetector detector({0.004, 1});
  // Whether the call ran no query, and its answer is what a fresh detector gives.
  auto reused = [&](const RandomScene& scene) {
    const auto answer = detector.detect(scene.surfaces, scene.planes);
    const bool was_reused = detector.last_stats().reused;
    CollisionDetector fresh({0.004, 1});
    testing::expect_same_candidates(answer, fresh.detect(scene.surfaces, scene.planes), 0.0);
    return was_reused;
  };
  EXPECT_FALSE(reused(a));
  EXPECT_FALSE(reused(b));
  EXPECT_TRUE(reused(a));
  EXPECT_TRUE(reused(b));
  EXPECT_EQ(detector.last_stats().vertex_triangle_pairs + detector.last_stats().edge_edge_pairs, 0);
  EXPECT_FALSE(reused(c));  // takes the place of the older, a
  EXPECT_FALSE(reused(a));
  // Any difference in the input is a new search: one coordinate by one ulp, a plane.
  RandomScene nudged = a;
  nudged.surfaces[1].x1(3, 2) = std::nextafter(nudged.surfaces[1].x1(3, 2), 1.0);
  EXPECT_FALSE(reused(nudged));
  EXPECT_TRUE(reused(a));
  RandomScene tilted = a;
  tilted.planes[0].normal.x() = 1e-9;
  EXPECT_FALSE(reused(tilted));
}

TEST(CollisionDetector, FarApartSurfacesAreCulledUnlessTheyMoveThrough) {
  TriMesh left = icosphere(1), right = icosphere(1);
  left.vertices *= 0.1;
  right.vertices *= 0.1;
  right.vertices.col(0).array() += 1.0;  // 0.8 m of free space between them
  CollisionDetector detector({0.002, 1});
  const std::vector<CollisionSurface> resting = {
      moving_surface(left, 1, BodyKind::rigid, Eigen::Vector3d::Zero()),
      moving_surface(right, 2, BodyKind::deformable, Eigen::Vector3d::Zero())};
  EXPECT_TRUE(detector.detect(resting, {}).empty());
  EXPECT_EQ(detector.last_stats().vertex_triangle_pairs, 0);
  EXPECT_EQ(detector.last_stats().edge_edge_pairs, 0);
  // The left sphere crosses the whole gap and the right sphere in one step.
  const std::vector<CollisionSurface> flying = {
      moving_surface(left, 1, BodyKind::rigid, Eigen::Vector3d(1.5, 0.01, 0)),
      moving_surface(right, 2, BodyKind::deformable, Eigen::Vector3d::Zero())};
  const auto found = detector.detect(flying, {});
  testing::expect_same_candidates(found, brute_force_candidates(flying, {}, {0.002, 1}), 1e-9);
  const auto with_toi = std::count_if(found.begin(), found.end(), [](const auto& c) { return c.toi.has_value(); });
  std::cout << found.size() << " candidates for a sphere flying through another, " << with_toi << " with toi\n";
  EXPECT_GT(with_toi, 20);
}

TEST(CollisionDetector, BodiesFallingTogetherGiveNoCandidatesUntilTheyClose) {
  // Two spheres 1 cm apart, one above the other, both falling 3 cm in the
  // step (a pile before its bottom lands): summing their motions would allow
  // 6 cm of approach, but their relative motion is zero (narrow_phase.h),
  // so nothing is a candidate. With the lower one held still, the upper one closes the gap
  // within the step, and its lower vertices are.
  TriMesh lower = icosphere(2), upper = icosphere(2);
  lower.vertices *= 0.05;
  upper.vertices *= 0.05;
  upper.vertices.col(2).array() += 0.11;
  const Eigen::Vector3d fall(0.0, 0.0, -0.03);
  CollisionDetector detector({0.002, 1});
  const std::vector<CollisionSurface> together = {moving_surface(lower, 1, BodyKind::deformable, fall),
                                                  moving_surface(upper, 2, BodyKind::deformable, fall)};
  const auto apart = detector.detect(together, {});
  testing::expect_same_candidates(apart, brute_force_candidates(together, {}, {0.002, 1}), 1e-9);
  EXPECT_TRUE(apart.empty()) << apart.size() << " candidates";
  const std::vector<CollisionSurface> closing = {
      moving_surface(lower, 1, BodyKind::deformable, Eigen::Vector3d::Zero()),
      moving_surface(upper, 2, BodyKind::deformable, fall)};
  const auto found = detector.detect(closing, {});
  testing::expect_same_candidates(found, brute_force_candidates(closing, {}, {0.002, 1}), 1e-9);
  EXPECT_GT(found.size(), 0u);
  for (const ContactCandidate& c : found)  // from side B to side A: up when the upper sphere is A
    EXPECT_GT(c.normal.z() * (c.surface_a == 1 ? 1.0 : -1.0), 0.0);
}

TEST(CollisionDetector, PrimitivesSlidingPastEachOtherAreNoCandidates) {
  // A small block 1 cm above a slab slides 1.5 cm along it in the step: each
  // of its lower vertices is 1 cm from the slab's top face at both ends, so
  // the distance never drops below (1 + 1 - 1.5) / 2 cm, far outside the
  // 2 mm margin (narrow_phase.h), though 1 cm is within margin + motion.
  // Moved as far sideways but also 9.5 mm down, it closes the gap.
  const TriMesh slab = testing::box({0.1, 0.1, 0.01});
  TriMesh block = testing::box({0.02, 0.02, 0.01});
  block.vertices.rowwise() += Eigen::RowVector3d(0.0, 0.05, 0.03);  // clear of the slab's diagonal
  CollisionDetector detector({0.002, 1});
  for (const double down : {0.0, 0.0095}) {
    const std::vector<CollisionSurface> surfaces = {
        moving_surface(slab, 1, BodyKind::fixed, Eigen::Vector3d::Zero()),
        moving_surface(block, 2, BodyKind::rigid, Eigen::Vector3d(0.015, 0.0, -down))};
    const auto found = detector.detect(surfaces, {});
    testing::expect_same_candidates(found, brute_force_candidates(surfaces, {}, {0.002, 1}), 1e-9);
    if (down == 0.0) EXPECT_TRUE(found.empty()) << found.size() << " candidates sliding past";
    else EXPECT_EQ(std::count_if(found.begin(), found.end(), [](const ContactCandidate& c) { return c.surface_a == 1; }), 4);
  }
}

// A sheet folded over itself: two layers (81 vertices each) 1 mm apart in
// one deformable surface, which at rest lay side by side 0.2 m apart.
struct FoldedSheet {
  TriMesh sheet, unfolded;
};
FoldedSheet folded_sheet() {
  FoldedSheet out{testing::grid(8, 0.01), {}};
  TriMesh upper = out.sheet;
  upper.vertices.col(2).array() += 0.001;
  upper.vertices.col(0).array() += 0.003;
  TriMesh beside = out.sheet;
  out.unfolded = out.sheet;
  beside.vertices.col(0).array() += 0.2;
  append(out.sheet, upper);
  append(out.unfolded, beside);
  return out;
}

TEST(CollisionDetector, SelfContactSkipsNeighbours) {
  const auto [sheet, unfolded] = folded_sheet();
  CollisionSurface s = moving_surface(sheet, 1, BodyKind::deformable, Eigen::Vector3d::Zero());
  s.self_contact = true;
  s.rest = &unfolded.vertices;
  CollisionDetector detector({0.002, 1});
  const auto found = detector.detect({s}, {});
  testing::expect_same_candidates(found, brute_force_candidates({s}, {}, {0.002, 1}), 1e-9);
  ASSERT_FALSE(found.empty());
  const int layer = 81;  // vertices per layer
  for (const ContactCandidate& c : found) {
    // Only layer-to-layer pairs: within a flat layer everything else is >= a cell away.
    EXPECT_NE(c.a.vertex[0] < layer, c.b.vertex[0] < layer);
    for (int i = 0; i < c.a.count; ++i)
      for (int j = 0; j < c.b.count; ++j) EXPECT_NE(c.a.vertex[i], c.b.vertex[j]);
    EXPECT_NEAR(std::abs(c.normal.z()), 1.0, 1e-9);
  }
  // Without the flag: nothing.
  s.self_contact = false;
  EXPECT_TRUE(detector.detect({s}, {}).empty());
}

TEST(CollisionDetector, SelfContactSkipsPairsInOneElementOrInElementsSharingAFace) {
  // The folded sheet embedded in a lattice: each layer's vertices move with
  // elements of their own, or with elements that share a node or a face with
  // the other layer's (about a node the two can fold without straining).
  const auto [sheet, unfolded] = folded_sheet();
  const int layer = 81;  // vertices per layer
  Tets elements(4, 4);
  elements << 0, 1, 2, 3,  //
      4, 5, 6, 7,          // apart from the first
      3, 8, 9, 10,         // sharing node 3 with the first
      1, 2, 3, 11;         // sharing a face with the first
  Eigen::VectorXi vertex_element(2 * layer);
  CollisionSurface s = moving_surface(sheet, 1, BodyKind::deformable, Eigen::Vector3d::Zero());
  s.self_contact = true;
  s.rest = &unfolded.vertices;
  s.vertex_element = &vertex_element;
  s.elements = &elements;
  auto candidates = [&](int upper_element) {
    vertex_element.head(layer).setZero();
    vertex_element.tail(layer).setConstant(upper_element);
    CollisionDetector detector({0.002, 1});  // a fresh one: a detector reuses its last search for the same positions
    const auto found = detector.detect({s}, {});
    testing::expect_same_candidates(found, brute_force_candidates({s}, {}, {0.002, 1}), 1e-9);
    return found.size();
  };
  const size_t apart = candidates(1);
  EXPECT_GT(apart, 0u);
  s.vertex_element = nullptr;
  EXPECT_EQ(CollisionDetector({0.002, 1}).detect({s}, {}).size(), apart) << "elements apart must change nothing";
  s.vertex_element = &vertex_element;
  EXPECT_EQ(candidates(2), apart) << "the layers' elements share a node only";
  EXPECT_EQ(candidates(3), 0u) << "the layers' elements share a face";
  EXPECT_EQ(candidates(0), 0u) << "both layers in one element";
}

TEST(CollisionDetector, SelfContactCountsOnlyWhatDeformationClosed) {
  // Two layers of one surface that lie 2.5 mm apart at rest, just past the
  // 2 mm margin (a narrow modelled gap, or neighbours on a fine mesh). A pair
  // counts only within min(margin, rest distance - margin) = 0.5 mm.
  const double margin = 0.002, rest_gap = 0.0025;
  TriMesh rest = testing::grid(8, 0.01);
  TriMesh upper = rest;
  upper.vertices.col(2).array() += rest_gap;
  append(rest, upper);
  const int layer = 81;  // vertices per layer
  auto surface_at = [&](double gap, double slide) {
    TriMesh now = rest;
    now.vertices.bottomRows(layer).col(2).array() += gap - rest_gap;
    CollisionSurface s = moving_surface(now, 1, BodyKind::deformable, Eigen::Vector3d::Zero());
    s.x1.bottomRows(layer).col(0).array() += slide;  // the upper layer slides over the lower in the step
    s.self_contact = true;
    s.rest = &rest.vertices;
    return s;
  };
  CollisionDetector detector({margin, 1});
  auto candidates = [&](double gap, double slide) {
    const CollisionSurface s = surface_at(gap, slide);
    const auto found = detector.detect({s}, {});
    testing::expect_same_candidates(found, brute_force_candidates({s}, {}, {margin, 1}), 1e-9);
    return found.size();
  };
  // Undeformed, the upper layer sliding 0.6 mm within the step: within
  // margin + motion of the lower one, but nothing has closed.
  EXPECT_EQ(candidates(rest_gap, 0.0006), 0u);
  // Pressed to 1 mm: closer than the margin, but closed by less than one.
  EXPECT_EQ(candidates(0.001, 0.0), 0u);
  // Pressed to 0.4 mm: every upper vertex over the lower layer's interior.
  EXPECT_GT(candidates(0.0004, 0.0), 0u);
}

}  // namespace
}  // namespace recoil::sim
