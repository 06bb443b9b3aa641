#pragma once
// The contact solver's view of one time step: the
// unconstrained implicit-Euler system A dv = b and, per contact, a block of
// three constraint rows. The solver sees matrices and rows, never bodies;
// sim/contact builds the rows from collision candidates (embedding weights
// for deformable bodies, v + w x r for rigid ones) and re-linearises them.
//
// Conventions (every part of the code relies on them):
// - DoFs come in nodes of 3: a deformable node's velocity, or a rigid body's
//   linear velocity node and angular velocity node (A holds m I and the
//   world inertia tensor as their 3x3 diagonal blocks).
// - Contact k's rows J_k (3 by #DoF): row 0 is the normal (J_n dv grows the
//   gap), rows 1-2 the tangents t1, t2 of an orthonormal basis.
// - Non-penetration: J_n dv >= rhs_normal, multiplier lambda >= 0.
// - Sticking: J_t dv = rhs_tangent, multiplier gamma in R^2, valid while
//   |gamma| <= mu_static * lambda.
// - Sliding: no tangent rows; a known impulse -mu * lambda' * slip enters
//   the right-hand side, with `slip` the unit direction of the tangential
//   slip J_t dv - rhs_tangent and mu = mu_static while the slip has not
//   started (ContactState::impending), mu_kinetic once it has.
// - The impulses applied to the DoFs: A dv = b + sum_k J_k^T f_k with
//   f_k = [lambda, gamma] (sticking) or [lambda, -mu lambda' slip]
//   (sliding), f_k = 0 when inactive.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "sim/fem/block_sparse.h"
#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_policy.h"

namespace recoil::sim {

// One contact's three rows restricted to the DoF nodes it touches:
// J_k dv = sum_i blocks[i] * dv.segment<3>(3 * nodes[i]).
struct ContactRows {
  std::vector<int> nodes;                 // DoF nodes, ascending, unique; fixed (pinned) nodes left out
  std::vector<Eigen::Matrix3d> blocks;    // one per node: row 0 normal, rows 1-2 tangent coefficients
  double rhs_normal = 0.0;                // m/s: J_n dv >= rhs_normal
  Eigen::Vector2d rhs_tangent = Eigen::Vector2d::Zero();  // m/s: J_t dv = rhs_tangent while sticking
  double mu_static = 0.5;
  double mu_kinetic = 0.5;
};

enum class ContactMode : std::uint8_t { inactive, sticking, sliding };

// Multipliers and friction state of one contact; carried from step to step
// by the caller for the warm start (step 3).
struct ContactState {
  ContactMode mode = ContactMode::inactive;
  double lambda = 0.0;                                 // normal impulse, N s, >= 0
  Eigen::Vector2d gamma = Eigen::Vector2d::Zero();     // sticking impulse in (t1, t2), N s
  double lambda_kinetic = 0.0;                         // lambda', N s: what sliding friction is based on
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();      // unit slip direction in (t1, t2); friction opposes it
  // Sliding only: broken away from sticking, with no slip yet (u below
  // epsilon_2). Its friction is the static limit, mu_static lambda': kinetic
  // friction acts on a contact that slips, so one whose neighbours still
  // hold it keeps the static share of the load. A step that begins with its
  // sides still at rest starts it sticking again (cr_solver.cpp).
  bool impending = false;
};

struct ContactProblem {
  const BlockSparseMatrix* A = nullptr;  // #DoF by #DoF, SPD; fixed nodes are identity rows with b = 0
  // P_A^-1 of A (momentum_preconditioner.h) with the deformable bodies'
  // rigid modes; null: the solvers use block Jacobi alone.
  const MomentumPreconditioner* preconditioner = nullptr;
  Eigen::VectorXd b;                     // #DoF
  std::vector<ContactRows> rows;         // one per contact
  std::vector<ContactState> states;      // same size as rows: in, the warm start; out, the solution
  // #DoF, or empty (zero): where cr's and cr_plain's dv starts. Zero suits a
  // body in contact (resting contacts end near dv = 0); a body no row
  // touches starts at its contact-free solution, which answers it exactly,
  // so that it is no part of the Krylov solve's residual at all (one solve
  // runs for every body, and a stiff one far from any contact kept a
  // pushed crate's solve from converging).
  Eigen::VectorXd start_dv;
};

enum class SolverMethod { cr, cr_plain, pgs };
const char* to_string(SolverMethod method);

struct ContactSolverSettings {
  SolverMethod method = SolverMethod::cr;
  double tolerance = 1e-6;   // epsilon_1 on the (preconditioned) residual; cr/cr_plain: the 2-norm of
                             // the residual scaled to m/s (momentum rows by P_A^-1, multiplier rows by
                             // diag(J P_A^-1 J^T)); pgs: the largest impulse change per sweep, in m/s
  int max_iterations = 5000; // cap over the whole solve, restarts included
  // Added with the solvers (sim/solver/constraint_evaluation.h):
  double constraint_tolerance = 1e-6;  // epsilon_2, m/s: smallest accepted change of a contact, and
                                       // the bound on each constraint row's residual at convergence
  int max_relinearizations = 16;       // relinearize calls per solve
  ContactPolicy policy;                // what cr's evaluations add to Algorithms 2 and 3
};

// What started each Krylov solve of `cr` / `cr_plain` (where the
// iterations go). Every accepted change of the system throws the Krylov
// space away, and the iterations that follow re-solve from the true
// residual: first_solve is the start, the others are restarts.
enum class KrylovStart {
  first_solve,      // the step's first solve, from the warm start
  contact_switch,   // a mid-solve evaluation switched contacts on or off
  mode_change,      // a converged evaluation changed some contact's mode (on/off, sticking/sliding)
  friction_update,  // a converged evaluation only moved sliding impulses (lambda', slip direction)
  new_contacts,     // the new-collision check added rows
  relinearization,  // the rows were recomputed at the predicted positions
  recheck,          // the recurrence's residual was below tolerance (or stationary): recomputed explicitly
  breakdown,        // the CR recurrence broke down
  past_dimension,   // one Krylov solve ran as many iterations as the system has rows
};
inline constexpr int kKrylovStarts = 9;
static_assert(static_cast<int>(KrylovStart::past_dimension) + 1 == kKrylovStarts, "one count per KrylovStart");
const char* to_string(KrylovStart start);

struct ContactSolverStats {
  int iterations = 0;
  int restarts = 0;            // CR restarts, every cause (`starts` below tells them apart)
  int relinearizations = 0;
  int new_contacts = 0;        // added by the mid-solve new-collision check
  double residual = 0.0;       // final true residual |d - B y|, same units as the tolerance
  bool converged = true;       // false: the iteration cap was hit
  int active = 0;              // active contacts at the end
  int sticking = 0;
  int sliding = 0;
  double ms = 0.0;             // wall-clock
  // Added with the solvers: the common accuracy measure (sim/solver/kkt_residual.h), m/s.
  double kkt = 0.0;
  // (cr and cr_plain only) Krylov solves started per
  // cause, and the iterations each cause's solves took (until the next start).
  std::array<int, kKrylovStarts> starts{}, start_iterations{};
};

// What the solver calls back, once converged, for Algorithm 1's outer loop:
// implemented by sim/contact for the World. Both functions may change the
// rows (never the node layout), so the solver recomputes its residual after.
class ContactLinearization {
 public:
  virtual ~ContactLinearization() = default;
  // Appends rows and inactive states for candidates that come into contact
  // at the predicted positions x* = x + h (v + dv) and are not in `problem`
  // yet. Returns how many were added.
  virtual int add_new_contacts(const Eigen::VectorXd& dv, ContactProblem& problem) = 0;
  // Recomputes every contact's normal, tangents, rows and right-hand sides
  // at x*, holding the contact weights. Returns the
  // largest change of any right-hand side, m/s.
  virtual double relinearize(const Eigen::VectorXd& dv, ContactProblem& problem) = 0;
};

// Solves the step's mixed complementarity problem for dv (#DoF, resized).
// `linearization` may be null (a fixed set of rows, as in the solver tests).
ContactSolverStats solve_contacts(ContactProblem& problem, const ContactSolverSettings& settings,
                                  Eigen::VectorXd& dv, ContactLinearization* linearization = nullptr);

}  // namespace recoil::sim
