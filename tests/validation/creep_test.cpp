// Validation checks: a block held by static friction on a slope does not
// creep once it has settled.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/scenes/contact_scenes.h"
#include "tests/validation/contact_helpers.h"
#include "tests/validation/measured.h"

namespace recoil::sim::validation {
namespace {

using namespace recoil::sim::scenes;

// Distance (m) the body's centre moves down the slope from 1 s to 10 s.
double creep(const WorldDesc& w) {
  World world(w);
  run(world, steps(1.0, w.dt));
  const Eigen::Vector3d settled = motion(world, 0).center;
  run(world, steps(9.0, w.dt));
  return (motion(world, 0).center - settled).dot(downslope(kHoldingSlope));
}

TEST(Creep, RigidBlockOnSlopeHolds) {
  const double d = creep(cube_on_holding_slope());
  validation::Measured() << "rigid cube on a 16 degree slope, mu 0.35: creep from 1 s to 10 s " << d * 1e3 << " mm\n";
  EXPECT_LT(std::abs(d), 1e-5);
}

TEST(Creep, DeformableBlockOnSlopeHolds) {
  WorldDesc w = cube_on_holding_slope();
  w.rigid_bodies.clear();
  DeformableBodyDesc b = soft_box("cube", Eigen::Vector3d::Constant(kBenchCube), 3, jelly(1e6, kBenchDensity),
                                  Eigen::Vector3d::Zero(), friction(kHoldingMu, kHoldingMu));
  place_on_incline(b, kHoldingSlope, 0.5 * kBenchCube, 0.0, 0.0);
  w.bodies.push_back(b);
  const double d = creep(w);
  validation::Measured() << "deformable cube (E 1 MPa) on a 16 degree slope, mu 0.35: creep from 1 s to 10 s " << d * 1e3
            << " mm\n";
  EXPECT_LT(std::abs(d), 1e-5);
}

}  // namespace
}  // namespace recoil::sim::validation
