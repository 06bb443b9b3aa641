// Fast objects against thin plates (no tunnelling) and degenerate geometry
// (parallel edges, coplanar faces, a vertex on an edge, zero-area triangles).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

#include "sim/collision/brute_force.h"
#include "sim/collision/collision_detector.h"
#include "sim/collision/embree_scene.h"
#include "sim/geometry/primitives.h"
#include "tests/sim/collision/collision_candidate_checks.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::sim {
namespace {

using testing::moving_surface;

// Runs the detector, checks it against the oracle and for consistency.
std::vector<ContactCandidate> detect_checked(const std::vector<CollisionSurface>& surfaces,
                                             const std::vector<CollisionPlane>& planes, double margin) {
  CollisionDetector detector({margin, 1});
  auto found = detector.detect(surfaces, planes);
  testing::expect_same_candidates(found, brute_force_candidates(surfaces, planes, {margin, 1}), 1e-9);
  testing::expect_consistent(found, surfaces, planes, margin);
  return found;
}

// A 2 cm cube falls 8 cm in one step through a 2 mm static plate (centred at
// z = 0); its bottom starts 2 cm above the plate's top face.
class ThinPlate : public ::testing::TestWithParam<BodyKind> {};

TEST_P(ThinPlate, FastSmallObjectIsCaught) {
  const double half = 0.01, plate_half = 0.001, fall = 0.08;
  TriMesh cube = testing::box({half, half, half});
  cube.vertices.col(2).array() += plate_half + 0.02 + half;
  // Tilted a little so no feature is axis-aligned with the plate.
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.1, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  const Eigen::RowVector3d centre = cube.vertices.colwise().mean();
  cube.vertices = ((cube.vertices.rowwise() - centre) * tilt.transpose()).rowwise() + centre;
  const CollisionSurface falling = moving_surface(cube, 1, GetParam(), Eigen::Vector3d(0.003, 0, -fall));
  const CollisionSurface plate =
      moving_surface(testing::box({0.2, 0.2, plate_half}), 2, BodyKind::fixed, Eigen::Vector3d::Zero());
  const auto found = detect_checked({falling, plate}, {}, 0.002);
  EmbreeDevice device;
  const TriangleScene plate_scene(device, plate.x0, plate.triangles, /*dynamic=*/false);

  // Every cube vertex whose path crosses the plate's top face must have a
  // candidate against it with the time of impact and an upward normal.
  int crossing = 0;
  for (int v = 0; v < falling.x0.rows(); ++v) {
    const double z0 = falling.x0(v, 2), z1 = falling.x1(v, 2);
    if (!(z0 > plate_half && z1 < plate_half)) continue;
    ++crossing;
    const double expected_toi = (z0 - plate_half) / (z0 - z1);
    // The first impact is with the top face (later ones, through the bottom
    // face, are candidates too).
    const ContactCandidate* first = nullptr;
    for (const ContactCandidate& c : found)
      if (c.kind == ContactKind::vertex_triangle && c.surface_a == 0 && c.primitive_a == v && c.toi) {
        EXPECT_NEAR(c.normal.z(), 1.0, 1e-9);  // always from the side the vertex comes from
        if (!first || *c.toi < *first->toi) first = &c;
      }
    const bool caught = first != nullptr;
    if (first) {
      EXPECT_NEAR(*first->toi, expected_toi, 1e-9);
      EXPECT_NEAR(first->gap, z0 - plate_half, 1e-9);
      // The linearised constraint n.(p1 - q1) >= 0 is violated by the
      // predicted motion, so the solver will act on it.
      EXPECT_LT(first->normal.dot(falling.x1.row(v).transpose() - first->b.evaluate(plate.x1)), 0.0);
      // An Embree ray along the vertex's path (the plate is static, so a ray
      // is exact here) agrees, to float precision.
      const Eigen::Vector3d origin = falling.x0.row(v).transpose();
      const auto hit = plate_scene.first_hit(origin, falling.x1.row(v).transpose() - origin, 0.0, 1.0);
      ASSERT_TRUE(hit.has_value());
      EXPECT_NEAR(hit->t, *first->toi, 1e-5);
      EXPECT_EQ(hit->triangle, first->primitive_b);
    }
    EXPECT_TRUE(caught) << "vertex " << v << " tunnels";
  }
  EXPECT_EQ(crossing, 8);
  std::cout << found.size() << " candidates, " << crossing << " crossing vertices caught\n";
}

INSTANTIATE_TEST_SUITE_P(Kinds, ThinPlate, ::testing::Values(BodyKind::rigid, BodyKind::deformable));

TEST(CollisionRobustness, ThinPlateAgainstFastSheetEdges) {
  // A single-sided open plate (a grid 0.2 m wide) and a stick-like box
  // falling through it across the plate's border (x = 0.1): the stick's
  // bottom edges cross the border edge, where the part of the stick over the
  // plate ends, and only an edge-edge impact holds that end. Crossings of
  // the plate's inner (flat) edges are left out: the stick's bottom vertices
  // over the plate and the border crossings hold it (narrow_phase.h).
  TriMesh stick = testing::box({0.05, 0.004, 0.004});
  stick.vertices = stick.vertices * Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix().transpose();
  stick.vertices.rowwise() += Eigen::RowVector3d(0.1, 0.007, 0.03);
  const CollisionSurface falling = moving_surface(stick, 1, BodyKind::rigid, Eigen::Vector3d(0, 0, -0.06));
  const CollisionSurface plate =
      moving_surface(testing::grid(4, 0.05), 2, BodyKind::fixed, Eigen::Vector3d::Zero());
  const auto found = detect_checked({falling, plate}, {}, 0.002);
  int edge_impacts = 0, inner_edges = 0;
  for (const ContactCandidate& c : found)
    if (c.kind == ContactKind::edge_edge && c.toi) {
      const Eigen::Vector3d stick_edge = c.a.evaluate(falling.x0) - falling.x0.row(c.a.vertex[0]).transpose();
      if (std::abs(stick_edge.z()) > 0.0) continue;  // a vertical edge sliding past
      ++edge_impacts;
      EXPECT_NEAR(c.normal.z(), 1.0, 1e-12);  // from the plate up to the stick that hits it from above
      const bool on_border = std::abs(plate.x0(c.b.vertex[0], 0) - 0.1) < 1e-12 &&
                             std::abs(plate.x0(c.b.vertex[1], 0) - 0.1) < 1e-12;
      if (!on_border) ++inner_edges;
    }
  std::cout << edge_impacts << " edge-edge impacts of horizontal stick edges with the plate, " << inner_edges
            << " with inner edges\n";
  EXPECT_GT(edge_impacts, 0);
  EXPECT_EQ(inner_edges, 0);
}

TEST(CollisionRobustness, ParallelEdgesAndCoplanarFaces) {
  // Two equal boxes, one exactly on top of the other (touching faces, parallel
  // and coincident edges) and pressing down by 0.1 mm over the step, then
  // 1 mm apart and still. Touching corner on corner, only the top face that
  // the corner moves into may give the normal, never a side face.
  for (double separation : {0.0, 0.001}) {
    TriMesh lower = testing::box({0.05, 0.05, 0.05});
    TriMesh upper = lower;
    upper.vertices.col(2).array() += 0.1 + separation;
    const Eigen::Vector3d press(0.0, 0.0, separation == 0.0 ? -1e-4 : 0.0);
    const auto found = detect_checked({moving_surface(lower, 1, BodyKind::rigid, Eigen::Vector3d::Zero()),
                                       moving_surface(upper, 2, BodyKind::deformable, press)},
                                      {}, 0.002);
    // The 4 facing corners of each box meet the 4 of the other: each pair is
    // found from both sides but is one constraint, so one candidate per pair.
    int vertex_candidates = 0;
    for (const ContactCandidate& c : found) {
      ASSERT_TRUE(c.normal.allFinite());
      EXPECT_NEAR(c.gap, separation, 1e-12);
      EXPECT_NEAR(std::abs(c.normal.z()), 1.0, 1e-12);
      vertex_candidates += c.kind == ContactKind::vertex_triangle;
    }
    EXPECT_EQ(vertex_candidates, 4) << "separation " << separation;
    std::cout << "separation " << separation << ": " << found.size() << " candidates\n";
  }
}

TEST(CollisionRobustness, NearlyCoincidentGridsGiveOneContactPerVertexPair) {
  // Two 10 cm boxes with 3x3 face grids, the upper 0.2 mm above the lower and
  // each of its vertices nudged sideways by up to 5 microns (a jelly cube
  // resting on another after a few steps). Every vertex of the facing grids
  // is near a vertex of the other; before the contact reduction this gave
  // up to six nearly equal rows per pair (narrowly different weights and
  // normals) and edge-edge rows between the parallel grid lines, and the
  // contact solve never converged. One contact per pair of the 4 x 4
  // facing vertices, all along the vertical.
  const TriMesh lower = make_box(Eigen::Vector3d::Constant(0.1), 3);
  TriMesh upper = lower;
  for (Eigen::Index i = 0; i < upper.vertices.rows(); ++i) {
    upper.vertices(i, 0) += 5e-6 * static_cast<double>(i % 3 - 1);
    upper.vertices(i, 1) += 5e-6 * static_cast<double>(i % 2) + 0.1002;
  }
  const auto found = detect_checked({moving_surface(lower, 1, BodyKind::deformable, Eigen::Vector3d::Zero()),
                                     moving_surface(upper, 2, BodyKind::deformable, Eigen::Vector3d::Zero())},
                                    {}, 0.002);
  int vertex_candidates = 0, edge_candidates = 0;
  double worst_tilt = 0.0;
  for (const ContactCandidate& c : found) {
    vertex_candidates += c.kind == ContactKind::vertex_triangle;
    edge_candidates += c.kind == ContactKind::edge_edge;
    worst_tilt = std::max(worst_tilt, std::acos(std::min(1.0, std::abs(c.normal.y()))));
  }
  std::cout << "nearly coincident grids: " << vertex_candidates << " vertex-triangle, " << edge_candidates
            << " edge-edge candidates, largest normal tilt " << worst_tilt << " rad\n";
  EXPECT_EQ(vertex_candidates, 16);
  EXPECT_EQ(edge_candidates, 0);
  EXPECT_LT(worst_tilt, 0.05);
}

TEST(CollisionRobustness, VertexExactlyOnAnEdge) {
  // A square of two triangles (diagonal 0-2) and a tetrahedron-like vertex
  // lying exactly on the diagonal's midpoint: one candidate on the edge.
  TriMesh square;
  square.vertices.resize(4, 3);
  square.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  square.triangles.resize(2, 3);
  square.triangles << 0, 1, 2, 0, 2, 3;
  TriMesh point = testing::box({0.1, 0.1, 0.1});
  point.vertices.rowwise() += Eigen::RowVector3d(0.6, 0.6, 0.1);  // corner 0 at (0.5, 0.5, 0)
  const auto found =
      detect_checked({moving_surface(point, 1, BodyKind::rigid, Eigen::Vector3d(0, 0, -0.001)),
                      moving_surface(square, 2, BodyKind::fixed, Eigen::Vector3d::Zero())},
                     {}, 0.002);
  int on_edge = 0;
  for (const ContactCandidate& c : found)
    if (c.kind == ContactKind::vertex_triangle && c.surface_a == 0 && c.primitive_a == 0) {
      ++on_edge;
      EXPECT_EQ(c.gap, 0.0);
      EXPECT_EQ(c.primitive_b, 0);  // the lower triangle id of the two sharing the edge
      EXPECT_NEAR(c.normal.z(), 1.0, 1e-12);  // face normal, against the downward motion
      const Eigen::Vector3d q = c.b.evaluate(square.vertices);
      EXPECT_LT((q - Eigen::Vector3d(0.5, 0.5, 0)).norm(), 1e-12);
    }
  EXPECT_EQ(on_edge, 1);
}

TEST(CollisionRobustness, RestingVertexKeepsTheOutwardNormalWhicheverWayItMoves) {
  // A box corner exactly on a face's interior at the start, leaving it, still,
  // or pressing into it: the normal is the face's outward normal each time.
  TriMesh square;
  square.vertices.resize(4, 3);
  square.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  square.triangles.resize(2, 3);
  square.triangles << 0, 1, 2, 0, 2, 3;
  TriMesh probe = testing::box({0.1, 0.1, 0.1});
  probe.vertices.rowwise() += Eigen::RowVector3d(0.8, 0.3, 0.1);  // corner 0 at (0.7, 0.2, 0)
  for (double dz : {0.001, 0.0, -0.001}) {
    const auto found =
        detect_checked({moving_surface(probe, 1, BodyKind::rigid, Eigen::Vector3d(0.0005, 0, dz)),
                        moving_surface(square, 2, BodyKind::fixed, Eigen::Vector3d::Zero())},
                       {}, 0.002);
    int resting = 0;
    for (const ContactCandidate& c : found)
      if (c.kind == ContactKind::vertex_triangle && c.surface_a == 0 && c.primitive_a == 0) {
        ++resting;
        EXPECT_EQ(c.primitive_b, 0);
        EXPECT_EQ(c.gap, 0.0);
        EXPECT_NEAR(c.normal.z(), 1.0, 1e-12) << "dz " << dz;
      }
    EXPECT_EQ(resting, 1) << "dz " << dz;
  }
}

TEST(CollisionRobustness, VertexOverAFacetIsHeldByThatFacetAlone) {
  // A faceted roller (32-gon, 5 cm radius) and a vertex 0.5 mm above one of
  // its facets, 1 mm in from the ridge to the next facet. The neighbouring
  // triangles in reach (across that ridge and the facet's diagonal) have
  // their closest points on their shared edges, with normals p - q along the
  // surface: rows that, with their weights held for the step, wall the
  // vertex in wherever the roller turns (candidate_reduction.h). Only the
  // facet under the vertex may hold it, along its face normal.
  const TriMesh roller = make_cylinder(0.05, 0.2, 32);
  int facet = -1;  // a side triangle (normal across the axis), away from the caps
  for (Eigen::Index t = 0; t < roller.triangles.rows() && facet < 0; ++t) {
    const Eigen::Vector3d a = roller.vertices.row(roller.triangles(t, 0)).transpose();
    const Eigen::Vector3d b = roller.vertices.row(roller.triangles(t, 1)).transpose();
    const Eigen::Vector3d c = roller.vertices.row(roller.triangles(t, 2)).transpose();
    if (std::abs((b - a).cross(c - a).normalized().y()) < 1e-9) facet = static_cast<int>(t);
  }
  ASSERT_GE(facet, 0);
  std::array<Eigen::Vector3d, 3> v;
  for (int k = 0; k < 3; ++k) v[static_cast<size_t>(k)] = roller.vertices.row(roller.triangles(facet, k)).transpose();
  const Eigen::Vector3d normal = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
  ASSERT_GT(normal.dot(Eigen::Vector3d(v[0].x(), 0.0, v[0].z())), 0.0) << "outward (axis along y)";
  // The triangle's edge that runs along the axis (a ridge), and a point on the
  // facet 1 mm in from it, half-way along.
  int ridge = -1;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = v[static_cast<size_t>((k + 1) % 3)] - v[static_cast<size_t>(k)];
    if (std::abs(e.normalized().y()) > 0.999) ridge = k;
  }
  ASSERT_GE(ridge, 0) << "a side triangle has an edge along the axis";
  const Eigen::Vector3d r0 = v[static_cast<size_t>(ridge)], r1 = v[static_cast<size_t>((ridge + 1) % 3)];
  const Eigen::Vector3d third = v[static_cast<size_t>((ridge + 2) % 3)];
  const Eigen::Vector3d axis = (r1 - r0).normalized();
  Eigen::Vector3d inward = third - r0;
  inward = (inward - inward.dot(axis) * axis).normalized();
  const Eigen::Vector3d on_facet = r0 + 0.35 * (r1 - r0) + 0.001 * inward;
  TriMesh probe = testing::box({0.002, 0.002, 0.002});
  probe.vertices.rowwise() -= probe.vertices.row(0);
  const Eigen::Matrix3d turn = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(1, 1, 1), normal).toRotationMatrix();
  probe.vertices = (probe.vertices * turn.transpose()).rowwise() + (on_facet + 0.0005 * normal).transpose();
  const auto found = detect_checked({moving_surface(probe, 1, BodyKind::deformable, Eigen::Vector3d::Zero()),
                                     moving_surface(roller, 2, BodyKind::kinematic, Eigen::Vector3d::Zero())},
                                    {}, 0.002);
  int held = 0;
  for (const ContactCandidate& c : found)
    if (c.kind == ContactKind::vertex_triangle && c.surface_a == 0 && c.primitive_a == 0) {
      ++held;
      EXPECT_EQ(c.primitive_b, facet);
      EXPECT_NEAR(c.normal.dot(normal), 1.0, 1e-9);
      EXPECT_NEAR(c.gap, 0.0005, 1e-9);
    }
  EXPECT_EQ(held, 1);
}

// A tetrahedron whose edge (vertices 0, 1) crosses the box's top-front ridge
// (y = z = 5 cm, along x) at right angles, its middle `depth` metres inside
// the box along the ridge's outward bisector (negative: outside); the other
// two vertices stand 5 mm out from the box. Counter-clockwise from outside.
TriMesh tetrahedron_across_the_ridge(double depth) {
  const Eigen::Vector3d out = Eigen::Vector3d(0, 1, 1).normalized(), along = Eigen::Vector3d(0, 1, -1).normalized();
  const Eigen::Vector3d middle = Eigen::Vector3d(0, 0.05, 0.05) - depth * out;
  TriMesh tet;
  tet.vertices.resize(4, 3);
  tet.vertices.row(0) = (middle + 0.005 * along).transpose();
  tet.vertices.row(1) = (middle - 0.005 * along).transpose();
  tet.vertices.row(2) = (middle + 0.005 * out + Eigen::Vector3d(0.003, 0, 0)).transpose();
  tet.vertices.row(3) = (middle + 0.005 * out - Eigen::Vector3d(0.003, 0, 0)).transpose();
  tet.triangles.resize(4, 3);
  tet.triangles << 0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2;
  const Eigen::Vector3d centre = tet.vertices.colwise().mean().transpose();
  for (Eigen::Index f = 0; f < 4; ++f) {  // turn each face outwards
    const Eigen::Vector3d a = tet.vertices.row(tet.triangles(f, 0)).transpose();
    const Eigen::Vector3d b = tet.vertices.row(tet.triangles(f, 1)).transpose();
    const Eigen::Vector3d c = tet.vertices.row(tet.triangles(f, 2)).transpose();
    if ((b - a).cross(c - a).dot(a - centre) < 0.0) std::swap(tet.triangles(f, 1), tet.triangles(f, 2));
  }
  return tet;
}

TEST(CollisionRobustness, EdgeAlreadyThroughARidgeCountsAsPenetrating) {
  // A ridge that slipped through a body's face between two of its vertices
  // (while the face was flat, so no edge pair held it) lies inside that
  // body once the face bends round it. Its normal p - q would then hold the
  // edges crossed, with a positive gap; it must point out of the box instead,
  // with the depth as a negative gap, so that the solver pushes the edge out.
  // The same edge as far outside keeps p - q. Also between two closed
  // deformable bodies, and whichever body is side A.
  const double depth = 0.0002;
  for (BodyKind box_kind : {BodyKind::fixed, BodyKind::deformable})
    for (double sign : {1.0, -1.0}) {
      const CollisionSurface tet = moving_surface(tetrahedron_across_the_ridge(sign * depth), 1,
                                                  BodyKind::deformable, Eigen::Vector3d::Zero());
      const CollisionSurface box = moving_surface(testing::box({0.05, 0.05, 0.05}), 2, box_kind, Eigen::Vector3d::Zero());
      const auto found = detect_checked({tet, box}, {}, 0.002);
      int crossings = 0;
      for (const ContactCandidate& c : found) {
        if (c.kind != ContactKind::edge_edge) continue;
        ++crossings;
        const bool tet_is_a = c.surface_a == 0;
        const std::array<int, 2> tet_edge = tet_is_a ? std::array<int, 2>{c.a.vertex[0], c.a.vertex[1]}
                                                     : std::array<int, 2>{c.b.vertex[0], c.b.vertex[1]};
        const std::array<int, 2> ridge = tet_is_a ? std::array<int, 2>{c.b.vertex[0], c.b.vertex[1]}
                                                  : std::array<int, 2>{c.a.vertex[0], c.a.vertex[1]};
        EXPECT_EQ(std::min(tet_edge[0], tet_edge[1]), 0);
        EXPECT_EQ(std::max(tet_edge[0], tet_edge[1]), 1);
        EXPECT_EQ(std::min(ridge[0], ridge[1]), 6);
        EXPECT_EQ(std::max(ridge[0], ridge[1]), 7);
        // From the box to the tetrahedron: out of the box across its ridge.
        const Eigen::Vector3d out_of_box = Eigen::Vector3d(0, 1, 1).normalized() * (tet_is_a ? 1.0 : -1.0);
        EXPECT_NEAR(c.normal.dot(out_of_box), 1.0, 1e-9) << "depth " << sign * depth;
        EXPECT_NEAR(c.gap, -sign * depth, 1e-9);
      }
      EXPECT_EQ(crossings, 1) << "depth " << sign * depth;
    }
}

TEST(CollisionRobustness, DegenerateTriangles) {
  // A surface with a zero-area triangle (collinear) and one with a repeated
  // vertex, next to a moving small box.
  TriMesh bad;
  bad.vertices.resize(5, 3);
  bad.vertices << 0, 0, 0, 1, 0, 0, 0.5, 0, 0, 0, 1, 0, 0.4, 0.4, 0;
  bad.triangles.resize(3, 3);
  bad.triangles << 0, 1, 2,  // collinear
      0, 4, 4,               // repeated vertex
      0, 1, 3;               // a proper one
  TriMesh probe = testing::box({0.05, 0.05, 0.05});
  probe.vertices.rowwise() += Eigen::RowVector3d(0.5, -0.0505, 0.0);  // a face 0.5 mm from the collinear one
  const CollisionSurface deg = moving_surface(bad, 2, BodyKind::deformable, Eigen::Vector3d(0, 0, 0.0001));
  const CollisionSurface box = moving_surface(probe, 1, BodyKind::rigid, Eigen::Vector3d(0, 0.0002, 0));
  const auto found = detect_checked({box, deg}, {}, 0.002);
  bool saw_degenerate = false;
  for (const ContactCandidate& c : found) {
    ASSERT_TRUE(c.normal.allFinite() && std::isfinite(c.gap));
    if (c.kind == ContactKind::vertex_triangle && c.surface_b == 1 && c.primitive_b != 2) saw_degenerate = true;
    if (c.kind == ContactKind::vertex_triangle && c.surface_a == 1) saw_degenerate = true;
  }
  EXPECT_TRUE(saw_degenerate);
  EXPECT_FALSE(found.empty());
}

TEST(CollisionRobustness, VertexOnVertexGivesOneCandidate) {
  // A box corner exactly on a grid vertex shared by six triangles.
  TriMesh sheet = testing::grid(4, 0.1);  // vertex 12 is at the origin
  TriMesh probe = testing::box({0.02, 0.02, 0.02});
  probe.vertices.rowwise() += Eigen::RowVector3d(0.02, 0.02, 0.02);  // corner 0 at the origin
  const auto found =
      detect_checked({moving_surface(probe, 1, BodyKind::deformable, Eigen::Vector3d(0, 0, -0.0005)),
                      moving_surface(sheet, 2, BodyKind::fixed, Eigen::Vector3d::Zero())},
                     {}, 0.002);
  int at_corner = 0;
  for (const ContactCandidate& c : found)
    if (c.kind == ContactKind::vertex_triangle && c.surface_a == 0 && c.primitive_a == 0) {
      ++at_corner;
      EXPECT_EQ(c.gap, 0.0);
      EXPECT_NEAR(c.normal.z(), 1.0, 1e-12);
    }
  EXPECT_EQ(at_corner, 1);
}

TEST(CollisionRobustness, PlanesAndPrescribedSurfaces) {
  TriMesh cube = testing::box({0.05, 0.05, 0.05});
  cube.vertices.col(2).array() += 0.051;  // 1 mm above the ground
  CollisionSurface moving = moving_surface(cube, 1, BodyKind::rigid, Eigen::Vector3d(0, 0, -0.003));
  CollisionSurface parked = moving_surface(cube, 2, BodyKind::kinematic, Eigen::Vector3d::Zero());
  const std::vector<CollisionPlane> ground = {{7, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()}};
  const auto found = detect_checked({moving}, ground, 0.002);
  ASSERT_EQ(found.size(), 4u);  // the four bottom corners
  for (const ContactCandidate& c : found) {
    EXPECT_EQ(c.kind, ContactKind::vertex_plane);
    EXPECT_EQ(c.body_b, 7);
    EXPECT_NEAR(c.gap, 0.001, 1e-12);
    ASSERT_TRUE(c.toi.has_value());
    EXPECT_NEAR(*c.toi, 1.0 / 3.0, 1e-12);
  }
  EXPECT_TRUE(detect_checked({parked}, ground, 0.002).empty());
}

}  // namespace
}  // namespace recoil::sim
