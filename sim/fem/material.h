#pragma once
// Material parameters of a deformable body (`material`)
// and the per-model energy densities behind them.
#include <Eigen/Core>
#include <string>

namespace recoil::sim {

enum class MaterialModel { corotated, neo_hookean };

struct Material {
  MaterialModel model = MaterialModel::corotated;
  double youngs_modulus = 1e5;  // E, Pa
  double poisson_ratio = 0.3;   // nu, in [0, 0.5)
  double density = 1000.0;      // rho, kg/m^3
  // Damping ratio zeta of the body's lowest vibration mode, dimensionless. It is
  // stiffness-proportional (D = beta K), so rigid motion is never damped.
  double damping_ratio = 0.0;
};

// Throws bad_input naming `where` (e.g. "bodies/1/material") and the field.
void validate(const Material& material, const std::string& where);

struct Lame {
  double mu = 0.0;      // shear modulus, Pa
  double lambda = 0.0;  // first Lame parameter, Pa
};
Lame lame_parameters(double youngs_modulus, double poisson_ratio);

using Matrix9d = Eigen::Matrix<double, 9, 9>;
using Vector9d = Eigen::Matrix<double, 9, 1>;

// What second derivative to compute: none, the exact dP/dF, or dP/dF with
// negative eigenvalues clamped to zero (so element Hessians are PSD).
enum class HessianMode { none, exact, projected };

// One energy density evaluation at deformation gradient F. Vectors over F are
// column-major: index i + 3 j holds F(i, j).
struct DensityEval {
  double psi = 0.0;                  // energy density, J/m^3
  Eigen::Matrix3d P;                 // first Piola-Kirchhoff stress dpsi/dF, Pa
  Matrix9d dPdF;                     // d vec(P) / d vec(F), Pa (symmetric; projected when asked)
};

// Co-rotated linear: psi = mu |F - R|^2 + lambda/2 (tr(R^T F) - 3)^2 with R
// the rotation of the polar decomposition (SVD with reflections folded into
// the smallest singular value, so inverted elements push back).
// Its dP/dF has a closed-form eigen-system (the three "twist" directions
// u_i v_j^T - u_j v_i^T carry all possibly negative eigenvalues), so its
// projection is analytic.
DensityEval corotated_density(const Eigen::Matrix3d& F, const Lame& lame, HessianMode mode);

// Stable Neo-Hookean (Smith, de Goes, Kim 2018, without the log term):
// psi = mu/2 (|F|^2 - 3) + lambda'/2 (J - a)^2, lambda' = lambda + mu,
// a = 1 + mu / lambda', which matches linear elasticity at rest and is
// defined for J <= 0.
// Projected by project_psd.
DensityEval neo_hookean_density(const Eigen::Matrix3d& F, const Lame& lame, HessianMode mode);

DensityEval evaluate_density(MaterialModel model, const Eigen::Matrix3d& F, const Lame& lame, HessianMode mode);

// Clamps negative eigenvalues of a symmetric matrix to zero.
void project_psd(Matrix9d& m);

}  // namespace recoil::sim
