// Validation check: a body that no contact touches plays no part in the
// contact solve. One Krylov solve runs for every body in the world, so a
// stiff pinned beam a metre away once kept a pushed crate's solves from
// converging (176 of 250 steps, worst KKT residual 1e4 m/s).
#include <gtest/gtest.h>

#include "tests/scenes/contact_scenes.h"
#include "tests/sim/fem/fem_scenes.h"
#include "tests/validation/contact_helpers.h"
#include "tests/validation/measured.h"

namespace recoil::sim::validation {
namespace {

using namespace recoil::sim::scenes;

// A kinematic pusher drives a rigid 0.2 m crate across the ground at
// 0.5 m/s (dt 4 ms); with `beam`, a 0.6 m beam of 1 MPa, pinned at one
// end, hangs 0.4 m up and a metre away from both.
WorldDesc pushed_crate(bool beam) {
  WorldDesc w = base_world(0.004);
  w.contact.solver.tolerance = 1e-6;
  w.planes.push_back(ground(friction(0.3, 0.3)));
  RigidBodyDesc pusher = rigid_box("pusher", Eigen::Vector3d(0.1, 0.2, 0.4), Eigen::Vector3d(-0.3, 0.102, 0.0),
                                   friction(0.5, 0.5));
  pusher.kind = BodyKind::kinematic;
  pusher.velocity = Eigen::Vector3d(0.5, 0.0, 0.0);
  w.rigid_bodies.push_back(pusher);
  w.rigid_bodies.push_back(rigid_box("crate", Eigen::Vector3d::Constant(0.2), Eigen::Vector3d(0.0, 0.1005, 0.0),
                                     friction(0.3, 0.3)));
  if (beam) {
    Material m = jelly(1e6);
    m.damping_ratio = 0.1;
    DeformableBodyDesc b =
        soft_box("beam", Eigen::Vector3d(0.6, 0.06, 0.06), 12, m, Eigen::Vector3d(1.0, 0.4, 0.0), friction(0.5, 0.5));
    b.pinned = PinBox{Eigen::Vector3d(0.69, 0.3, -0.1), Eigen::Vector3d(0.76, 0.5, 0.1)};
    w.bodies.push_back(std::move(b));
  }
  return w;
}

TEST(DistantBody, AStiffBeamFarAwayLeavesAPushedCratesSolvesAsTheyAre) {
  Eigen::Vector3d crate[2];
  for (const bool beam : {false, true}) {
    World world(pushed_crate(beam));
    const int crate_index = beam ? 1 : 0;  // stats(): deformable bodies first
    int unconverged = 0, stepped = 0;
    double worst_kkt = 0.0;
    for (int i = 0; i < steps(0.6, 0.004); ++i) {
      const StepReport r = world.step();
      ASSERT_EQ(r.status, StepStatus::ok) << "step " << r.step << " body " << r.body;
      ++stepped;
      unconverged += !r.solver_converged;
      worst_kkt = std::max(worst_kkt, r.solver_kkt);
    }
    crate[beam] = motion(world, crate_index).center;
    Measured() << "pushed crate" << (beam ? ", a pinned beam far away" : "") << ": " << unconverged << " of "
               << stepped << " steps unconverged, worst KKT " << worst_kkt << " m/s, crate moved to x = "
               << crate[beam].x() << " m\n";
    EXPECT_LE(unconverged, 1) << (beam ? "with" : "without") << " the beam";
    EXPECT_LT(worst_kkt, 1e-4) << (beam ? "with" : "without") << " the beam";
  }
  EXPECT_GT(crate[0].x(), 0.05) << "the pusher moved the crate";
  EXPECT_LT((crate[1] - crate[0]).norm(), 1e-5) << "the beam changed how the crate moved";
}

}  // namespace
}  // namespace recoil::sim::validation
