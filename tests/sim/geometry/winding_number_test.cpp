// Generalized winding number: exact per-triangle solid angles on a closed, an
// open and a partly flipped cube, and the tree's far-field approximation
// against the exact sum.
#include "sim/geometry/winding_number.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "sim/geometry/mesh_import.h"
#include "sim/geometry/primitives.h"
#include "tests/test_support.h"

namespace recoil::sim {
namespace {

// A unit cube [-0.5, 0.5]^3, two triangles per face.
TriMesh unit_cube() { return make_box(Eigen::Vector3d::Ones(), 1); }

// The triangles whose centroids lie on the face `axis` = `side` * 0.5.
std::vector<int> face_triangles(const TriMesh& mesh, int axis, double side) {
  std::vector<int> out;
  for (int f = 0; f < mesh.num_triangles(); ++f) {
    double c = 0.0;
    for (int k = 0; k < 3; ++k) c += mesh.vertices(mesh.triangles(f, k), axis) / 3.0;
    if (std::abs(c - 0.5 * side) < 1e-12) out.push_back(f);
  }
  return out;
}

TriMesh without(const TriMesh& mesh, const std::vector<int>& removed) {
  TriMesh out;
  out.vertices = mesh.vertices;
  out.triangles.resize(mesh.num_triangles() - static_cast<int>(removed.size()), 3);
  int next = 0;
  for (int f = 0; f < mesh.num_triangles(); ++f)
    if (std::find(removed.begin(), removed.end(), f) == removed.end()) out.triangles.row(next++) = mesh.triangles.row(f);
  return out;
}

}  // namespace

TEST(WindingNumber, OctantTriangleIsAnEighthOfTheSphere) {
  // The triangle (1,0,0), (0,1,0), (0,0,1) seen from the origin covers one
  // octant: 4 pi / 8; from the other side the sign flips; on its plane it is 0.
  const Eigen::Vector3d a(1, 0, 0), b(0, 1, 0), c(0, 0, 1);
  EXPECT_NEAR(triangle_solid_angle(a, b, c, Eigen::Vector3d::Zero()), std::numbers::pi / 2.0, 1e-14);
  EXPECT_NEAR(triangle_solid_angle(a, c, b, Eigen::Vector3d::Zero()), -std::numbers::pi / 2.0, 1e-14);
  EXPECT_EQ(triangle_solid_angle(a, b, c, Eigen::Vector3d(2, -1, 0)), 0.0);
}

TEST(WindingNumber, ClosedCubeIsOneInsideZeroOutside) {
  const TriMesh cube = unit_cube();
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, -0.2, 0.45), Eigen::Vector3d(-0.49, 0.49, 0)})
    EXPECT_NEAR(winding_number(cube, p), 1.0, 1e-12) << p.transpose();
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.51, 0, 0), Eigen::Vector3d(2, 3, -1), Eigen::Vector3d(-0.6, 0.6, 0.6)})
    EXPECT_NEAR(winding_number(cube, p), 0.0, 1e-12) << p.transpose();
}

TEST(WindingNumber, OpenCubeIsAboutHalfAtTheHoleAndInsideDeepIn) {
  const TriMesh open = without(unit_cube(), face_triangles(unit_cube(), 1, +1.0));  // no top
  ASSERT_EQ(open.num_triangles(), 10);
  // At the centre the missing face would subtend a sixth of the sphere.
  EXPECT_NEAR(winding_number(open, Eigen::Vector3d::Zero()), 5.0 / 6.0, 1e-12);
  EXPECT_GT(winding_number(open, Eigen::Vector3d(0, -0.3, 0)), 0.9);
  // In the plane of the hole the walls below subtend half the sphere.
  EXPECT_NEAR(winding_number(open, Eigen::Vector3d(0, 0.5, 0)), 0.5, 1e-12);
  EXPECT_NEAR(winding_number(open, Eigen::Vector3d(0.1, 0.48, -0.2)), 0.5, 0.05);
  // Above the hole it falls away; far off it is 0.
  EXPECT_LT(winding_number(open, Eigen::Vector3d(0, 0.8, 0)), 0.5);
  EXPECT_NEAR(winding_number(open, Eigen::Vector3d(5, 5, 5)), 0.0, 1e-3);
}

TEST(WindingNumber, FlippedFacesSubtractButTheInsideStaysAboveHalf) {
  TriMesh flipped = unit_cube();
  for (int f : face_triangles(flipped, 0, -1.0)) std::swap(flipped.triangles(f, 1), flipped.triangles(f, 2));
  // One face of six counts negative at the centre: 4/6.
  EXPECT_NEAR(winding_number(flipped, Eigen::Vector3d::Zero()), 4.0 / 6.0, 1e-12);
  // Outside, in front of the flipped face, that face counts twice where it
  // should cancel: 2 Omega / 4 pi, Omega the unit square's solid angle from
  // 0.2 m along its axis, 4 atan(1 / (2 d sqrt(4 d^2 + 2))).
  const double d = 0.2, omega = 4.0 * std::atan(1.0 / (2.0 * d * std::sqrt(4.0 * d * d + 2.0)));
  EXPECT_NEAR(winding_number(flipped, Eigen::Vector3d(-0.5 - d, 0, 0)), 2.0 * omega / (4.0 * std::numbers::pi), 1e-12);
  EXPECT_NEAR(winding_number(flipped, Eigen::Vector3d(-40, 0, 0)), 0.0, 1e-3);
  // Wholly inward-wound: -1 inside (the tetrahedralizer tests the magnitude).
  TriMesh inward = unit_cube();
  for (int f = 0; f < inward.num_triangles(); ++f) std::swap(inward.triangles(f, 1), inward.triangles(f, 2));
  EXPECT_NEAR(winding_number(inward, Eigen::Vector3d(0.1, 0.2, 0.3)), -1.0, 1e-12);
}

TEST(WindingNumber, TreeMatchesTheExactSumAwayFromTheSurface) {
  const TriMesh bunny = import_surface(test::source_path("assets/meshes/bunny.obj"));
  const WindingNumberTree tree(bunny), fine(bunny, 4.0);
  EXPECT_GT(tree.num_nodes(), 1);
  const Aabb box = bounding_box(bunny);
  std::mt19937_64 rng(7);
  double worst = 0.0, worst_fine = 0.0;
  int agree = 0, queries = 0;
  for (int i = 0; i < 400; ++i) {
    Eigen::Vector3d u;
    for (int a = 0; a < 3; ++a) u[a] = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    const Eigen::Vector3d p = box.min - 0.1 * box.extent() + u.cwiseProduct(1.2 * box.extent());
    const double exact = winding_number(bunny, p), fast = tree(p);
    worst = std::max(worst, std::abs(exact - fast));
    worst_fine = std::max(worst_fine, std::abs(exact - fine(p)));
    agree += (exact > 0.5) == (fast > 0.5);
    ++queries;
    EXPECT_EQ(fast, tree(p));  // deterministic
  }
  std::cout << "bunny winding number, tree against exact over " << queries << " points: worst difference " << worst
            << " (" << worst_fine << " at accuracy 4), same side " << agree << "\n";
  EXPECT_LT(worst, 0.06);
  EXPECT_LT(worst_fine, 0.015);
  EXPECT_GE(agree, queries - 2);
}

TEST(WindingNumber, EmptySurfaceIsZero) {
  EXPECT_EQ(winding_number(TriMesh{}, Eigen::Vector3d::Zero()), 0.0);
  EXPECT_EQ(WindingNumberTree(TriMesh{})(Eigen::Vector3d::Zero()), 0.0);
}

}  // namespace recoil::sim
