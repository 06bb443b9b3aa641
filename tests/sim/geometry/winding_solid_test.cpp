// The solid an open surface's winding number fills: a closed box is tiled
// exactly, a box with its lid off keeps all but its top layer (its signed
// volume loses a sixth), an open shell weighs the same wherever it lies and on
// any number of threads, and a flat sheet encloses nothing.
#include "sim/geometry/winding_solid.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/primitives.h"
#include "sim/rigid/mass_properties.h"

namespace recoil::sim {
namespace {

// The box without its two triangles on the +y face.
TriMesh lidless(const TriMesh& box) {
  TriMesh out;
  out.vertices = box.vertices;
  std::vector<Eigen::Vector3i> kept;
  for (int f = 0; f < box.num_triangles(); ++f) {
    double y = 0.0;
    for (int k = 0; k < 3; ++k) y += box.vertices(box.triangles(f, k), 1) / 3.0;
    if (y < box.vertices.col(1).maxCoeff() - 1e-12) kept.push_back(box.triangles.row(f).transpose());
  }
  out.triangles.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t f = 0; f < kept.size(); ++f) out.triangles.row(static_cast<Eigen::Index>(f)) = kept[f].transpose();
  return out;
}

TEST(WindingSolid, TilesAClosedBoxAndWeighsItAsItsSurfaceDoes) {
  TriMesh box = make_box(Eigen::Vector3d(0.4, 0.2, 0.1), 1);
  transform_in_place(box, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Ones(), Eigen::Vector3d(0.3, 1.0, -0.2));
  const WindingSolid solid = winding_solid(box);
  EXPECT_EQ(solid.centers.size(), 64u * 32u * 16u);
  const MassProperties surface = mass_properties(box, 700.0), cells = mass_properties(solid, 700.0);
  EXPECT_NEAR(cells.mass, surface.mass, 1e-9 * surface.mass);
  EXPECT_LT((cells.center - surface.center).norm(), 1e-9);
  EXPECT_LT((cells.inertia - surface.inertia).norm(), 1e-9 * surface.inertia.norm());
}

TEST(WindingSolid, ABoxWithItsLidOffKeepsAllButTheLayerUnderTheHole) {
  const TriMesh box = make_box(Eigen::Vector3d(0.2, 0.2, 0.2), 1);
  const TriMesh open = lidless(box);
  ASSERT_FALSE(compute_mesh_stats(open).watertight);
  const double full = winding_solid(box).volume(), kept = winding_solid(open).volume();
  EXPECT_LE(kept, full);
  EXPECT_GE(kept, full * 63.0 / 64.0 - 1e-12);
  // The signed volume about the box's centre loses the cone the lid would close: a sixth.
  EXPECT_NEAR(enclosed_volume(open), full * 5.0 / 6.0, 1e-12);
}

TEST(WindingSolid, AnOpenShellWeighsTheSameWhereverItLies) {
  const TriMesh open = lidless(make_box(Eigen::Vector3d(0.2, 0.2, 0.2), 1));
  TriMesh moved = open;
  transform_in_place(moved, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Ones(), Eigen::Vector3d(5.0, -3.0, 2.0));
  EXPECT_NEAR(winding_solid(moved).volume(), winding_solid(open).volume(), 1e-12);
}

TEST(WindingSolid, AnyNumberOfThreadsFindsTheSameCellsInTheSameOrder) {
  const TriMesh open = lidless(make_box(Eigen::Vector3d(0.3, 0.2, 0.1), 1));
  const WindingSolid one = winding_solid(open, 24, 1);
  ASSERT_FALSE(one.centers.empty());
  for (int threads : {2, 5, 64}) {
    const WindingSolid many = winding_solid(open, 24, threads);
    EXPECT_EQ(many.cell, one.cell);
    EXPECT_EQ(many.centers, one.centers) << threads << " threads";
  }
  EXPECT_THROW(winding_solid(open, 24, 0), Error);
}

TEST(WindingSolid, ASheetEnclosesNothing) {
  TriMesh sheet;
  sheet.vertices.resize(4, 3);
  sheet.vertices << 0, 0.5, 0, 0.3, 0.5, 0, 0.3, 0.5, 0.3, 0, 0.5, 0.3;
  sheet.triangles.resize(2, 3);
  sheet.triangles << 0, 1, 2, 0, 2, 3;
  EXPECT_TRUE(winding_solid(sheet).centers.empty());
  EXPECT_TRUE(winding_solid(TriMesh{}).centers.empty());
}

}  // namespace
}  // namespace recoil::sim
