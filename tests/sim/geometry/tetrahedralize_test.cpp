// Lattice tetrahedralization, boundary extraction and surface embedding on a
// sphere, a torus and the bunny, and a sphere with a hole (the winding-number
// inside test).
#include "sim/geometry/tetrahedralize.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include "core/error.h"
#include "sim/geometry/boundary.h"
#include "sim/geometry/embedding.h"
#include "sim/geometry/mesh_import.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/primitives.h"
#include "tests/test_support.h"

namespace recoil::sim {
namespace {

struct Checked {
  double volume_ratio = 0.0;  // lattice volume / surface volume
  int outside = 0;
};

// Every property the issue asks of a tetrahedralized and embedded surface.
Checked check_tetrahedralization(const char* name, const TriMesh& surface, int resolution) {
  TetrahedralizeStats stats;
  const TetMesh tets = tetrahedralize(surface, resolution, &stats);
  EXPECT_GT(tets.num_tets(), 0);
  for (int t = 0; t < tets.num_tets(); ++t) EXPECT_GT(tet_volume(tets, t), 0.0) << name << " tet " << t;

  // Conforming: every face is shared by at most two tets, and the boundary is a
  // closed, consistently oriented surface enclosing exactly the tets' volume.
  std::map<std::array<int, 3>, int> face_use;
  constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (int t = 0; t < tets.num_tets(); ++t)
    for (const auto& f : kFaces) {
      std::array<int, 3> key = {tets.tets(t, f[0]), tets.tets(t, f[1]), tets.tets(t, f[2])};
      std::sort(key.begin(), key.end());
      ++face_use[key];
    }
  for (const auto& [face, count] : face_use) EXPECT_LE(count, 2);
  const TriMesh boundary = boundary_surface(tets);
  const MeshStats bstats = compute_mesh_stats(boundary);
  EXPECT_EQ(bstats.boundary_edges, 0) << name;
  EXPECT_EQ(bstats.inconsistent_edges, 0) << name;
  const double tet_volume_sum = total_volume(tets);
  EXPECT_NEAR(enclosed_volume(boundary), tet_volume_sum, 1e-9 * tet_volume_sum) << name;

  // Embedding: weights sum to 1 and reproduce every surface vertex.
  const Embedding e = embed_points(tets, surface.vertices);
  Points back;
  embedded_positions(e, tets.tets, tets.nodes, back);
  double worst_sum = 0.0, worst_pos = 0.0;
  for (int v = 0; v < surface.num_vertices(); ++v) {
    worst_sum = std::max(worst_sum, std::abs(e.weights.row(v).sum() - 1.0));
    worst_pos = std::max(worst_pos, (back.row(v) - surface.vertices.row(v)).norm());
  }
  EXPECT_LT(worst_sum, 1e-12) << name;
  EXPECT_LT(worst_pos, 1e-9) << name;

  const double surface_volume = enclosed_volume(surface);
  Checked out{tet_volume_sum / surface_volume, e.outside};
  std::cout << name << " at resolution " << resolution << ": " << tets.num_tets() << " tets, " << tets.num_nodes()
            << " nodes, cells crossing " << stats.cells_crossing << " inside " << stats.cells_inside
            << ", lattice/surface volume " << out.volume_ratio << ", vertices outside the tets " << e.outside
            << ", embedding error " << worst_pos << " m\n";
  EXPECT_GE(out.volume_ratio, 1.0) << name << ": the lattice must cover the surface";
  return out;
}

TEST(Tetrahedralize, SphereCoversSurfaceAndEmbedsEveryVertex) {
  const Checked c = check_tetrahedralization("sphere", make_sphere(0.5, 3), 16);
  EXPECT_LT(c.volume_ratio, 1.6);
  EXPECT_EQ(c.outside, 0);  // the crossing cells contain the whole surface
}

TEST(Tetrahedralize, TorusCoversSurfaceAndEmbedsEveryVertex) {
  const Checked c = check_tetrahedralization("torus", make_torus(0.5, 0.2, 48, 16), 16);
  EXPECT_LT(c.volume_ratio, 2.0);
  EXPECT_EQ(c.outside, 0);
}

TEST(Tetrahedralize, BunnyCoversSurfaceAndEmbedsEveryVertex) {
  const TriMesh bunny = import_surface(test::source_path("assets/meshes/bunny.obj"));
  // The bunny's scanned surface was closed for the repository; the test holds
  // for open scans as well (HoledSphereKeepsItsInside).
  const Checked c = check_tetrahedralization("bunny", bunny, 16);
  EXPECT_LT(c.volume_ratio, 1.8);
}

TEST(Tetrahedralize, CoarseResolutionsStillValid) {
  check_tetrahedralization("sphere", make_sphere(1.0, 2), 2);
  check_tetrahedralization("box", make_box(Eigen::Vector3d(2.0, 0.5, 0.3), 2), 4);
}

TEST(Tetrahedralize, HoledSphereKeepsItsInside) {
  const TriMesh closed = make_sphere(0.5, 3);
  TriMesh holed = closed;
  // Remove a few triangles around one vertex: a small hole.
  holed.triangles = closed.triangles.topRows(closed.num_triangles() - 6);
  EXPECT_FALSE(compute_mesh_stats(holed).watertight);
  const int closed_tets = tetrahedralize(closed, 10).num_tets();
  const int holed_tets = tetrahedralize(holed, 10).num_tets();
  std::cout << "sphere at resolution 10: " << closed_tets << " tets closed, " << holed_tets << " with a hole\n";
  EXPECT_EQ(closed_tets, holed_tets);
}

// An open scan from Debian's assimp-testmodels: a sphere of radius 1.5 m with
// a hole (9 boundary edges) is filled like a closed one.
TEST(Tetrahedralize, AssimpSphereWithAHoleIsFilled) {
  const std::filesystem::path file = "/usr/share/assimp/models/STL/sphereWithHole.stl";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const TriMesh sphere = import_surface(file);
  ASSERT_FALSE(compute_mesh_stats(sphere).watertight);
  const Checked c = check_tetrahedralization("sphereWithHole", sphere, 12);
  EXPECT_LT(c.volume_ratio, 1.8);
  EXPECT_EQ(c.outside, 0);
}

TEST(Tetrahedralize, InwardWoundSurfaceIsStillSolid) {
  TriMesh inward = make_sphere(0.5, 3);
  const Eigen::VectorXi second = inward.triangles.col(1);
  inward.triangles.col(1) = inward.triangles.col(2);
  inward.triangles.col(2) = second;
  EXPECT_EQ(tetrahedralize(inward, 10).num_tets(), tetrahedralize(make_sphere(0.5, 3), 10).num_tets());
}

TEST(Tetrahedralize, SameSurfaceSameBytes) {
  const TriMesh bunny = import_surface(test::source_path("assets/meshes/bunny.obj"));
  const TetMesh a = tetrahedralize(bunny, 12), b = tetrahedralize(bunny, 12);
  ASSERT_EQ(a.nodes.rows(), b.nodes.rows());
  ASSERT_EQ(a.tets.rows(), b.tets.rows());
  EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), sizeof(double) * static_cast<size_t>(a.nodes.size())), 0);
  EXPECT_TRUE(a.tets == b.tets);
}

// The lattice prefers no direction: a cube of an even number of cells is
// split the same way on either side of each of its mid-planes, so its tets
// mirrored across any of them are its tets again. One diagonal for every cell
// mapped (0, 0, 0)-(1, 1, 1) diagonals onto (1, 0, 0)-(0, 1, 1) ones.
TEST(Tetrahedralize, AnEvenCubeIsItsOwnMirrorImage) {
  const TetMesh tets = tetrahedralize(make_box(Eigen::Vector3d::Constant(0.2), 4), 4);
  ASSERT_EQ(tets.num_tets(), 6 * 4 * 4 * 4);  // the cube's own cells, no more
  const Eigen::Vector3d lo = tets.nodes.colwise().minCoeff(), hi = tets.nodes.colwise().maxCoeff();
  std::map<std::array<long, 3>, int> node_at;  // nodes by position, in 1e-9 m
  const auto key = [](const Eigen::Vector3d& p) {
    return std::array<long, 3>{std::lround(p.x() * 1e9), std::lround(p.y() * 1e9), std::lround(p.z() * 1e9)};
  };
  for (int n = 0; n < tets.num_nodes(); ++n) node_at[key(tets.nodes.row(n).transpose())] = n;
  const auto sorted_tet = [&](int t, int axis) {
    std::array<int, 4> ids{};
    for (int q = 0; q < 4; ++q) {
      Eigen::Vector3d p = tets.nodes.row(tets.tets(t, q)).transpose();
      if (axis >= 0) p[axis] = lo[axis] + hi[axis] - p[axis];
      const auto it = node_at.find(key(p));
      ids[static_cast<size_t>(q)] = it == node_at.end() ? -1 : it->second;
    }
    std::sort(ids.begin(), ids.end());
    return ids;
  };
  std::set<std::array<int, 4>> own;
  for (int t = 0; t < tets.num_tets(); ++t) own.insert(sorted_tet(t, -1));
  for (int axis = 0; axis < 3; ++axis) {
    int unmatched = 0;
    for (int t = 0; t < tets.num_tets(); ++t) unmatched += own.count(sorted_tet(t, axis)) == 0;
    EXPECT_EQ(unmatched, 0) << "mirrored across axis " << axis << ", of " << tets.num_tets() << " tets";
  }
}

TEST(Tetrahedralize, TriangleBoxOverlap) {
  const Eigen::Vector3d c(0, 0, 0), h(0.5, 0.5, 0.5);
  EXPECT_TRUE(triangle_overlaps_box({-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, c, h));        // cuts through
  EXPECT_FALSE(triangle_overlaps_box({-1, -1, 0.6}, {1, -1, 0.6}, {0, 1, 0.6}, c, h)); // above
  // Its box overlaps but the slanted triangle passes beside the cube corner.
  EXPECT_FALSE(triangle_overlaps_box({0.8, 0.0, 1.0}, {1.0, 0.8, 0.0}, {0.0, 1.0, 0.8}, c, h));
  EXPECT_TRUE(triangle_overlaps_box({0.1, 0.1, 0.1}, {2, 0, 0}, {0, 2, 0}, c, h));      // vertex inside
}

TEST(Tetrahedralize, BadArgumentsAreBadInput) {
  EXPECT_THROW(tetrahedralize(TriMesh{}, 8), Error);
  EXPECT_THROW(tetrahedralize(make_sphere(1.0, 1), 0), Error);
}

}  // namespace
}  // namespace recoil::sim
