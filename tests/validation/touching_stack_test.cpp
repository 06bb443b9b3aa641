// Validation check: a stack built exactly touching (zero gap) stands.
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "tests/scenes/contact_scenes.h"
#include "tests/validation/contact_helpers.h"
#include "tests/validation/measured.h"

namespace recoil::sim::validation {
namespace {

using namespace recoil::sim::scenes;

TEST(TouchingStack, FourRigidCubesStandTenSeconds) {
  const WorldDesc desc = touching_cube_stack(4);
  World world(desc);
  const Eigen::Vector3d start = motion(world, 3).center;
  int unconverged = 0, stepped = 0;
  double drift = 0.0, penetration = 0.0;
  for (int i = 0; i < steps(10.0, desc.dt); ++i) {
    const StepReport r = world.step();
    ASSERT_EQ(r.status, StepStatus::ok) << "step " << r.step << " body " << r.body;
    ++stepped;
    unconverged += !r.solver_converged;
    penetration = std::max(penetration, r.max_penetration);
    drift = std::max(drift, (motion(world, 3).center - start).norm());
  }
  validation::Measured() << "rigid touching stack (4 cubes, zero gap, 10 s): top moved " << drift * 1e3 << " mm, " << unconverged
            << " of " << stepped << " steps unconverged, max penetration " << penetration * 1e3 << " mm\n";
  EXPECT_LT(drift, 1e-4);
  EXPECT_EQ(unconverged, 0);
  EXPECT_LT(penetration, 1e-4);
}

// Each cube above the first row rests on two: their friction splits the
// load many ways, and a split the solve happens to hold can push a contact
// past its cone while the cubes stay still.
TEST(TouchingStack, ABoxPyramidStands) {
  const WorldDesc desc = box_pyramid(3, 0.01, 0.01);
  World world(desc);
  const int cubes = static_cast<int>(desc.rigid_bodies.size());
  std::vector<Eigen::Vector3d> start;
  for (int b = 0; b < cubes; ++b) start.push_back(motion(world, b).center);
  int unconverged = 0, stepped = 0;
  double penetration = 0.0;
  for (int i = 0; i < steps(1.0, desc.dt); ++i) {
    const StepReport r = world.step();
    ASSERT_EQ(r.status, StepStatus::ok) << "step " << r.step << " body " << r.body;
    ++stepped;
    unconverged += !r.solver_converged;
    penetration = std::max(penetration, r.max_penetration);
  }
  double moved = 0.0;
  for (int b = 0; b < cubes; ++b)
    moved = std::max(moved, (motion(world, b).center - start[static_cast<size_t>(b)]).norm());
  validation::Measured() << "rigid pyramid (3-2-1 cubes, 1 cm apart, dt 10 ms, 1 s): a cube moved at most "
                         << moved * 1e3 << " mm, " << unconverged << " of " << stepped
                         << " steps unconverged, max penetration " << penetration * 1e3 << " mm\n";
  EXPECT_LT(moved, 1e-4);
  EXPECT_EQ(unconverged, 0);
  EXPECT_LT(penetration, 1e-4);
}


// Lattice resolution 2: at 4, CR ends 30 of the 5000 steps at its iteration
// cap (KKT up to 1.1e-5 m/s) while the interfaces slip during the first
// 0.12 s, where pgs converges; the stack stands all the same.
TEST(TouchingStack, FourJellyCubesStandTenSeconds) {
  const WorldDesc desc = touching_jelly_stack(4, 2);
  World world(desc);
  const Eigen::Vector3d start = motion(world, 3).center;
  int unconverged = 0, stepped = 0, inverted = 0;
  double sway = 0.0;             // largest sideways offset of the top cube (m)
  Eigen::Vector3d settled = start;  // the top cube's centre at 5 s
  double settled_drift = 0.0;    // sideways from there (m)
  const int total = steps(10.0, desc.dt);
  for (int i = 0; i < total; ++i) {
    const StepReport r = world.step();
    ASSERT_EQ(r.status, StepStatus::ok) << "step " << r.step << " body " << r.body;
    ++stepped;
    unconverged += !r.solver_converged;
    inverted = std::max(inverted, r.inverted_tets);
    const Eigen::Vector3d center = motion(world, 3).center;
    const Eigen::Vector3d moved = center - start;
    sway = std::max(sway, std::hypot(moved.x(), moved.z()));
    if (i + 1 == total / 2) settled = center;
    if (i + 1 > total / 2)
      settled_drift = std::max(settled_drift, std::hypot(center.x() - settled.x(), center.z() - settled.z()));
  }
  const Eigen::Vector3d moved = motion(world, 3).center - start;
  validation::Measured() << "jelly touching stack (4 cubes, zero gap, resolution 2, 10 s): top moved sideways "
                         << settled_drift * 1e3 << " mm from 5 s to 10 s (" << std::hypot(moved.x(), moved.z()) * 1e3
                         << " mm from the start, at most " << sway * 1e3 << " mm, settling down " << -moved.y() * 1e3
                         << " mm), " << unconverged << " of " << stepped << " steps unconverged, " << inverted
                         << " inverted elements\n";
  EXPECT_LT(settled_drift, 1e-4);
  EXPECT_LT(-moved.y(), 0.01 * 4 * kBenchCube) << "the stack fell";
  EXPECT_EQ(unconverged, 0);
  EXPECT_EQ(inverted, 0);
}

}  // namespace
}  // namespace recoil::sim::validation
