// Validation check: a stack built exactly touching (zero gap) stands.
#include <gtest/gtest.h>

#include <iostream>

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

}  // namespace
}  // namespace recoil::sim::validation
