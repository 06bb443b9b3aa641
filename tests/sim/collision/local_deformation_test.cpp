// The self-contact broad phase's local bound: every primitive a vertex or an
// edge may touch is listed by one of its cells (long edges and loose vertices
// too), the bound is zero for a rigid motion, and a surface bent smoothly far
// from its rest shape searches nothing of itself while its candidates stay
// the oracle's.
#include "sim/collision/local_deformation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/collision/brute_force.h"
#include "sim/collision/collision_detector.h"
#include "sim/collision/narrow_phase.h"
#include "sim/collision/rest_clearance.h"
#include "tests/sim/collision/collision_candidate_checks.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::sim {
namespace {

constexpr double kLocalMargin = 0.002;  // m

bool cell_lists(const RestCells& cells, int cell, int vertex) {
  const auto first = cells.near_vertices.begin() + cells.near_start[static_cast<size_t>(cell)];
  const auto last = cells.near_vertices.begin() + cells.near_start[static_cast<size_t>(cell) + 1];
  return std::binary_search(first, last, vertex);
}

// Checks the listing guarantee of local_deformation.h on every pair of `s`
// within the clearances' reach at rest: a vertex's cell lists the triangle
// and the vertex; one of an edge's cells lists both edges.
void expect_pairs_within_reach_listed(const TriMesh& s) {
  const std::vector<std::array<int, 2>> edges = unique_edges(s.triangles);
  const double reach = clearance_reach(kLocalMargin);
  const RestCells cells = rest_cells(s.vertices, s.triangles, edges, reach);
  for (int v = 0; v < s.num_vertices(); ++v) {
    const int cell = cells.vertex_cell[static_cast<size_t>(v)];
    ASSERT_GE(cell, 0);
    EXPECT_TRUE(cell_lists(cells, cell, v));
    for (int t = 0; t < s.num_triangles(); ++t) {
      const std::array<int, 3> tri = {s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)};
      if (rest_distance(s.vertices, v, tri) > reach) continue;
      for (int w : tri) EXPECT_TRUE(cell_lists(cells, cell, w)) << "vertex " << v << " triangle " << t;
    }
  }
  for (size_t e = 0; e < edges.size(); ++e)
    for (size_t f = 0; f < edges.size(); ++f) {
      if (rest_distance(s.vertices, edges[e], edges[f]) > reach) continue;
      bool held = false;  // one of e's cells lists both edges' ends
      for (int i = cells.edge_start[e]; i < cells.edge_start[e + 1] && !held; ++i) {
        const int c = cells.edge_cells[static_cast<size_t>(i)];
        held = cell_lists(cells, c, edges[e][0]) && cell_lists(cells, c, edges[e][1]) &&
               cell_lists(cells, c, edges[f][0]) && cell_lists(cells, c, edges[f][1]);
      }
      EXPECT_TRUE(held) << "edges " << e << " and " << f;
    }
}

TEST(LocalDeformation, EveryPrimitiveWithinReachIsListedByACellOfTheVertexOrEdge) {
  // A 3 cm sphere squashed to a fifth of its height: edges of 1-5 mm.
  TriMesh sphere = testing::icosphere(3);
  sphere.vertices *= 0.03;
  sphere.vertices.col(1) *= 0.2;
  expect_pairs_within_reach_listed(sphere);
  // Two 6 cm cubes of 12 triangles each, 3 mm apart, the second turned 35
  // degrees about x so that its 6-8 cm edges cross the first's near their
  // middles: edges spanning several cells, closest points far from any end.
  TriMesh pair = testing::box(Eigen::Vector3d::Constant(0.03));
  TriMesh turned = pair;
  turned.vertices = (turned.vertices * Eigen::AngleAxisd(0.61, Eigen::Vector3d::UnitX()).toRotationMatrix().transpose())
                        .rowwise() + Eigen::RowVector3d(0.063, 0.011, -0.007);
  append(pair, turned);
  expect_pairs_within_reach_listed(pair);
}

TEST(LocalDeformation, IsZeroForARigidMotionAndSeesABump) {
  TriMesh s = testing::grid(20, 0.002);
  const std::vector<std::array<int, 2>> edges = unique_edges(s.triangles);
  const RestCells cells = rest_cells(s.vertices, s.triangles, edges, clearance_reach(kLocalMargin));
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Points moved = ((s.vertices * turn.transpose()).rowwise() + Eigen::RowVector3d(0.3, -0.1, 2.0)).eval();
  const Points stepped = (moved.rowwise() + Eigen::RowVector3d(0.001, 0.0, -0.002)).eval();
  LocalDeformation rigid(cells, s.vertices, moved, stepped);
  for (int c = 0; c < cells.num_cells(); ++c) EXPECT_LT(rigid(c), 1e-12) << "cell " << c;
  // A bump of 1 mm in the middle of the sheet shows in the cells around it.
  Points bumped = s.vertices;
  for (Eigen::Index i = 0; i < bumped.rows(); ++i)
    bumped(i, 2) += 0.001 * std::exp(-bumped.row(i).head<2>().squaredNorm() / (0.005 * 0.005));
  LocalDeformation bent(cells, s.vertices, bumped, bumped);
  const int middle = cells.vertex_cell[static_cast<size_t>(s.num_vertices() / 2)];
  EXPECT_GT(bent(middle), 1e-4);
}

TEST(LocalDeformation, ASmoothlyBentSurfaceSearchesNothingOfItself) {
  // A 6.5 cm sheet with 1.8 mm cells (neighbours just past the 2 mm
  // margin), rolled round a cylinder of radius 0.35 m as it falls 1 mm: its
  // rim leaves the rest plane by 1.5 mm, more than the whole sheet's rigid
  // fit can excuse next to clearances of 2-2.5 mm, while each few
  // centimetres stay within a few tenths of a millimetre of rigid.
  TriMesh rest = testing::grid(36, 0.0018);
  TriMesh bent = rest;
  const double radius = 0.35;
  for (Eigen::Index i = 0; i < bent.vertices.rows(); ++i) {
    const double angle = rest.vertices(i, 1) / radius;
    bent.vertices(i, 1) = radius * std::sin(angle);
    bent.vertices(i, 2) = radius * (1.0 - std::cos(angle));
  }
  CollisionSurface s = testing::moving_surface(bent, 1, BodyKind::deformable, Eigen::Vector3d(0.0, 0.0, -0.001));
  s.self_contact = true;
  s.rest = &rest.vertices;
  CollisionDetector detector({kLocalMargin, 1});
  const auto found = detector.detect({s}, {});
  testing::expect_same_candidates(found, brute_force_candidates({s}, {}, {kLocalMargin, 1}), 1e-9);
  EXPECT_TRUE(found.empty());
  EXPECT_EQ(detector.last_stats().self_pairs, 0);
}

TEST(LocalDeformation, AVertexNoTriangleUsesIsStillBounded) {
  // A triangle and a vertex of no triangle 3 mm above it at rest, pressed to
  // 0.5 mm: the triangle alone is rigid, the vertex has moved 2.5 mm.
  TriMesh rest;
  rest.vertices.resize(4, 3);
  rest.vertices << 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0, 0.002, 0.002, 0.003;
  rest.triangles.resize(1, 3);
  rest.triangles << 0, 1, 2;
  TriMesh pressed = rest;
  pressed.vertices(3, 2) = 0.0005;
  CollisionSurface s = testing::moving_surface(pressed, 1, BodyKind::deformable, Eigen::Vector3d::Zero());
  s.self_contact = true;
  s.rest = &rest.vertices;
  CollisionDetector detector({kLocalMargin, 1});
  const auto found = detector.detect({s}, {});
  testing::expect_same_candidates(found, brute_force_candidates({s}, {}, {kLocalMargin, 1}), 1e-9);
  EXPECT_EQ(found.size(), 1u);
}

}  // namespace
}  // namespace recoil::sim
