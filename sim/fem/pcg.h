#pragma once
// Preconditioned conjugate gradients for the SPD system A dv = b of a step
// without contacts, preconditioned by P_A^-1 (momentum_preconditioner.h).
// Sequential and in a fixed order, hence bit-for-bit deterministic.
#include <Eigen/Core>

#include "sim/fem/block_sparse.h"
#include "sim/fem/momentum_preconditioner.h"

namespace recoil::sim {

struct PcgSettings {
  double relative_tolerance = 1e-8;  // stop when |r| <= tol * |b|
  int max_iterations = 2000;
};

struct PcgResult {
  int iterations = 0;
  double relative_residual = 0.0;  // |b - A x| / |b| at exit (recursive residual)
  bool converged = false;          // false: the iteration cap was hit or A was not SPD
};

// Solves A x = b from x = 0 with P_A^-1 = P (built from this A). x is resized to b's size.
PcgResult solve_pcg(const BlockSparseMatrix& A, const MomentumPreconditioner& P, const Eigen::VectorXd& b,
                    Eigen::VectorXd& x, const PcgSettings& settings);

}  // namespace recoil::sim
