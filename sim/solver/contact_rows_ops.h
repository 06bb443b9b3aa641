#pragma once
// Small kernels on the per-contact rows of contact_problem.h, shared by the
// CR solver, the PGS baseline and the KKT residual: J_k dv, J_k^T f, and
// the per-row effective inverse mass diag(J P_A^-1 J^T) that turns an
// impulse (N s) into a velocity (m/s), P_A^-1 as in momentum_preconditioner.h.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// J_k dv: (normal, t1, t2) velocities in m/s. dv is #DoF.
Eigen::Vector3d rows_times(const ContactRows& rows, const Eigen::VectorXd& dv);

// out += J_k^T f (f = (normal, t1, t2) impulses, N s). out is #DoF.
void add_rows_transpose_times(const ContactRows& rows, const Eigen::Vector3d& f, Eigen::VectorXd& out);

// The normal row alone: J_n dv (m/s), and out += J_n^T lambda (N s), for
// the rows the CR product and the evaluation need without the tangents (a
// sliding or an inactive contact). Rounded exactly as row 0 of rows_times
// (and, but for the sign of a zero, as add_rows_transpose_times), so that
// either path gives the same bits, as long as the compiler contracts no
// multiply-add into an FMA (the project's flags do not; -mfma would).
double normal_row_times(const ContactRows& rows, const Eigen::VectorXd& dv);
void add_normal_row_transpose_times(const ContactRows& rows, double lambda, Eigen::VectorXd& out);

// The P_A^-1 a solver of `problem` uses: problem.preconditioner, or block
// Jacobi of problem.A (owned here) when that is null. Neither copied nor moved.
class ProblemPreconditioner {
 public:
  explicit ProblemPreconditioner(const ContactProblem& problem);
  ProblemPreconditioner(const ProblemPreconditioner&) = delete;
  ProblemPreconditioner& operator=(const ProblemPreconditioner&) = delete;
  const MomentumPreconditioner& get() const { return *m_used; }

 private:
  std::optional<MomentumPreconditioner> m_own;
  const MomentumPreconditioner* m_used;
};

// diag(J_k P_A^-1 J_k^T) for the three rows of one contact, 1/kg. A row that
// touches no free DoF gets 0.
Eigen::Vector3d effective_inverse_mass(const ContactRows& rows, const MomentumPreconditioner& P);

// J_a,n P_A^-1 J_b,n^T: the coupling of two contacts' normal rows through
// the DoF nodes they share and the rigid motions of the bodies they both
// touch, 1/kg (0 when they share neither; for a = b it is
// effective_inverse_mass(a)[0]).
double normal_rows_product(const ContactRows& a, const ContactRows& b, const MomentumPreconditioner& P);

// A contact's three rows' velocities under the rigid motions of the
// deformable bodies it touches (J_k Z_b, 3 by 6 each, at most two bodies: a
// contact has two sides), the part of its rows that P_A^-1's coarse term sees.
struct ContactRowModes {
  int count = 0;
  std::array<int, 2> body{};
  std::array<MomentumPreconditioner::ModeBlock, 2> rows_times_modes;
};
ContactRowModes contact_row_modes(const ContactRows& rows, const MomentumPreconditioner& P);

// A normal row's velocities under the rigid motions of the bodies its
// contact touches (J_n Z_b, 1 by 6 each, at most two bodies): what
// normal_rows_product recomputes per pair, for a caller measuring many pairs.
struct NormalRowModes {
  int count = 0;
  std::array<int, 2> body{};
  std::array<Eigen::Matrix<double, 1, 6>, 2> row;
};
NormalRowModes normal_row_modes(const ContactRows& rows, const MomentumPreconditioner& P);
double normal_rows_product(const ContactRows& a, const NormalRowModes& modes_a, const ContactRows& b,
                           const NormalRowModes& modes_b, const MomentumPreconditioner& P);

// The part of effective_inverse_mass(rows)[0] that comes through those
// rigid motions (P_A^-1's coarse term), 1/kg: the only coupling two normal
// rows without a shared DoF node can have.
double normal_row_rigid_part(const NormalRowModes& modes, const MomentumPreconditioner& P);

// Whether a contact's two sides were at rest relative to each other as the
// step began: its slip at dv = 0, -rhs_tangent, is within eps2 (m/s).
inline bool sides_at_rest(const ContactRows& rows, double eps2) { return rows.rhs_tangent.norm() <= eps2; }

// The friction coefficient of a sliding contact: mu_static while its slip
// has not started (ContactState::impending), mu_kinetic after.
double sliding_mu(const ContactRows& rows, const ContactState& state);

// The friction impulse (t1, t2) that `state` applies: gamma when sticking,
// -sliding_mu lambda' slip when sliding, 0 when inactive.
Eigen::Vector2d tangent_impulse(const ContactRows& rows, const ContactState& state);

// How far a sliding contact's friction direction `slip` (unit, or zero) is
// from opposing its slip u (m/s), as a velocity: |u/|u| - slip| times the
// smaller of `friction_speed` (mu_k lambda w_t, the velocity the kinetic
// impulse removes) and |u| (the slip's sideways part). A u known to within
// epsilon gives its direction only to epsilon / |u|: at a slow slip under a
// large impulse the first alone demands more accuracy than any solve of u
// has (a soft cube settling restarted 4000 times in a step chasing it), and
// a wrong direction at a vanishing slip is a sticking contact in disguise.
double slip_direction_error(double friction_speed, const Eigen::Vector2d& u, const Eigen::Vector2d& slip);

}  // namespace recoil::sim
