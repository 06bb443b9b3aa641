// A fine mesh simulated through its simplified collision surface: at rest on
// the ground the drawn mesh sinks no deeper than the contact margin, for a
// deformable and a rigid body, and a free fall offers no candidates.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/scenes/contact_scenes.h"
#include "tests/validation/contact_helpers.h"
#include "tests/validation/measured.h"

namespace recoil::sim {
namespace {

using namespace scenes;

// The drawn mesh's lowest point after a 1 cm drop and 0.6 s of settling, m.
double lowest_drawn_point(bool deformable, int& free_fall_candidates) {
  const double dt = 0.004, radius = 0.1;
  WorldDesc w = base_world(dt);
  w.planes.push_back(ground(friction(0.6, 0.6)));
  const TriMesh fine = make_sphere(radius, 6);  // 81920 triangles
  const Eigen::Vector3d start(0.0, radius + 0.01, 0.0);
  if (deformable) {
    DeformableBodyDesc b = soft_sphere("ball", radius, 6, jelly(1e5), start, friction(0.6, 0.6));
    b.mesh = fine;
    w.bodies.push_back(b);
  } else {
    RigidBodyDesc b = rigid_box("ball", Eigen::Vector3d::Ones(), start, friction(0.6, 0.6));
    b.mesh = fine;
    w.rigid_bodies.push_back(b);
  }
  World world(w);
  const BodySurface drawn = world.surfaces()[0];
  EXPECT_EQ(drawn.triangles.rows(), fine.num_triangles()) << "the drawn surface is the imported mesh";
  free_fall_candidates = 0;
  for (int i = 0; i < validation::steps(0.6, dt); ++i) {
    const StepReport r = world.step();
    EXPECT_EQ(r.status, StepStatus::ok) << "step " << r.step;
    // Until the collision surface comes within the margin of the ground.
    if (world.time() < 0.02) free_fall_candidates += r.contacts;
  }
  return world.surfaces()[0].positions.col(1).minCoeff();
}

TEST(CollisionSurface, TheDrawnMeshRestsWithinTheMarginOfTheGround) {
  for (bool deformable : {true, false}) {
    int candidates = 0;
    const double lowest = lowest_drawn_point(deformable, candidates);
    validation::Measured() << (deformable ? "deformable" : "rigid") << " 81920-triangle sphere at rest: drawn mesh's lowest point "
              << lowest * 1e3 << " mm (margin 2 mm), " << candidates << " candidates while falling\n";
    EXPECT_GE(lowest, -0.002);
    EXPECT_EQ(candidates, 0);
  }
}

}  // namespace
}  // namespace recoil::sim
