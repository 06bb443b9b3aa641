// Static validation of the FEM against closed forms :
// a bar hanging under its own weight and a cantilever under its own weight
// (Euler-Bernoulli). Both settle by implicit Euler with large steps and mass
// damping, which converges to the static equilibrium.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/sim/fem/fem_scenes.h"
#include "tests/validation/measured.h"

namespace recoil::sim {
namespace {

constexpr double kG = 9.81;

// Steps until the largest node speed falls below `speed` (m/s) or `max_steps`.
// Returns the steps taken; fails the test on any non-ok status.
int settle(World& world, double speed, int max_steps) {
  for (int i = 1; i <= max_steps; ++i) {
    const StepReport r = world.step();
    EXPECT_EQ(r.status, StepStatus::ok) << to_string(r.status);
    if (r.status != StepStatus::ok) return i;
    if (world.velocities().cwiseAbs().maxCoeff() < speed) return i;
  }
  return max_steps;
}

TEST(FemStatics, HangingBarLowersItsCentreOfMassByRhoGL2Over3E) {
  const double L = 1.0, a = 0.1, E = 1e6, rho = 1000.0;
  for (MaterialModel model : {MaterialModel::corotated, MaterialModel::neo_hookean}) {
    Material m = test_scenes::soft_material(model);
    m.youngs_modulus = E;
    m.poisson_ratio = 0.0;  // 1-D bar: no lateral contraction against the clamped top
    m.density = rho;
    m.damping_ratio = 1.0;  // critically damped lowest mode: settles fast
    WorldDesc desc;
    desc.dt = 0.05;
    desc.solver.max_iterations = 20000;
    desc.bodies.push_back(test_scenes::box_body({a, L, a}, 20, m));
    desc.bodies.back().pinned = PinBox{Eigen::Vector3d(-1, 0.5 * L - 1e-9, -1), Eigen::Vector3d(1, 1, 1)};
    World world(desc);
    const double y0 = world.stats()[0].center_of_mass.y();
    const int steps = settle(world, 1e-6, 400);
    const double measured = y0 - world.stats()[0].center_of_mass.y();
    const double expected = rho * kG * L * L / (3.0 * E);
    validation::Measured() << (model == MaterialModel::corotated ? "corotated" : "neo-hookean")
              << " hanging bar: centre of mass lowered " << measured << " m, expected rho g L^2/(3E) = " << expected
              << " m, error " << 100.0 * (measured - expected) / expected << " % after " << steps << " steps\n";
    EXPECT_NEAR(measured, expected, 0.1 * expected);
  }
}

TEST(FemStatics, CantileverDeflectionApproachesEulerBernoulli) {
  const double L = 1.0, a = 0.1, E = 1e8, rho = 1000.0;
  // delta = q L^4 / (8 E I), q = rho g a^2, I = a^4 / 12.
  const double expected = rho * kG * a * a * std::pow(L, 4) / (8.0 * E * std::pow(a, 4) / 12.0);
  std::vector<double> ratios;
  for (int resolution : {10, 20, 40}) {
    Material m = test_scenes::soft_material(MaterialModel::corotated);
    m.youngs_modulus = E;
    m.poisson_ratio = 0.0;
    m.density = rho;
    m.damping_ratio = 1.0;
    WorldDesc desc;
    desc.dt = 0.2;
    desc.solver.max_iterations = 50000;
    desc.bodies.push_back(test_scenes::box_body({L, a, a}, resolution, m));
    desc.bodies.back().pinned = PinBox{Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(-0.5 * L + 1e-9, 1, 1)};
    World world(desc);
    const Eigen::VectorXd x0 = world.positions();
    const int steps = settle(world, 1e-7, 200);
    // Tip deflection: mean vertical displacement of the free end's nodes.
    double sum = 0.0;
    int count = 0;
    for (Eigen::Index n = 0; n < x0.size() / 3; ++n)
      if (x0[3 * n] > 0.5 * L - 1e-9) {
        sum += x0[3 * n + 1] - world.positions()[3 * n + 1];
        ++count;
      }
    const double measured = sum / count;
    ratios.push_back(measured / expected);
    validation::Measured() << "cantilever at resolution " << resolution << " (" << world.stats()[0].num_tets << " tets): tip "
              << measured << " m, Euler-Bernoulli " << expected << " m, ratio " << ratios.back() << " after " << steps
              << " steps\n";
  }
  // Linear tets lock in bending: the deflection grows towards the beam theory
  // value as the mesh is refined.
  EXPECT_LT(ratios[0], ratios[1]);
  EXPECT_LT(ratios[1], ratios[2]);
  EXPECT_GT(ratios[2], 0.75);
  EXPECT_LT(ratios[2], 1.1);
}

}  // namespace
}  // namespace recoil::sim
