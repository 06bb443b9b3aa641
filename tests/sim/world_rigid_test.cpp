// The World with rigid bodies: the DoF layout, free flight (linear and
// angular momentum), kinematic motion, surfaces and stats, bad input.
#include <gtest/gtest.h>

#include <iostream>

#include "core/error.h"
#include "sim/world.h"
#include "tests/scenes/contact_scenes.h"

namespace recoil::sim {
namespace {

using namespace scenes;

TEST(WorldRigid, FreeFlightKeepsMomentaAndFollowsGravity) {
  WorldDesc w = base_world(0.01);
  RigidBodyDesc b = rigid_box("brick", {0.3, 0.1, 0.05}, {0.0, 1.0, 0.0});
  b.velocity = {0.5, 2.0, 0.0};
  b.angular_velocity = {1.0, 4.0, 0.5};  // tumbling about no principal axis
  w.rigid_bodies.push_back(b);
  World world(w);
  ASSERT_EQ(world.positions().size(), 6);
  // The body's velocity and angular velocity are the World's DoF nodes 0 and 1.
  const auto velocity = [&] { return Eigen::Vector3d(world.velocities().segment<3>(0)); };
  const auto angular_velocity = [&] { return Eigen::Vector3d(world.velocities().segment<3>(3)); };
  const Eigen::Vector3d L0 = world.rigid_body(0).world_inertia() * angular_velocity();
  const double e0 = world.stats()[0].kinetic_energy - 0.5 * world.stats()[0].mass * b.velocity.squaredNorm();
  double worst_v = 0.0, worst_L = 0.0;
  for (int i = 0; i < 100; ++i) {
    const StepReport r = world.step();
    ASSERT_EQ(r.status, StepStatus::ok);
    EXPECT_EQ(r.contacts, 0);
    const RigidBody& body = world.rigid_body(0);
    const Eigen::Vector3d v_expected = b.velocity + world.time() * w.gravity;
    worst_v = std::max(worst_v, (velocity() - v_expected).norm());
    worst_L = std::max(worst_L, (body.world_inertia() * angular_velocity() - L0).norm() / L0.norm());
    EXPECT_NEAR(body.pose.orientation.norm(), 1.0, 1e-14);
  }
  const RigidBody& body = world.rigid_body(0);
  const double e1 = 0.5 * angular_velocity().dot(body.world_inertia() * angular_velocity());
  std::cout << "rigid free flight: |v - (v0 + g t)| " << worst_v << " m/s, relative angular momentum drift " << worst_L
            << ", rotational energy " << e0 << " -> " << e1 << " J\n";
  EXPECT_LT(worst_v, 1e-12);
  EXPECT_LT(worst_L, 1e-10);
  EXPECT_LT(e1, e0 * 1.05);
  // positions() gives the pose as centre and rotation vector, and set_state takes it back.
  const RigidPose before = body.pose;
  world.set_state(world.positions(), world.velocities());
  EXPECT_LT((world.rigid_body(0).pose.center - before.center).norm(), 1e-15);
  EXPECT_LT(world.rigid_body(0).pose.orientation.angularDistance(before.orientation), 1e-12);
}

// Spun near its intermediate axis, a free box tumbles (the axis is
// unstable) and its kinetic energy, with nothing acting on it, must stay:
// within 1 % over 10 s, the bounce check's bound on any energy gain.
TEST(WorldRigid, AFreeTumbleKeepsItsEnergy) {
  WorldDesc w = base_world(0.004);
  w.gravity.setZero();
  RigidBodyDesc b = rigid_box("brick", {0.3, 0.2, 0.1}, {0.0, 1.0, 0.0});
  b.angular_velocity = {0.1, 10.0, 0.1};
  w.rigid_bodies.push_back(b);
  World world(w);
  const auto energy = [&] { return world.stats()[0].kinetic_energy; };
  const auto momentum = [&] {
    return Eigen::Vector3d(world.rigid_body(0).world_inertia() * world.velocities().segment<3>(3));
  };
  const double e0 = energy();
  const Eigen::Vector3d L0 = momentum();
  double lowest = e0, highest = e0, worst_L = 0.0;
  for (int i = 0; i < 2500; ++i) {
    ASSERT_EQ(world.step().status, StepStatus::ok);
    lowest = std::min(lowest, energy());
    highest = std::max(highest, energy());
    worst_L = std::max(worst_L, (momentum() - L0).norm() / L0.norm());
  }
  std::cout << "free tumble, 10 s: kinetic energy " << e0 << " J, between " << lowest << " and " << highest
            << " J; relative angular momentum drift " << worst_L << "\n";
  EXPECT_LT(highest, 1.01 * e0);
  EXPECT_GT(lowest, 0.99 * e0);
  EXPECT_LT(worst_L, 1e-10);
}

TEST(WorldRigid, KinematicAndFixedBodiesFollowTheirScript) {
  WorldDesc w = base_world(0.01);
  RigidBodyDesc k = rigid_box("roller", {0.1, 0.1, 0.1}, {0.0, 0.0, 0.0});
  k.kind = BodyKind::kinematic;
  k.velocity = {1.0, 0.0, 0.0};
  k.angular_velocity = {0.0, kPi, 0.0};
  w.rigid_bodies.push_back(k);
  RigidBodyDesc f = rigid_box("wall", {0.1, 0.1, 0.1}, {0.0, -1.0, 0.0});
  f.kind = BodyKind::fixed;
  w.rigid_bodies.push_back(f);
  w.gravity.setZero();  // the jelly floats far from the others
  w.bodies.push_back(soft_box("jelly", {0.1, 0.1, 0.1}, 2, jelly(), {0.0, 3.0, 0.0}));
  World world(w);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(world.step().status, StepStatus::ok);
  const std::vector<BodySurface> s = world.surfaces();
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].kind, BodyKind::deformable);
  EXPECT_EQ(s[1].kind, BodyKind::kinematic);
  EXPECT_EQ(s[2].kind, BodyKind::fixed);
  // After 1 s: moved 1 m along x and turned half a turn about y (a box looks the same, its vertices swapped).
  EXPECT_NEAR(world.rigid_body(0).pose.center.x(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(rotation_vector(world.rigid_body(0).pose.orientation).y()), kPi, 1e-9);
  EXPECT_NEAR(s[2].positions.col(1).maxCoeff(), -0.95, 1e-15);
  // stats(): dynamic bodies only.
  ASSERT_EQ(world.stats().size(), 1u);
  EXPECT_EQ(world.stats()[0].name, "jelly");
}

// Contact hands energy from body to body: in zero gravity a box at rest
// struck by another, or pushed by a kinematic paddle, gains kinetic energy
// from nothing of its own, and that is no blow-up.
TEST(WorldRigid, AStruckOrPushedBodyInZeroGravityIsNoBlowUp) {
  for (const bool paddle : {false, true}) {
    WorldDesc w = base_world(0.002);
    w.gravity.setZero();
    RigidBodyDesc striker = rigid_box(paddle ? "paddle" : "striker", {0.1, 0.1, 0.1}, {0.0, 0.0, 0.0});
    striker.velocity = {2.0, 0.0, 0.0};
    if (paddle) striker.kind = BodyKind::kinematic;
    w.rigid_bodies.push_back(striker);
    w.rigid_bodies.push_back(rigid_box("struck", {0.1, 0.1, 0.1}, {0.3, 0.02, 0.0}));
    World world(w);
    for (int i = 0; i < 150; ++i) ASSERT_EQ(world.step().status, StepStatus::ok) << (paddle ? "paddle" : "striker");
    const std::vector<BodyStats> stats = world.stats();
    const BodyStats& struck = stats.back();
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    for (const BodyStats& b : stats) momentum += b.momentum;
    std::cout << (paddle ? "pushed by a paddle" : "struck") << " in zero g: struck box at "
              << struck.momentum.x() / struck.mass << " m/s, total momentum " << momentum.transpose() << " kg m/s\n";
    EXPECT_GT(struck.momentum.x() / struck.mass, 0.5);
    // Between two dynamic bodies nothing else acts: momentum stays 2 m/s times the striker's mass.
    if (!paddle) {
      EXPECT_LT((momentum - Eigen::Vector3d(2.0 * stats[0].mass, 0.0, 0.0)).norm(), 1e-9 * stats[0].mass);
    }
  }
}

TEST(WorldRigid, RejectsBadInput) {
  WorldDesc w = base_world(0.01);
  w.planes.push_back(ground());
  w.planes.back().normal.setZero();
  EXPECT_THROW(World{w}, Error);
  w = base_world(0.01);
  w.contact.margin = 0.0;
  EXPECT_THROW(World{w}, Error);
  w = base_world(0.01);
  w.rigid_bodies.push_back(rigid_box("b", {0.1, 0.1, 0.1}, {0, 0, 0}, friction(-1.0, 0.5)));
  try {
    World world(w);
    FAIL() << "negative friction accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rigid_bodies/0/friction"), std::string::npos) << e.what();
  }
  // A rigid body description is rigid, kinematic or fixed.
  w = base_world(0.01);
  w.rigid_bodies.push_back(rigid_box("b", {0.1, 0.1, 0.1}, {0, 0, 0}, friction(0.5, 0.5)));
  w.rigid_bodies.back().kind = BodyKind::deformable;
  try {
    World world(w);
    FAIL() << "a deformable rigid body description accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rigid_bodies/0: "), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace recoil::sim
