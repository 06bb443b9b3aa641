#include "sim/fem/vibration_modes.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/check.h"

namespace recoil::sim {

namespace {

// Subspace size: six rigid modes plus room for a degenerate lowest cluster
// (a symmetric body has two or three equal lowest frequencies).
constexpr int kSubspace = 12;
constexpr int kMaxIterations = 60;
constexpr double kConvergence = 1e-10;  // relative change of the lowest omega^2 between iterations

// Rest stiffness on the free DoF (#free by #free, N/m); `free_index` maps a
// global DoF to its free column or -1.
Eigen::SparseMatrix<double> rest_stiffness(const VibrationInput& in, const std::vector<int>& free_index,
                                           int num_free) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(in.rest->num_tets()) * 144);
  for (int t = 0; t < in.rest->num_tets(); ++t) {
    Vector12d x;
    for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = in.rest->nodes.row(in.rest->tets(t, k)).transpose();
    const ElementEval e = evaluate_element(in.model, in.lame, (*in.elements)[static_cast<size_t>(t)], x,
                                           /*want_hessian=*/true, /*project=*/true);
    for (int a = 0; a < 12; ++a) {
      const int row = free_index[static_cast<size_t>(3 * in.rest->tets(t, a / 3) + a % 3)];
      if (row < 0) continue;
      for (int c = 0; c < 12; ++c) {
        const int col = free_index[static_cast<size_t>(3 * in.rest->tets(t, c / 3) + c % 3)];
        if (col >= 0) entries.emplace_back(row, col, e.hessian(a, c));
      }
    }
  }
  Eigen::SparseMatrix<double> K(num_free, num_free);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

}  // namespace

VibrationMode lowest_vibration_mode(const VibrationInput& in) {
  RECOIL_CHECK(in.rest && in.elements && in.mass && in.pinned);
  const int num_dof = 3 * in.rest->num_nodes();
  std::vector<int> free_index(static_cast<size_t>(num_dof), -1);
  std::vector<int> free_dof;
  for (int i = 0; i < in.rest->num_nodes(); ++i)
    if (!(*in.pinned)[static_cast<size_t>(i)])
      for (int k = 0; k < 3; ++k) {
        free_index[static_cast<size_t>(3 * i + k)] = static_cast<int>(free_dof.size());
        free_dof.push_back(3 * i + k);
      }
  const int n = static_cast<int>(free_dof.size());
  VibrationMode out;
  out.shape = Eigen::VectorXd::Zero(num_dof);
  if (n == 0) return out;

  Eigen::VectorXd m(n);
  for (int j = 0; j < n; ++j) m[j] = (*in.mass)[free_dof[static_cast<size_t>(j)] / 3];
  const Eigen::VectorXd root_mass = m.cwiseSqrt(), inverse_root_mass = root_mass.cwiseInverse();
  const Eigen::SparseMatrix<double> K = rest_stiffness(in, free_index, n);

  // The scale of omega^2: a bar's first longitudinal mode (pi / L)^2 E / rho
  // over the body's longest side L. It sets the shift and what counts as zero.
  const Eigen::Vector3d extent = in.rest->nodes.colwise().maxCoeff() - in.rest->nodes.colwise().minCoeff();
  const double density = in.mass->sum() / std::max(total_volume(*in.rest), 1e-300);
  const double young = in.lame.mu * (3.0 * in.lame.lambda + 2.0 * in.lame.mu) / (in.lame.lambda + in.lame.mu);
  const double scale = std::pow(std::numbers::pi / std::max(extent.maxCoeff(), 1e-12), 2) * young / density;
  const double sigma = 1e-3 * scale;  // small against the lowest elastic mode, so it converges fast
  const double zero = 1e-6 * scale;   // rigid modes come out at round-off level, far below this

  Eigen::SparseMatrix<double> shifted = K;
  for (int j = 0; j < n; ++j) shifted.coeffRef(j, j) += sigma * m[j];
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(shifted);
  RECOIL_CHECK(factor.info() == Eigen::Success, "shifted rest stiffness is not positive definite");

  // A fixed pseudo-random start (std::mt19937 is the same sequence everywhere).
  const int p = std::min(kSubspace, n);
  std::mt19937 rng(1);
  Eigen::MatrixXd X(n, p);
  for (Eigen::Index i = 0; i < X.size(); ++i) X.data()[i] = static_cast<double>(rng()) / 4294967296.0 - 0.5;
  // The first Ritz value above numerical zero.
  auto lowest_elastic = [&](const Eigen::VectorXd& ritz) {
    int first = 0;
    while (first < p - 1 && ritz[first] < zero) ++first;
    return first;
  };
  double previous = -1.0;
  Eigen::VectorXd ritz;
  for (int it = 0; it < kMaxIterations; ++it) {
    // M-orthonormal basis of the new subspace through a Householder QR of
    // M^1/2 Y: the shift makes the rigid directions dominate Y, so forming
    // Y^T M Y directly would lose the elastic ones to round-off.
    const Eigen::MatrixXd Z = root_mass.asDiagonal() * factor.solve(m.asDiagonal() * X);
    const Eigen::MatrixXd Q = Z.householderQr().householderQ() * Eigen::MatrixXd::Identity(n, p);
    const Eigen::MatrixXd Y = inverse_root_mass.asDiagonal() * Q;
    const Eigen::MatrixXd Kr = Y.transpose() * (K * Y);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> small(0.5 * (Kr + Kr.transpose()));
    RECOIL_CHECK(small.info() == Eigen::Success, "Rayleigh-Ritz step failed");
    X = Y * small.eigenvectors();  // M-orthonormal columns, ascending omega^2
    ritz = small.eigenvalues();
    const int first = lowest_elastic(ritz);
    if (std::abs(ritz[first] - previous) <= kConvergence * ritz[first]) break;
    previous = ritz[first];
  }
  const int first = lowest_elastic(ritz);
  out.omega = std::sqrt(std::max(ritz[first], 0.0));
  for (int j = 0; j < n; ++j) out.shape[free_dof[static_cast<size_t>(j)]] = X(j, first);
  return out;
}

}  // namespace recoil::sim
