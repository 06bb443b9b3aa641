// Exits and safeguards of the solvers: re-linearisation that turns the rows
// is solved for, the re-linearisation cap reports non-convergence, a pulled
// contact is let go, and a residual stuck on an inconsistent singular system
// stops early (|B C^-1 r| < epsilon_1) instead of burning the budget, a
// rigid body's included.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "sim/solver/contact_rows_ops.h"
#include "sim/solver/kkt_residual.h"
#include "tests/fixtures/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

using solver_test::kG;
using solver_test::kH;
using solver_test::kMethods;

// Re-linearisation that tilts the contact normal by 20 degrees about x
// (as a contact sliding onto a slope would) while its right-hand side stays
// zero: the reported change is 0, yet the rows did change.
class TiltingLinearization : public ContactLinearization {
 public:
  int calls = 0;
  int add_new_contacts(const Eigen::VectorXd&, ContactProblem&) override { return 0; }
  double relinearize(const Eigen::VectorXd&, ContactProblem& problem) override {
    if (calls++ == 0) {
      const double theta = 20.0 * M_PI / 180.0;
      problem.rows[0].blocks[0] = contact_frame(Eigen::Vector3d(0.0, -std::sin(theta), std::cos(theta)));
    }
    return 0.0;
  }
};

// Re-linearisation that never settles: every call moves the normal rhs.
class RestlessLinearization : public ContactLinearization {
 public:
  int add_new_contacts(const Eigen::VectorXd&, ContactProblem&) override { return 0; }
  double relinearize(const Eigen::VectorXd&, ContactProblem& problem) override {
    problem.rows[0].rhs_normal += 0.01;
    return 0.01;
  }
};

OwnedProblem resting_particle(double mu) {
  return particle_on_incline(1.0, 0.0, kG, kH, Eigen::Vector2d::Zero(), mu, mu);
}

TEST(SolverRobustness, TurnedRowsAreSolvedAfterRelinearization) {
  for (SolverMethod method : kMethods) {
    OwnedProblem owned = resting_particle(0.0);
    TiltingLinearization tilt;
    Eigen::VectorXd dv;
    const auto stats = solve_contacts(owned.problem, solver_test::tight(method), dv, &tilt);
    // Frictionless on the tilted plane: slides down it with g sin(theta) h.
    const double theta = 20.0 * M_PI / 180.0;
    const Eigen::Vector3d up_slope(0.0, std::cos(theta), std::sin(theta));
    const double along = -dv.dot(up_slope);
    std::cout << to_string(method) << ": after a tilting relinearization, speed down the slope " << along
              << " m/s (expected " << kG * std::sin(theta) * kH << "), kkt " << stats.kkt << ", relinearizations "
              << stats.relinearizations << "\n";
    EXPECT_TRUE(stats.converged) << to_string(method);
    EXPECT_LT(stats.kkt, 1e-9) << to_string(method);
    EXPECT_NEAR(along, kG * std::sin(theta) * kH, 1e-9) << to_string(method);
  }
}

TEST(SolverRobustness, RelinearizationCapReportsNotConverged) {
  for (SolverMethod method : kMethods) {
    OwnedProblem owned = resting_particle(0.5);
    RestlessLinearization restless;
    ContactSolverSettings settings = solver_test::tight(method);
    settings.max_relinearizations = 3;
    Eigen::VectorXd dv;
    const auto stats = solve_contacts(owned.problem, settings, dv, &restless);
    std::cout << to_string(method) << ": restless relinearization: " << stats.relinearizations
              << " relinearizations, converged " << stats.converged << "\n";
    EXPECT_FALSE(stats.converged) << to_string(method);
    EXPECT_EQ(stats.relinearizations, 3) << to_string(method);
  }
}

// Warm started active, then pulled upward: the contact separates (Algorithm
// 2 lines 5-6) and the particle rises freely.
TEST(SolverRobustness, APulledContactIsLetGo) {
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain}) {
    OwnedProblem owned = resting_particle(0.5);
    owned.problem.b[2] = +kH * kG;
    owned.problem.states[0].mode = ContactMode::sliding;
    owned.problem.states[0].lambda = 0.1;
    const auto s = solver_test::solve_copy(owned.problem, solver_test::tight(method));
    std::cout << to_string(method) << ": pulled contact: converged " << s.stats.converged << ", dv_z " << s.dv[2]
              << "\n";
    EXPECT_TRUE(s.stats.converged) << to_string(method);
    EXPECT_NEAR(s.dv[2], kH * kG, 1e-9) << to_string(method);
    EXPECT_EQ(s.states[0].mode, ContactMode::inactive) << to_string(method);
  }
}

// Two sticking contacts on one particle with the same frame but tangential
// right-hand sides 1e-7 m/s apart: B is singular and d is not in its range,
// so the residual cannot drop below ~5e-8 m/s. Tolerance 1e-11: without the
// |B C^-1 r| exit the solver would iterate to the cap. It stops at the
// least-squares compromise, above its tolerance: unconverged.
TEST(SolverRobustness, StationaryResidualStopsEarly) {
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain}) {
    OwnedProblem owned = particle_on_incline(1.0, 0.0, kG, kH, Eigen::Vector2d::Zero(), 1e6, 1e6);
    owned.problem.rows.push_back(owned.problem.rows[0]);
    owned.problem.states.push_back(owned.problem.states[0]);
    owned.problem.rows[1].rhs_tangent = Eigen::Vector2d(1e-7, 0.0);
    for (ContactState& s : owned.problem.states) {
      s.mode = ContactMode::sticking;
      s.lambda = 0.5 * kH * kG;
    }
    const ContactSolverSettings settings = solver_test::tight(method, 1e-11, 20000);
    const auto s = solver_test::solve_copy(owned.problem, settings);
    std::cout << to_string(method) << ": inconsistent sticking rows: iterations " << s.stats.iterations
              << ", restarts " << s.stats.restarts << ", residual " << s.stats.residual << ", dv_y " << s.dv[1]
              << ", lambdas " << s.states[0].lambda << " " << s.states[1].lambda << "\n";
    EXPECT_FALSE(s.stats.converged) << to_string(method);
    EXPECT_LT(s.stats.iterations + s.stats.restarts, 200) << to_string(method);
    EXPECT_NEAR(s.dv[1], 0.5e-7, 1e-9) << to_string(method) << ": the least-squares compromise";
    EXPECT_NEAR(s.states[0].lambda + s.states[1].lambda, kH * kG, 1e-9) << to_string(method);
    EXPECT_LT(std::abs(s.states[0].gamma[0]) + std::abs(s.states[1].gamma[0]), 1.0) << to_string(method);
  }
}

// A rigid box held on its four sticking corners, two of them asked for
// tangential velocities 2e-4 m/s apart, which no rigid motion gives (a
// rotating body's linearised rows ask this to second order). The residual
// left is in B's null space: each restart finds z^T B z ~ 0, and a
// minimal-residual step from there moved the iterate off the explicit
// residual, so that every recheck restarted again until the budget ran out.
// It stops early, above its tolerance: unconverged.
TEST(SolverRobustness, ARigidBodysStationaryResidualStopsEarly) {
  constexpr double kMass = 3.0, kApart = 1e-4;  // kg, m/s
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain}) {
    OwnedProblem owned =
        rigid_box_on_ground(Eigen::Vector3d(1.0, 0.6, 0.4), kMass, 0.3, kG, kH, Eigen::Vector3d::Zero(), 1e6, 1e6);
    for (ContactState& s : owned.problem.states) {
      s.mode = ContactMode::sticking;
      s.lambda = 0.25 * kMass * kG * kH;
    }
    owned.problem.rows[0].rhs_tangent = Eigen::Vector2d(kApart, 0.3 * kApart);
    owned.problem.rows[3].rhs_tangent = Eigen::Vector2d(-kApart, 0.5 * kApart);
    const auto s = solver_test::solve_copy(owned.problem, solver_test::tight(method, 1e-9, 20000));
    double lambda_sum = 0.0;
    for (const ContactState& state : s.states) lambda_sum += state.lambda;
    std::cout << to_string(method) << ": rigid box, inconsistent sticking corners: iterations " << s.stats.iterations
              << ", restarts " << s.stats.restarts << ", kkt " << s.stats.kkt << ", |dv|_inf "
              << s.dv.lpNorm<Eigen::Infinity>() << "\n";
    EXPECT_FALSE(s.stats.converged) << to_string(method);
    EXPECT_LT(s.stats.iterations + s.stats.restarts, 100) << to_string(method);
    EXPECT_NEAR(lambda_sum, kMass * kG * kH, 1e-9) << to_string(method) << ": the normal rows are consistent";
    for (size_t k = 0; k < owned.problem.rows.size(); ++k) {
      // Each corner's tangential velocity misses what its rows ask by no more
      // than the two requests differ: a compromise between them.
      const ContactRows& rows = owned.problem.rows[k];
      const Eigen::Vector2d miss = rows_times(rows, s.dv).tail<2>() - rows.rhs_tangent;
      EXPECT_LT(miss.norm(), 2.0 * kApart) << to_string(method) << ": corner " << k;
    }
  }
}

}  // namespace
}  // namespace recoil::sim
