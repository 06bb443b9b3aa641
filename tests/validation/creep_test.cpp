// Validation checks: a block held by static friction on a slope does not
// creep once it has settled.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/scenes/contact_scenes.h"
#include "tests/validation/contact_helpers.h"

namespace recoil::sim::validation {
namespace {

using namespace recoil::sim::scenes;

constexpr double kSlope = 16.0 * kPi / 180.0;  // tan 16 deg = 0.287 < mu: the block sticks
constexpr double kMu = 0.35;
constexpr double kBlock = 0.2;  // m
constexpr double kCreepDt = 0.002;

// Distance (m) the block's centre moves down the slope from 1 s to 10 s.
double creep(WorldDesc w) {
  World world(w);
  run(world, steps(1.0, kCreepDt));
  const Eigen::Vector3d settled = motion(world, 0).center;
  run(world, steps(9.0, kCreepDt));
  return (motion(world, 0).center - settled).dot(downslope(kSlope));
}

WorldDesc slope_world() {
  WorldDesc w = base_world(kCreepDt);
  w.planes.push_back(incline(kSlope, friction(kMu, kMu)));
  return w;
}

TEST(Creep, RigidBlockOnSlopeHolds) {
  WorldDesc w = slope_world();
  RigidBodyDesc b = rigid_box("block", Eigen::Vector3d::Constant(kBlock), Eigen::Vector3d::Zero(), friction(kMu, kMu), 700);
  place_on_incline(b, kSlope, 0.5 * kBlock, 0.0);
  w.rigid_bodies.push_back(b);
  const double d = creep(w);
  std::cout << "rigid block on a 16 degree slope, mu 0.35: creep from 1 s to 10 s " << d * 1e3 << " mm\n";
  EXPECT_LT(std::abs(d), 1e-5);
}

TEST(Creep, DeformableBlockOnSlopeHolds) {
  WorldDesc w = slope_world();
  DeformableBodyDesc b = soft_box("block", Eigen::Vector3d::Constant(kBlock), 3, jelly(1e6, 700),
                                  Eigen::Vector3d::Zero(), friction(kMu, kMu));
  place_on_incline(b, kSlope, 0.5 * kBlock, 0.0);
  w.bodies.push_back(b);
  const double d = creep(w);
  std::cout << "deformable block on a 16 degree slope, mu 0.35: creep from 1 s to 10 s " << d * 1e3 << " mm\n";
  EXPECT_LT(std::abs(d), 1e-5);
}

}  // namespace
}  // namespace recoil::sim::validation
