// sim::World with deformable bodies: free fall, conservation, dissipation,
// determinism, pins, transforms, statuses and stats.
#include "sim/world.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <iostream>
#include <random>

#include "core/error.h"
#include "sim/geometry/mesh_stats.h"
#include "tests/sim/fem/fem_scenes.h"

namespace recoil::sim {
namespace {

using test_scenes::box_body;
using test_scenes::soft_material;

TEST(World, FreeFallKeepsVelocityMinusGT) {
  for (MaterialModel model : {MaterialModel::corotated, MaterialModel::neo_hookean}) {
    WorldDesc desc;
    desc.dt = 0.01;
    desc.bodies.push_back(box_body({0.2, 0.1, 0.1}, 4, soft_material(model)));
    desc.bodies.back().velocity = Eigen::Vector3d(0.5, 0.0, 0.0);
    World world(desc);
    double worst = 0.0;
    for (int i = 0; i < 50; ++i) {
      const StepReport r = world.step();
      ASSERT_EQ(r.status, StepStatus::ok);
      const Eigen::Vector3d expected(0.5, -9.81 * world.time(), 0.0);
      for (Eigen::Index n = 0; n < world.velocities().size() / 3; ++n)
        worst = std::max(worst, (world.velocities().segment<3>(3 * n) - expected).norm());
    }
    std::cout << "free fall: worst |v - (v0 - g t)| over 50 steps " << worst << " m/s\n";
    EXPECT_LT(worst, 1e-7);
    EXPECT_LT(world.stats()[0].elastic_energy, 1e-9);
  }
}

// A random velocity field and a random deformation, zero gravity.
std::unique_ptr<World> perturbed_world(MaterialModel model, Eigen::VectorXd& v0) {
  WorldDesc desc;
  desc.dt = 0.005;
  desc.gravity.setZero();
  Material m = soft_material(model);
  desc.bodies.push_back(box_body({0.3, 0.1, 0.1}, 6, m));
  auto world = std::make_unique<World>(desc);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd x = world->positions();
  v0 = world->velocities();
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    x[i] += 0.004 * u(rng);
    v0[i] = 0.5 * u(rng);
  }
  world->set_state(x, v0);
  return world;
}

TEST(World, MomentumIsConservedWithoutGravity) {
  for (MaterialModel model : {MaterialModel::corotated, MaterialModel::neo_hookean}) {
    Eigen::VectorXd v0;
    const auto owner = perturbed_world(model, v0);
    World& world = *owner;
    const Eigen::Vector3d p0 = world.stats()[0].momentum;
    double worst = 0.0;
    for (int i = 0; i < 100; ++i) {
      ASSERT_EQ(world.step().status, StepStatus::ok);
      worst = std::max(worst, (world.stats()[0].momentum - p0).norm());
    }
    const double scale = world.stats()[0].mass * 0.5;
    std::cout << "momentum drift over 100 steps: " << worst << " kg m/s (mass * |v| scale " << scale << ")\n";
    EXPECT_LT(worst, 1e-6 * scale);
  }
}

TEST(World, UndampedEnergyNeverIncreases) {
  for (MaterialModel model : {MaterialModel::corotated, MaterialModel::neo_hookean}) {
    Eigen::VectorXd v0;
    const auto owner = perturbed_world(model, v0);
    World& world = *owner;
    auto energy = [&] {
      const BodyStats s = world.stats()[0];
      return s.kinetic_energy + s.elastic_energy;
    };
    double previous = energy();
    const double e0 = previous;
    int increases = 0;
    for (int i = 0; i < 100; ++i) {
      ASSERT_EQ(world.step().status, StepStatus::ok);
      const double e = energy();
      if (e > previous + 1e-9 * e0) ++increases;
      previous = e;
    }
    std::cout << "energy " << e0 << " J -> " << previous << " J after 100 undamped steps\n";
    EXPECT_EQ(increases, 0);
    EXPECT_LT(previous, e0);
  }
}

TEST(World, TwoRunsAreBitIdentical) {
  auto run = [] {
    WorldDesc desc;
    desc.dt = 0.01;
    Material m = soft_material(MaterialModel::neo_hookean);
    m.damping_ratio = 0.1;
    desc.bodies.push_back(box_body({0.4, 0.1, 0.1}, 6, m));
    desc.bodies.back().pinned = PinBox{Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(-0.19, 1, 1)};
    desc.bodies.push_back(box_body({0.1, 0.1, 0.1}, 3, soft_material(), Eigen::Vector3d(1, 0, 0), "cube"));
    World world(desc);
    for (int i = 0; i < 100; ++i) world.step();
    return world.positions();
  };
  const Eigen::VectorXd a = run(), b = run();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())), 0);
}

TEST(World, PinnedNodesStayAndOthersSag) {
  WorldDesc desc;
  desc.dt = 0.01;
  desc.bodies.push_back(box_body({0.4, 0.1, 0.1}, 8, soft_material()));
  desc.bodies.back().pinned = PinBox{Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(-0.199, 1, 1)};
  World world(desc);
  const Eigen::VectorXd x0 = world.positions();
  for (int i = 0; i < 30; ++i) ASSERT_EQ(world.step().status, StepStatus::ok);
  const DeformableBody& body = world.deformable_body(0);
  int pinned = 0;
  for (int n = 0; n < body.num_nodes; ++n) {
    if (!body.pinned[static_cast<size_t>(n)]) continue;
    ++pinned;
    EXPECT_EQ((world.positions().segment<3>(3 * n) - x0.segment<3>(3 * n)).norm(), 0.0);
  }
  EXPECT_EQ(pinned, 3 * 3);  // the x = -0.2 face of a 8 x 2 x 2 lattice
  EXPECT_LT(world.stats()[0].center_of_mass.y(), -1e-4);
}

TEST(World, TransformMassAndSurfaces) {
  WorldDesc desc;
  DeformableBodyDesc body;
  body.name = "torus";
  body.mesh = make_torus(0.5, 0.2, 32, 12);
  body.resolution = 8;
  body.material = soft_material();
  body.transform.rotation = Eigen::Vector3d(90, 0, 0);  // x-z plane -> x-y plane
  body.transform.scale = Eigen::Vector3d(2.0, 1.0, 1.0);
  body.transform.position = Eigen::Vector3d(0, 3, 0);
  desc.bodies.push_back(body);
  World world(desc);
  const BodyStats s = world.stats()[0];
  TriMesh expected = body.mesh;
  transform_in_place(expected, body.transform.rotation_matrix(), body.transform.scale, body.transform.position);
  EXPECT_NEAR(s.mass, 1000.0 * enclosed_volume(expected), 1e-9 * s.mass);
  EXPECT_NEAR(s.mass, 1000.0 * 2.0 * enclosed_volume(body.mesh), 1e-9 * s.mass);
  const auto surfaces = world.surfaces();
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].name, "torus");
  EXPECT_LT((surfaces[0].positions - expected.vertices).cwiseAbs().maxCoeff(), 1e-9);
  const Aabb box = bounding_box(TriMesh{surfaces[0].positions, surfaces[0].triangles, nullptr});
  EXPECT_NEAR(box.extent().x(), 2 * 2 * 0.7, 0.05);  // major diameter along x, scaled
  EXPECT_NEAR(box.extent().y(), 2 * 0.7, 0.05);      // rotated into y
  EXPECT_NEAR(box.extent().z(), 2 * 0.2, 0.01);      // tube thickness along z
  EXPECT_NEAR(s.center_of_mass.y(), 3.0, 1e-6);
}

TEST(World, EulerAnglesApplyAboutXThenYThenZ) {
  Transform t;
  t.rotation = Eigen::Vector3d(90, 90, 0);
  // Local +y: about x by 90 -> +z, then about y by 90 -> +x.
  EXPECT_LT((t.rotation_matrix() * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitX()).norm(), 1e-12);
  t.rotation = Eigen::Vector3d(0, 0, 90);
  EXPECT_LT((t.rotation_matrix() * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-12);
}

TEST(World, NumericalTroubleIsAStatus) {
  WorldDesc desc;
  desc.dt = 0.01;
  desc.bodies.push_back(box_body({0.1, 0.1, 0.1}, 2, soft_material(), Eigen::Vector3d::Zero(), "jelly"));
  World world(desc);
  Eigen::VectorXd x = world.positions(), v = world.velocities();
  // Fold one node through the body: inverted elements.
  x.segment<3>(0) = -x.segment<3>(0) * 1.5;
  world.set_state(x, v);
  StepReport r = world.step();
  EXPECT_EQ(r.status, StepStatus::inverted);
  EXPECT_EQ(r.body, "jelly");
  EXPECT_GT(r.inverted_tets, 0);
  // An absurd velocity: far more energy than the body ever had.
  world.set_state(world.positions(), Eigen::VectorXd::Constant(v.size(), 1e4), /*reset_energy_reference=*/false);
  r = world.step();
  EXPECT_EQ(r.status, StepStatus::energy_blowup);
  // NaN anywhere.
  x = world.positions();
  x[4] = std::numeric_limits<double>::quiet_NaN();
  world.set_state(x, v);
  r = world.step();
  EXPECT_EQ(r.status, StepStatus::nan);
  EXPECT_EQ(r.body, "jelly");
  EXPECT_GE(world.counters().nan_steps, 1);
  std::cout << "statuses: " << to_string(StepStatus::inverted) << ", " << to_string(StepStatus::energy_blowup) << ", "
            << to_string(StepStatus::nan) << "\n";
}

TEST(World, InvalidDescriptionsAreBadInput) {
  WorldDesc desc;
  desc.bodies.push_back(box_body({0.1, 0.1, 0.1}, 2, soft_material()));
  desc.bodies.back().material.poisson_ratio = 0.5;
  try {
    World world(desc);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bodies/0/material/poisson_ratio"), std::string::npos) << e.what();
  }
  desc.bodies.back().material = soft_material();
  desc.dt = 0.0;
  EXPECT_THROW(World world(desc), Error);
}

}  // namespace
}  // namespace recoil::sim
