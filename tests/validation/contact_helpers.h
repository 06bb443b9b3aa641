#pragma once
// Small helpers for the contact validation tests: stepping with status
// checks, and the motion of one body (rigid or deformable) read from stats().
#include <gtest/gtest.h>

#include <algorithm>

#include "sim/world.h"

namespace recoil::sim::validation {

struct BodyMotion {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();    // m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s, of the centre of mass
};

// Dynamic body i in stats() order (deformable, then rigid).
inline BodyMotion motion(const World& world, int i) {
  const BodyStats s = world.stats()[static_cast<size_t>(i)];
  return {s.center_of_mass, s.momentum / s.mass};
}

// Steps n times; fails the test on a bad status. Returns the largest
// penetration seen.
inline double run(World& world, int n) {
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const StepReport r = world.step();
    EXPECT_EQ(r.status, StepStatus::ok) << "step " << r.step << " body " << r.body;
    if (r.status != StepStatus::ok) return worst;
    worst = std::max(worst, r.max_penetration);
  }
  return worst;
}

inline int steps(double seconds, double dt) { return static_cast<int>(seconds / dt + 0.5); }

}  // namespace recoil::sim::validation
