// Damping acts on deformation only: a damped body falls and slides exactly as
// an undamped one, while its lowest vibration decays at the stated ratio.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <iostream>
#include <vector>

#include "sim/fem/vibration_modes.h"
#include "tests/scenes/contact_scenes.h"
#include "tests/validation/contact_helpers.h"
#include "tests/validation/measured.h"

namespace recoil::sim {
namespace {

using namespace scenes;
using validation::motion;
using validation::run;
using validation::steps;

constexpr double kGravity = 9.81;

// The 0.2 m cube of the friction benchmarks (density 700) with damping ratio zeta.
DeformableBodyDesc damped_cube(double zeta, const Eigen::Vector3d& position, FrictionDesc f = {}) {
  Material m = jelly(1e5, kBenchDensity);
  m.damping_ratio = zeta;
  return soft_box("cube", Eigen::Vector3d::Constant(kBenchCube), 3, m, position, f);
}

TEST(DampingValidation, DampedFreeFallIsExactlyGT) {
  for (double zeta : {0.0, 0.02, 0.5}) {
    WorldDesc w = base_world(kBenchDt);
    w.bodies.push_back(damped_cube(zeta, Eigen::Vector3d::Zero()));
    World world(w);
    run(world, steps(0.5, w.dt));
    const double v = motion(world, 0).velocity.y(), expected = -kGravity * world.time();
    const double err = std::abs(v - expected) / std::abs(expected);
    validation::Measured() << "free fall, zeta " << zeta << ": v after " << world.time() << " s = " << v << " m/s, g t = "
              << -expected << ", relative error " << err << "\n";
    EXPECT_LT(err, 1e-6);
  }
}

TEST(DampingValidation, DampedSlideOnInclineMatchesCoulomb) {
  const double theta = 27.0 * kPi / 180.0, mu = 0.35, dt = kBenchDt;
  for (double zeta : {0.0, 0.02}) {
    WorldDesc w = base_world(dt);
    w.planes.push_back(incline(theta, friction(mu, mu)));
    DeformableBodyDesc b = damped_cube(zeta, Eigen::Vector3d::Zero(), friction(mu, mu));
    place_on_incline(b, theta, 0.1, 0.0);
    w.bodies.push_back(b);
    World world(w);
    run(world, steps(0.1, dt));
    // Least-squares slope of the down-slope velocity over the next 0.5 s: the
    // soft block's elastic wobble averages out over its periods.
    double st = 0, sv = 0, stt = 0, stv = 0;
    const int n = steps(0.5, dt);
    for (int i = 0; i < n; ++i) {
      run(world, 1);
      const double t = world.time(), v = motion(world, 0).velocity.dot(downslope(theta));
      st += t, sv += v, stt += t * t, stv += t * v;
    }
    const double a = (n * stv - st * sv) / (n * stt - st * st);
    const double expected = kGravity * (std::sin(theta) - mu * std::cos(theta));
    const double err = std::abs(a - expected) / expected;
    validation::Measured() << "incline 27 deg, mu 0.35, zeta " << zeta << ": a = " << a << " m/s^2, expected " << expected
              << ", relative error " << err << "\n";
    EXPECT_LT(err, 0.005);
  }
}

// One implicit-Euler step of a single mode q'' = -omega^2 q - beta omega^2 q'
// as the assembly takes it: returns the step's 2x2 map of (q, q').
Eigen::Matrix2d modal_step(double omega, double beta, double h) {
  const double w2 = omega * omega, denom = 1.0 + (h * beta + h * h) * w2;
  Eigen::Matrix2d step;
  step(1, 0) = -h * w2 / denom;                           // dv from q
  step(1, 1) = 1.0 - h * (beta + h) * w2 / denom;         // v + dv from v
  step(0, 0) = 1.0 + h * step(1, 0);                      // q + h (v + dv)
  step(0, 1) = h * step(1, 1);
  return step;
}

// Decay rate (1/s) and angular frequency (rad/s) of the discrete map.
std::pair<double, double> decay_and_frequency(const Eigen::Matrix2d& step, double h) {
  const std::complex<double> lambda = Eigen::EigenSolver<Eigen::Matrix2d>(step).eigenvalues()[0];
  return {-std::log(std::abs(lambda)) / h, std::abs(std::arg(lambda)) / h};
}

TEST(DampingValidation, LowestModeDecaysAtTheStatedRatio) {
  const double zeta = 0.05, h = 2e-4;
  WorldDesc w = base_world(h);
  w.gravity.setZero();
  w.bodies.push_back(damped_cube(zeta, Eigen::Vector3d::Zero()));
  World world(w);
  const DeformableBody& body = world.deformable_body(0);
  const VibrationMode mode =
      lowest_vibration_mode({&body.rest, &body.elements, body.material.model, body.lame, &body.mass, &body.pinned});
  ASSERT_GT(mode.omega, 0.0);
  EXPECT_NEAR(body.lowest_frequency, mode.omega, 1e-9 * mode.omega);
  EXPECT_NEAR(body.damping_beta, 2.0 * zeta / mode.omega, 1e-12);

  // Start in the mode with a small velocity (linear regime), then follow its
  // modal coordinate q = phi^T M (x - x_rest).
  const Eigen::VectorXd x0 = world.positions();
  Eigen::VectorXd m3(x0.size());
  for (int i = 0; i < body.num_nodes; ++i) m3.segment<3>(3 * i).setConstant(body.mass[i]);
  const double amplitude = 1e-4 * mode.omega;  // m/s per unit modal mass: about 0.1 mm of motion
  world.set_state(x0, amplitude * mode.shape);
  std::vector<double> q;
  const int n = steps(8.0 * 2.0 * kPi / mode.omega, h);
  for (int i = 0; i < n; ++i) {
    ASSERT_EQ(world.step().status, StepStatus::ok);
    q.push_back(mode.shape.dot(m3.cwiseProduct(world.positions() - x0)));
  }
  // Peaks of |q| (one per half period) by parabolic interpolation.
  std::vector<std::pair<double, double>> peaks;  // (time s, |q|)
  for (size_t i = 1; i + 1 < q.size(); ++i) {
    const double a = std::abs(q[i - 1]), b = std::abs(q[i]), c = std::abs(q[i + 1]);
    if (b > a && b >= c) {
      const double offset = 0.5 * (a - c) / (a - 2.0 * b + c);
      peaks.emplace_back((static_cast<double>(i + 1) + offset) * h, b - 0.25 * (a - c) * offset);
    }
  }
  ASSERT_GE(peaks.size(), 8u);
  const auto& first = peaks[1];
  const auto& last = peaks.back();
  const double measured_decay = std::log(first.second / last.second) / (last.first - first.first);
  const double half_periods = static_cast<double>(peaks.size() - 2);
  const double measured_omega = kPi * half_periods / (last.first - first.first);

  const auto [decay, omega_discrete] = decay_and_frequency(modal_step(mode.omega, body.damping_beta, h), h);
  const auto [numerical_decay, unused] = decay_and_frequency(modal_step(mode.omega, 0.0, h), h);
  const double measured_zeta = (measured_decay - numerical_decay) / mode.omega;
  validation::Measured() << "lowest mode: omega " << mode.omega << " rad/s (measured " << measured_omega
            << "), decay " << measured_decay << " 1/s against " << decay << " predicted for zeta " << zeta
            << " under implicit Euler (" << numerical_decay << " of it numerical); measured zeta " << measured_zeta
            << "\n";
  EXPECT_NEAR(measured_omega, omega_discrete, 0.01 * omega_discrete);
  EXPECT_NEAR(measured_decay, decay, 0.02 * decay);
  EXPECT_NEAR(measured_zeta, zeta, 0.05 * zeta);
}

// The mode is an eigenpair of the rest stiffness the world assembles
// (A = M + h^2 K for an undamped body at rest), and no lower one exists.
TEST(DampingValidation, LowestModeMatchesADenseEigenSolve) {
  const double h = 1e-3;
  WorldDesc w = base_world(h);
  w.gravity.setZero();
  Material m = jelly(1e5, 700.0);
  m.damping_ratio = 0.0;
  w.bodies.push_back(soft_box("box", Eigen::Vector3d(0.3, 0.2, 0.1), 2, m, Eigen::Vector3d::Zero()));
  World world(w);
  world.step();  // assembles A at the rest state (no forces act)
  const DeformableBody& body = world.deformable_body(0);
  const Eigen::MatrixXd A = Eigen::MatrixXd(world.system_matrix().to_eigen());
  Eigen::VectorXd m3(A.rows());
  for (int i = 0; i < body.num_nodes; ++i) m3.segment<3>(3 * i).setConstant(body.mass[i]);
  const Eigen::MatrixXd K = (A - Eigen::MatrixXd(m3.asDiagonal())) / (h * h);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(K, Eigen::MatrixXd(m3.asDiagonal()));
  const Eigen::VectorXd lambdas = dense.eigenvalues();
  int first = 0;
  while (lambdas[first] < 1e-6 * lambdas[lambdas.size() - 1]) ++first;
  const VibrationMode mode =
      lowest_vibration_mode({&body.rest, &body.elements, body.material.model, body.lame, &body.mass, &body.pinned});
  validation::Measured() << "dense: " << first << " zero modes, omega_1 " << std::sqrt(lambdas[first]) << " rad/s; subspace "
            << mode.omega << " rad/s\n";
  EXPECT_EQ(first, 6);
  EXPECT_NEAR(mode.omega, std::sqrt(lambdas[first]), 1e-6 * mode.omega);
  EXPECT_NEAR(mode.shape.dot(m3.cwiseProduct(mode.shape)), 1.0, 1e-9);
}

}  // namespace
}  // namespace recoil::sim
