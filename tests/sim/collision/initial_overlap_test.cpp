// Bodies that start inside one another: only overlaps deeper than the margin
// count, the deepest is named, and pairs of prescribed surfaces are left alone.
#include <gtest/gtest.h>

#include "sim/collision/initial_overlap.h"
#include "sim/geometry/primitives.h"

namespace recoil::sim {
namespace {

constexpr double kMargin = 0.002;  // m

// A 0.1 m cube centred at `center`, of the given kind.
CollisionSurface cube_at(const Eigen::Vector3d& center, BodyKind kind = BodyKind::rigid) {
  const TriMesh box = make_box(Eigen::Vector3d::Constant(0.1), 2);
  CollisionSurface s;
  s.kind = kind;
  s.x0 = box.vertices.rowwise() + center.transpose();
  s.x1 = s.x0;
  s.triangles = box.triangles;
  return s;
}

TEST(InitialOverlap, CubesPushedTogetherAreFoundWithTheirDepth) {
  // The upper cube's bottom corners sit 30 mm inside the lower one.
  const std::vector<CollisionSurface> surfaces = {cube_at({0, 0.05, 0}), cube_at({0, 0.12, 0})};
  const auto overlap = deepest_overlap(surfaces, {}, {}, kMargin);
  ASSERT_TRUE(overlap.has_value());
  EXPECT_EQ(overlap->inside_plane, -1);
  EXPECT_NE(overlap->surface, overlap->inside_surface);
  EXPECT_NEAR(overlap->depth, 0.03, 1e-12);
}

TEST(InitialOverlap, TouchingOrWithinTheMarginIsContactNotOverlap) {
  for (const double gap : {0.0, -0.001, 0.0005}) {
    const std::vector<CollisionSurface> surfaces = {cube_at({0, 0.05, 0}), cube_at({0, 0.15 + gap, 0})};
    EXPECT_FALSE(deepest_overlap(surfaces, {}, {}, kMargin).has_value()) << gap;
  }
}

TEST(InitialOverlap, ABodyBelowThePlaneIsBehindIt) {
  CollisionPlane ground;
  ground.normal = Eigen::Vector3d::UnitY();
  const auto overlap = deepest_overlap({cube_at({0, 0.02, 0})}, {ground}, {}, kMargin);
  ASSERT_TRUE(overlap.has_value());
  EXPECT_EQ(overlap->inside_plane, 0);
  EXPECT_NEAR(overlap->depth, 0.03, 1e-12);
  // Resting on it (1 mm in, within the margin) is a contact.
  EXPECT_FALSE(deepest_overlap({cube_at({0, 0.049, 0})}, {ground}, {}, kMargin).has_value());
}

TEST(InitialOverlap, PrescribedSurfacesMayOverlapEachOtherAndThePlane) {
  CollisionPlane ground;
  ground.normal = Eigen::Vector3d::UnitY();
  const std::vector<CollisionSurface> surfaces = {cube_at({0, 0.0, 0}, BodyKind::fixed),
                                                  cube_at({0.05, 0.0, 0}, BodyKind::kinematic)};
  EXPECT_FALSE(deepest_overlap(surfaces, {ground}, {}, kMargin).has_value());
}

}  // namespace
}  // namespace recoil::sim
