#include "sim/fem/material.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/error.h"

namespace recoil::sim {

void validate(const Material& m, const std::string& where) {
  auto fail = [&](const std::string& field, const std::string& why, double value) {
    throw bad_input(where + "/" + field + ": " + why + " (got " + std::to_string(value) + ")");
  };
  if (!(m.youngs_modulus > 0.0) || !std::isfinite(m.youngs_modulus))
    fail("youngs_modulus", "must be > 0", m.youngs_modulus);
  if (!(m.poisson_ratio >= 0.0 && m.poisson_ratio < 0.5)) fail("poisson_ratio", "must be in [0, 0.5)", m.poisson_ratio);
  if (!(m.density > 0.0) || !std::isfinite(m.density)) fail("density", "must be > 0", m.density);
  if (!(m.damping_ratio >= 0.0) || !std::isfinite(m.damping_ratio)) fail("damping", "must be >= 0", m.damping_ratio);
}

Lame lame_parameters(double e, double nu) {
  return {e / (2.0 * (1.0 + nu)), e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))};
}

void project_psd(Matrix9d& m) {
  // Most elements are positive definite: a Cholesky factorisation (a tenth of
  // the cost of the eigen-decomposition) proves it and skips the projection.
  if (Eigen::LLT<Matrix9d>(m).info() == Eigen::Success) return;
  Eigen::SelfAdjointEigenSolver<Matrix9d> eig(m);
  Vector9d values = eig.eigenvalues();
  if (values.minCoeff() >= 0.0) return;
  values = values.cwiseMax(0.0);
  m = eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
}

DensityEval evaluate_density(MaterialModel model, const Eigen::Matrix3d& F, const Lame& lame, HessianMode mode) {
  return model == MaterialModel::corotated ? corotated_density(F, lame, mode) : neo_hookean_density(F, lame, mode);
}

}  // namespace recoil::sim
