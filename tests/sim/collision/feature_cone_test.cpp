// The contact normal between closed surfaces from the features' normal
// cones (feature_cone.h), and what it does for faces resting exactly on faces.
#include "sim/collision/feature_cone.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/collision/brute_force.h"
#include "sim/collision/collision_detector.h"
#include "sim/geometry/primitives.h"
#include "tests/sim/collision/collision_candidate_checks.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::sim {
namespace {

const Eigen::Vector3d kUp = Eigen::Vector3d::UnitY(), kSide = Eigen::Vector3d::UnitX();

TEST(FeatureCone, CosineToAConeOfFaceNormals) {
  const std::vector<Eigen::Vector3d> corner = {kUp, kSide, Eigen::Vector3d::UnitZ()};
  EXPECT_EQ(cone_cosine(Eigen::Vector3d(1, 1, 1).normalized(), corner), 1.0);
  EXPECT_NEAR(cone_cosine(-kUp, corner), 0.0, 1e-15);
  // Out of an edge's wedge beyond its side face: the nearest direction is that face's normal.
  EXPECT_NEAR(cone_cosine(Eigen::Vector3d(1, -1, 0).normalized(), {kUp, kSide}), std::sqrt(0.5), 1e-15);
  // Within a wedge, out of its plane: the projection onto the plane.
  EXPECT_NEAR(cone_cosine(Eigen::Vector3d(1, 1, 1).normalized(), {kUp, kSide}), std::sqrt(2.0 / 3.0), 1e-15);
  EXPECT_EQ(cone_cosine(kUp, {}), -1.0);
}

TEST(FeatureCone, ADirectionInBothConesIsKept) {
  // A rounded vertex facing a box's edge from outside, 45 degrees up.
  const Eigen::Vector3d d = Eigen::Vector3d(1, 1, 0).normalized() * 1e-3;
  const std::vector<Eigen::Vector3d> rounded = {Eigen::Vector3d(-1, -1, 0.1).normalized(),
                                                Eigen::Vector3d(-1, -1, -0.1).normalized()};
  const auto n = feature_cone_normal(d, Eigen::Vector3d::Zero(), {kUp, kSide}, rounded);
  ASSERT_TRUE(n.has_value());
  EXPECT_EQ(n->source, -1);
  EXPECT_NEAR(n->normal.dot(d.normalized()), 1.0, 1e-15);
}

TEST(FeatureCone, CoincidentVerticesTakeTheSharedFaceNormal) {
  // The border vertex of a cube's bottom face on the border of the top face
  // below, 1e-10 m off in a direction the solve left it: sideways (in the
  // lower cube's edge wedge, but the upper cube's surface does not face it)
  // or down and in.
  const std::vector<Eigen::Vector3d> lower_edge = {kUp, kSide}, upper_edge = {-kUp, kSide};
  for (const Eigen::Vector3d& noise : {Eigen::Vector3d(1.0, 0.01, 0.0), Eigen::Vector3d(-0.3, -1.0, 0.2)}) {
    const auto n = feature_cone_normal(1e-10 * noise.normalized(), Eigen::Vector3d::Zero(), lower_edge, upper_edge);
    ASSERT_TRUE(n.has_value());
    EXPECT_EQ(n->normal, kUp);
  }
  // Inside a flat face: the only direction of its cone.
  const auto n = feature_cone_normal(Eigen::Vector3d(0.7, 0.015, -0.7) * 1e-10, Eigen::Vector3d::Zero(), {kUp}, {-kUp});
  ASSERT_TRUE(n.has_value());
  EXPECT_EQ(n->normal, kUp);
}

TEST(FeatureCone, AVertexUnderAThinPlateIsNoContactOfItsTopFace) {
  // 1 mm under a 0.5 mm plate, within the margin of its top face through it:
  // the vertex's surface faces up, away from that face.
  EXPECT_FALSE(feature_cone_normal(-1.5e-3 * kUp, Eigen::Vector3d::Zero(), {kUp}, {kUp}).has_value());
}

TEST(FeatureCone, ImpactOfAVertexThatFacesNoFaceNeedsAStartClearOfTheMargin) {
  const Eigen::Vector3d aim = kUp;  // p came down
  const auto far = impact_cone_normal(aim, {kUp, kSide}, 0.03 * kUp, 0.002);
  ASSERT_TRUE(far.has_value());
  EXPECT_EQ(far->normal, kUp);
  EXPECT_FALSE(impact_cone_normal(aim, {kUp, kSide}, 1e-10 * kSide, 0.002).has_value());
}

// Two boxes whose faces touch exactly, the upper one's vertices moved by
// up to 1e-10 m as a solve leaves them: every vertex-triangle candidate
// between them holds along the shared face normal.
TEST(FeatureCone, BoxesRestingFaceOnFaceKeepTheirFaceNormal) {
  const double size = 0.2;
  TriMesh lower = make_box(Eigen::Vector3d::Constant(size), 4), upper = lower;
  upper.vertices.col(1).array() += size;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-1e-10, 1e-10);
  for (Eigen::Index v = 0; v < upper.vertices.rows(); ++v)
    for (int k = 0; k < 3; ++k) upper.vertices(v, k) += jitter(rng);
  const std::vector<CollisionSurface> surfaces = {
      testing::moving_surface(lower, 1, BodyKind::deformable, Eigen::Vector3d::Zero()),
      testing::moving_surface(upper, 2, BodyKind::deformable, Eigen::Vector3d::Zero())};
  CollisionDetector detector({0.002, 1});
  const auto found = detector.detect(surfaces, {});
  testing::expect_same_candidates(found, brute_force_candidates(surfaces, {}, {0.002, 1}), 1e-9);
  int face_contacts = 0;
  for (const ContactCandidate& c : found) {
    if (c.kind != ContactKind::vertex_triangle) continue;
    ++face_contacts;
    EXPECT_NEAR(std::abs(c.normal.y()), 1.0, 1e-9) << "vertex " << c.primitive_a << " of surface " << c.surface_a << " at " << surfaces[c.surface_a].x0.row(c.primitive_a) << " normal " << c.normal.transpose() << " gap " << c.gap << " triangle " << c.primitive_b << " weights " << c.b.weight[0] << " " << c.b.weight[1] << " " << c.b.weight[2] << " toi " << c.toi.has_value();
  }
  // Each of the 25 vertices of either face, held once.
  EXPECT_GE(face_contacts, 25);
  EXPECT_LE(face_contacts, 50);
}


// The detector caches each surface's vertex faces, which index by the
// triangles' vertices: a triangle naming a vertex past the end is caught by
// the surface's check first.
TEST(FeatureConeDeathTest, ATriangleNamingAVertexPastTheEndIsCaughtFirst) {
  TriMesh box = make_box(Eigen::Vector3d::Constant(0.1), 1);
  box.triangles(3, 1) = static_cast<int>(box.vertices.rows());
  const std::vector<CollisionSurface> surfaces = {testing::moving_surface(box, 1, BodyKind::rigid, Eigen::Vector3d::Zero())};
  EXPECT_DEATH(CollisionDetector({0.002, 1}).detect(surfaces, {}), "triangle 3 has vertex 8");
}

}  // namespace
}  // namespace recoil::sim
