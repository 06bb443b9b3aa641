// Friction validation checks: incline stick and slide (rigid box and
// deformable block), slide to stop (rigid, on a plane, on a static box floor
// and over the seam of two static tiles, and deformable from soft to nearly
// rigid), cone isotropy, rolling sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/scenes/contact_scenes.h"
#include "tests/validation/contact_helpers.h"
#include "tests/validation/measured.h"

namespace recoil::sim {
namespace {

using namespace scenes;
using validation::motion;
using validation::run;
using validation::steps;

constexpr double g = 9.81;

WorldDesc incline_world(double theta, FrictionDesc f, bool deformable, double dt) {
  WorldDesc w = base_world(dt);
  w.planes.push_back(incline(theta, f));
  if (deformable) {
    DeformableBodyDesc b = soft_box("block", Eigen::Vector3d::Constant(0.1), 2, jelly(2e5), Eigen::Vector3d::Zero(), f);
    place_on_incline(b, theta, 0.05, 0.0);
    w.bodies.push_back(b);
  } else {
    RigidBodyDesc b = rigid_box("block", Eigen::Vector3d::Constant(0.1), Eigen::Vector3d::Zero(), f);
    place_on_incline(b, theta, 0.05, 0.0);
    w.rigid_bodies.push_back(b);
  }
  return w;
}

// A block set down on a slope with tan(theta) below mu_s stays. With mu_k
// below tan(theta) too, only static friction holds it: the block starts at
// rest, so kinetic friction must never take over.
void incline_stick(bool deformable, double tan_theta, double mu_s, double mu_k) {
  const double theta = std::atan(tan_theta);
  const double dt = 0.01;
  World world(incline_world(theta, friction(mu_s, mu_k), deformable, dt));
  const Eigen::Vector3d c0 = motion(world, 0).center;
  const double penetration = run(world, steps(2.0, dt));
  const double creep = (motion(world, 0).center - c0).dot(downslope(theta));
  validation::Measured() << (deformable ? "deformable" : "rigid") << " incline stick (tan " << tan_theta << ", mu_s "
                         << mu_s << ", mu_k " << mu_k << "): creep after 2 s " << creep * 1e3
                         << " mm, max penetration " << penetration * 1e3 << " mm\n";
  EXPECT_LT(std::abs(creep), 1e-3);
  EXPECT_LT(penetration, 0.002);
}

void incline_slide(bool deformable) {
  const double theta = std::atan(0.5), mu = 0.3;
  const double dt = 0.005;
  World world(incline_world(theta, friction(0.35, mu), deformable, dt));
  run(world, steps(0.1, dt));
  const double v1 = motion(world, 0).velocity.dot(downslope(theta)), t1 = world.time();
  run(world, steps(0.5, dt));
  const double v2 = motion(world, 0).velocity.dot(downslope(theta)), t2 = world.time();
  const double a = (v2 - v1) / (t2 - t1), expected = g * (std::sin(theta) - mu * std::cos(theta));
  const double err = std::abs(a - expected) / expected;
  validation::Measured() << (deformable ? "deformable" : "rigid") << " incline slide (tan 0.5, mu_k 0.3): a = " << a
            << " m/s^2, expected " << expected << ", relative error " << err << "\n";
  EXPECT_LT(err, 0.03);
}

TEST(ContactValidation, InclineStickRigid) { incline_stick(false, 0.3, 0.5, 0.5); }
TEST(ContactValidation, InclineStickDeformable) { incline_stick(true, 0.3, 0.5, 0.5); }
TEST(ContactValidation, InclineHeldByStaticFrictionAloneRigid) { incline_stick(false, 0.45, 0.5, 0.3); }
// A soft block spreads under its own weight, and its rim slips outwards
// (kinetic from then on) before it settles: at mu_s 0.5 that slip carries
// the 3 x 3 contacts of the coarse lattice down the slope, so the soft
// variant holds the load with a wider static margin.
TEST(ContactValidation, InclineHeldByStaticFrictionAloneDeformable) { incline_stick(true, 0.45, 0.9, 0.3); }
TEST(ContactValidation, InclineSlideRigid) { incline_slide(false); }
TEST(ContactValidation, InclineSlideDeformable) { incline_slide(true); }

// Stopping distance of a rigid box launched at v0 along `direction` on flat ground.
double stopping_distance(const Eigen::Vector3d& direction, double v0, double mu, double& creep) {
  const double dt = 0.002;
  WorldDesc w = base_world(dt);
  w.planes.push_back(ground(friction(mu, mu)));
  RigidBodyDesc b = rigid_box("block", Eigen::Vector3d::Constant(0.1), Eigen::Vector3d(0.0, 0.0501, 0.0),
                              friction(mu, mu));
  b.velocity = v0 * direction.normalized();
  w.rigid_bodies.push_back(b);
  World world(w);
  const Eigen::Vector3d c0 = motion(world, 0).center;
  const double expected_time = v0 / (mu * g);
  run(world, steps(expected_time + 0.1, dt));
  const Eigen::Vector3d stop = motion(world, 0).center;
  run(world, steps(0.5, dt));
  creep = (motion(world, 0).center - stop).norm();
  return (stop - c0).dot(direction.normalized());
}

TEST(ContactValidation, SlideToStopAndConeIsotropy) {
  const double v0 = 2.0, mu = 0.5, expected = v0 * v0 / (2.0 * mu * g);
  double creep_x = 0.0, creep_d = 0.0;
  const double dx = stopping_distance(Eigen::Vector3d::UnitX(), v0, mu, creep_x);
  const double dd = stopping_distance(Eigen::Vector3d(1.0, 0.0, 1.0), v0, mu, creep_d);
  const double err = std::abs(dx - expected) / expected, iso = std::abs(dd - dx) / dx;
  validation::Measured() << "slide to stop: distance " << dx << " m, expected " << expected << ", relative error " << err
            << "; diagonal " << dd << " m, anisotropy " << iso << "; creep after stop " << creep_x * 1e3 << " / "
            << creep_d * 1e3 << " mm\n";
  EXPECT_LT(err, 0.03);
  EXPECT_LT(iso, 0.01);
  EXPECT_LT(creep_x, 1e-4);
  EXPECT_LT(creep_d, 1e-4);
}

// A block launched on a static box floor that it rests on exactly, both
// with the scene primitive's 8 x 8-cell faces, slides to a stop as on a
// plane. Its front face sweeps over the floor's flat lattice vertices, and
// the contact-free prediction, falling g h^2 into the floor, lets the
// continuous check meet them on that face: held against it, a 0.1 m block
// at 2 m/s (dt 4 ms) tipped onto its edge at the floor's first grid line,
// rose 20 mm and stopped at 0.43 of 0.68 m.
TEST(ContactValidation, SlideToStopOnAStaticBoxFloor) {
  const double v0 = 2.0, mu = 0.3;
  for (const double dt : {0.004, 1.0 / 60.0}) {
    WorldDesc w = base_world(dt);
    const Eigen::Vector3d floor_size(3.0, 0.1, 1.0), block_size = Eigen::Vector3d::Constant(0.1);
    RigidBodyDesc floor = rigid_box("floor", floor_size, Eigen::Vector3d(0.0, -0.05, 0.0), friction(mu, mu));
    floor.mesh = make_box(floor_size);  // 8 x 8 cells a face, as a scene's box primitive
    floor.kind = BodyKind::fixed;
    RigidBodyDesc block = rigid_box("block", block_size, Eigen::Vector3d(0.0, 0.05, 0.0), friction(mu, mu), 500.0);
    block.mesh = make_box(block_size);
    block.velocity = Eigen::Vector3d(v0, 0.0, 0.0);
    w.rigid_bodies = {floor, block};
    World world(w);
    const Eigen::Vector3d c0 = motion(world, 0).center;
    double highest = c0.y();
    for (int i = 0; i < steps(v0 / (mu * g) + 0.2, dt); ++i) {
      ASSERT_EQ(world.step().status, StepStatus::ok) << "dt " << dt;
      highest = std::max(highest, motion(world, 0).center.y());
    }
    const Eigen::Vector3d stop = motion(world, 0).center;
    // Implicit Euler takes h v0 / 2 off the distance, as on a plane.
    const double expected = v0 * v0 / (2.0 * mu * g) - 0.5 * dt * v0;
    const double err = std::abs((stop - c0).x() - expected) / expected;
    validation::Measured() << "block on a static box floor, dt " << dt << " s: slid " << (stop - c0).x()
                           << " m, expected " << expected << ", relative error " << err << ", rose "
                           << (highest - c0.y()) * 1e3 << " mm\n";
    EXPECT_LT(err, 0.03) << "dt " << dt;
    // The rest gap (margin / 10) is all it may rise: it never tips.
    EXPECT_LT(highest - c0.y(), 0.1 * w.contact.margin + 1e-6) << "dt " << dt;
  }
}

// A floor of two static tiles laid edge to edge is one flat floor: a block
// launched across their seam, or along it, slides to a stop as on a plane.
// Each tile's side face at the seam, and the edge above it, were walls and
// corners to the narrow phase: a 0.1 m block at 2 m/s hopped 22 mm there and
// stopped at 0.26 of 0.40 m (0.34 along the seam).
TEST(ContactValidation, SlideOverTheSeamOfTwoStaticTiles) {
  const double v0 = 2.0, mu = 0.5, dt = 0.004;
  const Eigen::Vector3d across = Eigen::Vector3d::UnitX(), along = Eigen::Vector3d::UnitZ();
  for (const Eigen::Vector3d& direction : {across, along}) {
    WorldDesc w = base_world(dt);
    const Eigen::Vector3d tile_size(1.0, 0.2, 2.0), block_size = Eigen::Vector3d::Constant(0.1);
    std::vector<RigidBodyDesc> tiles;
    for (const double x : {-0.5, 0.5}) {
      RigidBodyDesc tile = rigid_box("tile", tile_size, Eigen::Vector3d(x, -0.1, 0.0), friction(mu, mu));
      tile.mesh = make_box(tile_size);  // 8 x 8 cells a face, as a scene's box primitive
      tile.kind = BodyKind::fixed;
      tiles.push_back(tile);
    }
    // Across: from 0.2 m before the seam; along: centred on it.
    const Eigen::Vector3d start =
        direction == across ? Eigen::Vector3d(-0.2, 0.05, 0.0) : Eigen::Vector3d(0.0, 0.05, -0.5);
    RigidBodyDesc block = rigid_box("block", block_size, start, friction(mu, mu), 1000.0);
    block.mesh = make_box(block_size);
    block.velocity = v0 * direction;
    w.rigid_bodies = {tiles[0], tiles[1], block};
    World world(w);
    const Eigen::Vector3d c0 = motion(world, 0).center;
    double highest = c0.y();
    for (int i = 0; i < steps(v0 / (mu * g) + 0.2, dt); ++i) {
      ASSERT_EQ(world.step().status, StepStatus::ok);
      highest = std::max(highest, motion(world, 0).center.y());
    }
    const double slid = (motion(world, 0).center - c0).dot(direction);
    const double expected = v0 * v0 / (2.0 * mu * g) - 0.5 * dt * v0;  // as on a plane (see above)
    const double err = std::abs(slid - expected) / expected;
    validation::Measured() << "block " << (direction == across ? "across" : "along")
                           << " the seam of two static tiles: slid " << slid << " m, expected " << expected
                           << ", relative error " << err << ", rose " << (highest - c0.y()) * 1e3 << " mm\n";
    EXPECT_LT(err, 0.03);
    EXPECT_LT(highest - c0.y(), 0.1 * w.contact.margin + 1e-6);
  }
}

// A deformable block launched on flat ground stops where a rigid one does,
// however stiff: at E = 1e12 Pa the step matrix's diagonal is h^2 k, 1e4
// times the mass at dt = 2 ms, and the block's rigid motion must still
// answer to friction and gravity like its mass (momentum_preconditioner.h).
// Also at dt = 0.1 s, where it once never landed and slid on at v0.
TEST(ContactValidation, StiffDeformableBlockSlidesToStop) {
  const double v0 = 2.0, mu = 0.5;
  for (const double dt : {0.002, 0.1}) {
    for (const double youngs_modulus : {1e6, 1e9, 1e12}) {
      WorldDesc w = base_world(dt);
      w.planes.push_back(ground(friction(mu, mu)));
      DeformableBodyDesc b = soft_box("block", Eigen::Vector3d::Constant(0.1), 2, jelly(youngs_modulus),
                                      Eigen::Vector3d(0.0, 0.0501, 0.0), friction(mu, mu));
      b.velocity = Eigen::Vector3d(v0, 0.0, 0.0);
      w.bodies.push_back(b);
      World world(w);
      const Eigen::Vector3d c0 = motion(world, 0).center;
      run(world, steps(v0 / (mu * g) + 0.2, dt));
      const Eigen::Vector3d stop = motion(world, 0).center;
      const double speed = motion(world, 0).velocity.norm();
      run(world, steps(0.5, dt));
      const double creep = (motion(world, 0).center - stop).norm();
      // Implicit Euler takes h v0 / 2 off the distance (v_{n+1} = v_n - mu g h, x += h v_{n+1}).
      const double expected = v0 * v0 / (2.0 * mu * g) - 0.5 * dt * v0;
      const double err = std::abs((stop - c0).x() - expected) / expected;
      validation::Measured() << "stiff block, E " << youngs_modulus << " Pa, dt " << dt << " s: slid " << (stop - c0).x()
                << " m, expected " << expected << ", relative error " << err << "; speed after " << speed
                << " m/s, creep " << creep * 1e3 << " mm, height " << stop.y() << " m\n";
      EXPECT_LT(err, 0.03) << youngs_modulus << " Pa, dt " << dt;
      EXPECT_LT(speed, 1e-3) << youngs_modulus << " Pa, dt " << dt;
      EXPECT_LT(creep, 1e-4) << youngs_modulus << " Pa, dt " << dt;
      EXPECT_NEAR(stop.y(), 0.05, 2e-4) << youngs_modulus << " Pa, dt " << dt;  // resting on its face
      EXPECT_EQ(world.counters().solver_not_converged, 0) << youngs_modulus << " Pa, dt " << dt;
    }
  }
}

// A faceted sphere (2562 vertices) rolls without slipping. Its pivot
// passes from vertex to vertex, and the vertices ahead of it have nearly
// parallel normal rows (cosine 0.98-0.99 in the P_A^-1 metric): switched on
// together, they flung the ball (a = 12.3 m/s^2); the
// parallel-row rule of constraint_evaluation.h switches them on one at a
// time, and every step converges.
TEST(ContactValidation, RollingSphere) {
  const double theta = 15.0 * kPi / 180.0, radius = 0.05, dt = 0.005;
  WorldDesc w = base_world(dt);
  w.planes.push_back(incline(theta, friction(0.6, 0.6)));
  RigidBodyDesc b = rigid_sphere("ball", radius, Eigen::Vector3d::Zero(), friction(0.6, 0.6), 4);
  b.transform.position = (radius + 1e-4) * incline_normal(theta);
  w.rigid_bodies.push_back(b);
  World world(w);
  run(world, steps(0.1, dt));
  const double v1 = motion(world, 0).velocity.dot(downslope(theta)), t1 = world.time();
  const double w1 = world.velocities().tail<3>().z();
  run(world, steps(0.5, dt));
  const double v2 = motion(world, 0).velocity.dot(downslope(theta)), t2 = world.time();
  const double w2 = world.velocities().tail<3>().z();
  const double a = (v2 - v1) / (t2 - t1), expected = 5.0 / 7.0 * g * std::sin(theta);
  const double err = std::abs(a - expected) / expected;
  const double slip = std::abs(v2 + w2 * radius);  // rolling: v = -w_z r down the slope
  validation::Measured() << "rolling sphere (15 deg, mu 0.6): a = " << a << " m/s^2, expected " << expected
            << ", relative error " << err << ", slip speed " << slip << " m/s (w " << w1 << " -> " << w2 << "), unconverged steps "
            << world.counters().solver_not_converged << "\n";
  EXPECT_LT(err, 0.03);
  EXPECT_LT(slip, 0.03 * std::abs(v2));
  EXPECT_EQ(world.counters().solver_not_converged, 0);
}

}  // namespace
}  // namespace recoil::sim
