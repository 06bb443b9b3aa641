// Validation check: a stack built exactly touching (zero gap) stands.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/scenes/contact_scenes.h"
#include "tests/validation/contact_helpers.h"

namespace recoil::sim::validation {
namespace {

using namespace recoil::sim::scenes;

// Four rigid 0.2 m cubes, density 700, mu 0.5, set down on the ground and
// on each other with no gap at all; dt 2 ms.
WorldDesc rigid_touching_stack(int count) {
  const double cube = 0.2;
  WorldDesc w = base_world(0.002);
  w.planes.push_back(ground(friction(0.5, 0.5)));
  for (int i = 0; i < count; ++i)
    w.rigid_bodies.push_back(rigid_box("box" + std::to_string(i), Eigen::Vector3d::Constant(cube),
                                       Eigen::Vector3d(0.0, (i + 0.5) * cube, 0.0), friction(0.5, 0.5), 700.0));
  return w;
}

TEST(TouchingStack, FourRigidCubesStandTenSeconds) {
  const WorldDesc desc = rigid_touching_stack(4);
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
  std::cout << "rigid touching stack (4 cubes, zero gap, 10 s): top moved " << drift * 1e3 << " mm, " << unconverged
            << " of " << stepped << " steps unconverged, max penetration " << penetration * 1e3 << " mm\n";
  EXPECT_LT(drift, 1e-4);
  EXPECT_EQ(unconverged, 0);
  EXPECT_LT(penetration, 1e-4);
}

}  // namespace
}  // namespace recoil::sim::validation
