// Element energies, forces and Hessians of both materials against finite
// differences, at rest, under rotation, and after PSD projection.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <iostream>
#include <random>

#include "core/error.h"
#include "sim/fem/element.h"

namespace recoil::sim {
namespace {

struct Case {
  MaterialModel model;
  const char* name;
};
const Case kCases[] = {{MaterialModel::corotated, "corotated"}, {MaterialModel::neo_hookean, "neo-hookean"}};

// A skewed rest tet of size ~0.1 m.
TetMesh rest_tet() {
  TetMesh m;
  m.nodes.resize(4, 3);
  m.nodes << 0.0, 0.0, 0.0, 0.12, 0.01, -0.02, 0.03, 0.09, 0.01, -0.01, 0.02, 0.11;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  return m;
}

Vector12d flatten(const Points& p) {
  Vector12d x;
  for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = p.row(k).transpose();
  return x;
}

const Lame kLame = lame_parameters(1e5, 0.35);

double fd_energy_error(MaterialModel model, const ElementRest& rest, const Vector12d& x, const Vector12d& g) {
  Vector12d fd;
  const double eps = 1e-7;
  for (int i = 0; i < 12; ++i) {
    Vector12d xp = x, xm = x;
    xp[i] += eps;
    xm[i] -= eps;
    fd[i] = (evaluate_element(model, kLame, rest, xp, false, false).energy -
             evaluate_element(model, kLame, rest, xm, false, false).energy) / (2 * eps);
  }
  return (fd - g).norm() / g.norm();
}

double fd_hessian_error(MaterialModel model, const ElementRest& rest, const Vector12d& x, const Matrix12d& H) {
  Matrix12d fd;
  const double eps = 1e-7;
  for (int i = 0; i < 12; ++i) {
    Vector12d xp = x, xm = x;
    xp[i] += eps;
    xm[i] -= eps;
    fd.col(i) = (evaluate_element(model, kLame, rest, xp, false, false).gradient -
                 evaluate_element(model, kLame, rest, xm, false, false).gradient) / (2 * eps);
  }
  return (fd - H).norm() / H.norm();
}

TEST(Material, ForcesAndHessiansMatchFiniteDifferences) {
  const TetMesh mesh = rest_tet();
  const ElementRest rest = element_rest(mesh)[0];
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Case& c : kCases) {
    double worst_g = 0.0, worst_h = 0.0;
    for (int trial = 0; trial < 20; ++trial) {
      // Random stretch/shear of up to 30 % of the edge length, then a random rotation.
      Vector12d x = flatten(mesh.nodes);
      for (int i = 0; i < 12; ++i) x[i] += 0.03 * u(rng);
      const Eigen::Matrix3d R =
          Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
      for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = R * x.segment<3>(3 * k);
      const ElementEval e = evaluate_element(c.model, kLame, rest, x, true, false);
      worst_g = std::max(worst_g, fd_energy_error(c.model, rest, x, e.gradient));
      worst_h = std::max(worst_h, fd_hessian_error(c.model, rest, x, e.hessian));
    }
    std::cout << c.name << ": worst relative FD error, force " << worst_g << ", Hessian " << worst_h << "\n";
    EXPECT_LT(worst_g, 1e-5) << c.name;
    EXPECT_LT(worst_h, 1e-5) << c.name;
  }
}

TEST(Material, InvertedElementStillHasConsistentDerivatives) {
  const TetMesh mesh = rest_tet();
  const ElementRest rest = element_rest(mesh)[0];
  for (const Case& c : kCases) {
    // Push node 3 through the opposite face: the element is inverted.
    Vector12d x = flatten(mesh.nodes);
    x.segment<3>(9) = Eigen::Vector3d(0.03, 0.03, -0.04);
    ASSERT_LT(deformation_gradient(rest, x).determinant(), 0.0);
    const ElementEval e = evaluate_element(c.model, kLame, rest, x, true, false);
    const double eg = fd_energy_error(c.model, rest, x, e.gradient);
    const double eh = fd_hessian_error(c.model, rest, x, e.hessian);
    std::cout << c.name << " inverted: FD error force " << eg << ", Hessian " << eh << "\n";
    EXPECT_LT(eg, 1e-5);
    EXPECT_LT(eh, 1e-5);
    // The force on node 3 pushes it back up towards the positive side (+z here).
    EXPECT_GT(-e.gradient[11], 0.0) << c.name;
  }
}

TEST(Material, ZeroForceAtRestAndRotationInvariance) {
  const TetMesh mesh = rest_tet();
  const ElementRest rest = element_rest(mesh)[0];
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  for (const Case& c : kCases) {
    const Vector12d x = flatten(mesh.nodes);
    const ElementEval e = evaluate_element(c.model, kLame, rest, x, true, true);
    EXPECT_NEAR(e.energy, 0.0, 1e-12) << c.name;
    EXPECT_LT(e.gradient.norm(), 1e-9 * kLame.mu * rest.volume / 0.1) << c.name;

    // Rigidly rotated and translated rest shape: still no energy or force.
    Vector12d xr;
    for (int k = 0; k < 4; ++k) xr.segment<3>(3 * k) = R * x.segment<3>(3 * k) + Eigen::Vector3d(1, -2, 3);
    const ElementEval er = evaluate_element(c.model, kLame, rest, xr, false, false);
    EXPECT_NEAR(er.energy, 0.0, 1e-9) << c.name;
    EXPECT_LT(er.gradient.norm(), 1e-6) << c.name;

    // A deformed state and its rotation: same energy, rotated forces.
    Vector12d xd = x;
    xd[3] += 0.02;
    xd[7] -= 0.015;
    Vector12d xdr;
    for (int k = 0; k < 4; ++k) xdr.segment<3>(3 * k) = R * xd.segment<3>(3 * k);
    const ElementEval a = evaluate_element(c.model, kLame, rest, xd, false, false);
    const ElementEval b = evaluate_element(c.model, kLame, rest, xdr, false, false);
    EXPECT_NEAR(a.energy, b.energy, 1e-10 * a.energy) << c.name;
    for (int k = 0; k < 4; ++k)
      EXPECT_LT((R * a.gradient.segment<3>(3 * k) - b.gradient.segment<3>(3 * k)).norm(), 1e-9 * a.gradient.norm());
  }
}

TEST(Material, ProjectedHessiansArePositiveSemiDefinite) {
  const TetMesh mesh = rest_tet();
  const ElementRest rest = element_rest(mesh)[0];
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Case& c : kCases) {
    int indefinite_before = 0;
    double worst = 0.0;
    for (int trial = 0; trial < 50; ++trial) {
      Vector12d x = flatten(mesh.nodes);
      for (int i = 0; i < 12; ++i) x[i] += 0.08 * u(rng);  // large: compressions and inversions
      const ElementEval raw = evaluate_element(c.model, kLame, rest, x, true, false);
      const ElementEval proj = evaluate_element(c.model, kLame, rest, x, true, true);
      const Eigen::SelfAdjointEigenSolver<Matrix12d> eraw(raw.hessian), eproj(proj.hessian);
      if (eraw.eigenvalues().minCoeff() < -1e-9 * eraw.eigenvalues().cwiseAbs().maxCoeff()) ++indefinite_before;
      worst = std::min(worst, eproj.eigenvalues().minCoeff() / eproj.eigenvalues().cwiseAbs().maxCoeff());
    }
    std::cout << c.name << ": " << indefinite_before << "/50 raw Hessians indefinite; worst projected "
              << "min/max eigenvalue " << worst << "\n";
    EXPECT_GT(indefinite_before, 0) << "the trial set should exercise the projection";
    EXPECT_GT(worst, -1e-10) << c.name;
  }
}

TEST(Material, ValidationNamesTheField) {
  Material m;
  EXPECT_NO_THROW(validate(m, "bodies/0/material"));
  m.youngs_modulus = 0.0;
  try {
    validate(m, "bodies/0/material");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    EXPECT_NE(std::string(e.what()).find("bodies/0/material/youngs_modulus"), std::string::npos) << e.what();
  }
  m = Material{};
  m.poisson_ratio = 0.5;
  EXPECT_THROW(validate(m, "x"), Error);
  m.poisson_ratio = -0.1;
  EXPECT_THROW(validate(m, "x"), Error);
  m = Material{};
  m.density = -1.0;
  EXPECT_THROW(validate(m, "x"), Error);
}

}  // namespace
}  // namespace recoil::sim
