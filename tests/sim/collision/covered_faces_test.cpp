// Faces of fixed bodies that other fixed bodies cover: which ones are, and
// that the detector and the brute-force oracle leave them out alike.
#include "sim/collision/covered_faces.h"

#include <gtest/gtest.h>

#include "sim/collision/brute_force.h"
#include "sim/collision/collision_detector.h"
#include "sim/collision/exact_distance.h"
#include "tests/sim/collision/collision_candidate_checks.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::sim {
namespace {

using testing::moving_surface;

constexpr double kMargin = 0.002;

CollisionSurface lattice_box(const Eigen::Vector3d& size, const Eigen::Vector3d& centre, int body, BodyKind kind) {
  TriMesh m = make_box(size);
  m.vertices.rowwise() += centre.transpose();
  return moving_surface(m, body, kind, Eigen::Vector3d::Zero());
}

Eigen::Vector3d unit_normal(const CollisionSurface& s, Eigen::Index f) {
  return face_normal(point_at(s.x0, s.triangles(f, 0)), point_at(s.x0, s.triangles(f, 1)),
                     point_at(s.x0, s.triangles(f, 2)))
      .normalized();
}

// Per triangle of `s`, whether `covered` (empty: none) marks it, against
// whether its outward normal is one of `expected`.
void expect_covered_faces(const CollisionSurface& s, const std::vector<char>& covered,
                          const std::vector<Eigen::Vector3d>& expected) {
  int marked = 0;
  for (Eigen::Index f = 0; f < s.triangles.rows(); ++f) {
    bool want = false;
    for (const Eigen::Vector3d& n : expected) want = want || unit_normal(s, f).dot(n) > 0.999;
    const bool got = !covered.empty() && covered[static_cast<size_t>(f)] != 0;
    EXPECT_EQ(got, want) << "triangle " << f << " normal " << unit_normal(s, f).transpose();
    marked += got ? 1 : 0;
  }
  if (!expected.empty()) {
    EXPECT_GT(marked, 0);
  }
}

// Two static tiles laid edge to edge: each covers the other's side face at
// the seam, and nothing else.
TEST(CoveredFaces, AbuttingTilesCoverEachOthersSideFaceAtTheSeam) {
  const Eigen::Vector3d size(1.0, 0.2, 2.0);
  const std::vector<CollisionSurface> tiles = {lattice_box(size, Eigen::Vector3d(-0.5, -0.1, 0.0), 0, BodyKind::fixed),
                                               lattice_box(size, Eigen::Vector3d(0.5, -0.1, 0.0), 1, BodyKind::fixed)};
  const auto covered = covered_triangles(tiles, {}, 0.1 * kMargin);
  expect_covered_faces(tiles[0], covered[0], {Eigen::Vector3d::UnitX()});
  expect_covered_faces(tiles[1], covered[1], {-Eigen::Vector3d::UnitX()});

  // Kinematic bodies move, so nothing is ever covered between them; nor
  // between two tiles a millimetre apart.
  std::vector<CollisionSurface> moving = tiles;
  for (CollisionSurface& s : moving) s.kind = BodyKind::kinematic;
  for (const auto& flags : covered_triangles(moving, {}, 0.1 * kMargin)) EXPECT_TRUE(flags.empty());
  std::vector<CollisionSurface> apart = tiles;
  apart[1].x0.col(0).array() += 0.001;
  apart[1].x1 = apart[1].x0;
  for (const auto& flags : covered_triangles(apart, {}, 0.1 * kMargin)) EXPECT_TRUE(flags.empty());
}

// A block sunk into a slab with its top and one side flush with the slab's:
// its faces inside the slab are covered, the flush ones (turned the same way
// as the slab's) stay, and the slab, whose faces are all outside the block,
// keeps every face.
TEST(CoveredFaces, FacesInsideAreCoveredAndFlushFacesTurnedAlikeAreNot) {
  const std::vector<CollisionSurface> bodies = {
      lattice_box(Eigen::Vector3d(1.0, 0.2, 2.0), Eigen::Vector3d::Zero(), 0, BodyKind::fixed),
      lattice_box(Eigen::Vector3d(0.5, 0.1, 0.5), Eigen::Vector3d(0.25, 0.05, 0.0), 1, BodyKind::fixed)};
  const auto covered = covered_triangles(bodies, {}, 0.1 * kMargin);
  EXPECT_TRUE(covered[0].empty());
  expect_covered_faces(bodies[1], covered[1],
                       {-Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
                        -Eigen::Vector3d::UnitZ()});
}

// The ground covers what is behind it: the bottom of a static box resting
// on it, and the bottom and sides of one sunk up to its top.
TEST(CoveredFaces, ThePlaneCoversWhatIsBehindIt) {
  const CollisionPlane ground{-1, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()};
  const Eigen::Vector3d size(1.0, 0.2, 2.0);
  const std::vector<CollisionSurface> resting = {lattice_box(size, Eigen::Vector3d(0.0, 0.1, 0.0), 0, BodyKind::fixed)};
  expect_covered_faces(resting[0], covered_triangles(resting, {ground}, 0.1 * kMargin)[0], {-Eigen::Vector3d::UnitY()});
  const std::vector<CollisionSurface> sunk = {lattice_box(size, Eigen::Vector3d(0.0, -0.1, 0.0), 0, BodyKind::fixed)};
  expect_covered_faces(sunk[0], covered_triangles(sunk, {ground}, 0.1 * kMargin)[0],
                       {-Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                        Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()});
  std::vector<CollisionSurface> rigid = resting;
  rigid[0].kind = BodyKind::rigid;
  EXPECT_TRUE(covered_triangles(rigid, {ground}, 0.1 * kMargin)[0].empty());
}

// A block resting across the seam and sliding over it: no candidate names a
// covered triangle, none has a horizontal normal (a row at the block's lower
// edge), and the detector agrees with the oracle.
TEST(CoveredFaces, ABlockOnTheSeamGetsOnlyUpwardContactsFromTheTiles) {
  const Eigen::Vector3d size(1.0, 0.2, 2.0);
  std::vector<CollisionSurface> surfaces = {
      lattice_box(size, Eigen::Vector3d(-0.5, -0.1, 0.0), 0, BodyKind::fixed),
      lattice_box(size, Eigen::Vector3d(0.5, -0.1, 0.0), 1, BodyKind::fixed)};
  TriMesh block = make_box(Eigen::Vector3d::Constant(0.1));
  // Its leading edge 0.1 mm short of the seam, resting 0.05 mm up, moving
  // 8 mm towards +x and sinking 0.16 mm over the step (the contact-free
  // prediction's g h^2).
  block.vertices.rowwise() += Eigen::RowVector3d(-0.0501, 0.05005, 0.0);
  surfaces.push_back(moving_surface(block, 2, BodyKind::rigid, Eigen::Vector3d(0.008, -0.00016, 0.0)));
  CollisionDetector detector({kMargin, 1});
  const std::vector<ContactCandidate> found = detector.detect(surfaces, {});
  testing::expect_same_candidates(found, brute_force_candidates(surfaces, {}, {kMargin, 1}), 1e-9);
  const auto covered = covered_triangles(surfaces, {}, 0.1 * kMargin);
  ASSERT_FALSE(found.empty());
  for (const ContactCandidate& c : found) EXPECT_GT(std::abs(c.normal.y()), 0.999) << "normal " << c.normal.transpose();
  ASSERT_FALSE(covered[0].empty() || covered[1].empty());
  for (const ContactCandidate& c : found)
    if (c.kind == ContactKind::vertex_triangle && c.surface_b < 2) {
      EXPECT_FALSE(covered[static_cast<size_t>(c.surface_b)][static_cast<size_t>(c.primitive_b)]);
    }
}

}  // namespace
}  // namespace recoil::sim
