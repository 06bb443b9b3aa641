#pragma once
// One accuracy measure for every contact solver (cr, cr_plain, pgs), so that
// benchmarks compare them at the same accuracy. Every term is a velocity in
// m/s: momentum errors are scaled by P_A^-1 (momentum_preconditioner.h),
// impulse errors by the row's effective inverse mass diag(J P_A^-1 J^T).
#include <Eigen/Core>
#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

struct KktResidual {
  double momentum = 0.0;         // |P_A^-1 (A dv - b - J^T f)|_inf
  double penetration = 0.0;      // max over contacts of rhs_normal - J_n dv, when positive
  double complementarity = 0.0;  // negative lambda; min(separation, lambda) of an active contact
  double friction = 0.0;         // sticking: tangential slip, cone excess; sliding: Coulomb law violation
  double max() const;
};

// dv: #DoF; problem.states hold the multipliers (as the solvers leave them).
// P_A^-1 is problem.preconditioner, or block Jacobi when it is null.
KktResidual kkt_residual(const ContactProblem& problem, const Eigen::VectorXd& dv);
// The same with P_A^-1 given, for a caller that measures many iterates of one problem.
KktResidual kkt_residual(const ContactProblem& problem, const Eigen::VectorXd& dv, const MomentumPreconditioner& P);

}  // namespace recoil::sim
