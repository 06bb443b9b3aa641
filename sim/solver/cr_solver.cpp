#include "sim/solver/cr_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/check.h"
#include "sim/solver/constraint_evaluation.h"
#include "sim/solver/cr_best_iterate.h"
#include "sim/solver/cr_hand_back.h"
#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

namespace {

// Below this |z^T B z| / (|z| |B z|) the CR recurrence has broken down.
constexpr double kBreakdown = 1e-12;
// Algorithm 1 line 21 stops when |B C^-1 r| < epsilon_1: r then lies in the
// (near) null space of B and no Krylov step can reduce it (redundant rows
// with right-hand sides consistent only to round-off). Alone, that test
// would also stop an ill-conditioned but regular system whose residual sits
// in a slow eigen-direction (|B C^-1 r| ~ lambda_min |r|, lambda_min ~ 1e-3
// for stiff FEM), so it must also be this small relative to |r|.
constexpr double kStationary = 1e-6;

class CrSolver {
 public:
  CrSolver(ContactProblem& problem, const ContactSolverSettings& settings, bool preconditioned,
           ContactLinearization* linearization, ContactSolverStats& stats)
      : m_problem(problem), m_settings(settings), m_preconditioned(preconditioned),
        m_linearization(linearization), m_stats(stats), m_n(problem.A->rows()),
        m_P(problem), m_best(problem, m_n, m_P.get()) {}

  void run(Eigen::VectorXd& dv);

 private:
  int contacts() const { return static_cast<int>(m_problem.rows.size()); }
  bool normal_on(int k) const { return m_problem.states[static_cast<size_t>(k)].mode != ContactMode::inactive; }
  bool tangent_on(int k) const { return m_problem.states[static_cast<size_t>(k)].mode == ContactMode::sticking; }
  bool row_on(int k, int r) const { return r == 0 ? normal_on(k) : tangent_on(k); }
  double row_w(int k, int r) const { return m_inverse_masses[static_cast<size_t>(k)][r]; }

  void start_from_warm_states();
  void grow_contacts();
  void refresh_rows();
  void build_rhs();
  void apply_B(const Eigen::VectorXd& x, Eigen::VectorXd& out) const;
  void apply_Cinv(const Eigen::VectorXd& x, Eigen::VectorXd& out) const;
  double scaled_square_sum(const Eigen::VectorXd& r, double stop_above, double& constraint_inf) const;
  double constraint_square_sum(const Eigen::VectorXd& r, double& constraint_inf) const;
  void note_residual_from_z();
  double residual_norm(double& constraint_inf);
  void recompute_residual();
  double rounding_floor() const;
  void update_stationary();
  void restart_true();
  void restart(KrylovStart cause);
  void start_directions();
  void restart_recurrence();
  void rescue_step();
  void restart_after_change(KrylovStart cause);
  void count_iteration();
  enum class Finish { converged, not_converged, go_on };
  Finish finish_or_continue();
  bool step();
  bool out_of_budget() const { return m_stats.iterations + m_stats.restarts >= m_settings.max_iterations; }

  ContactProblem& m_problem;
  const ContactSolverSettings& m_settings;
  bool m_preconditioned;
  ContactLinearization* m_linearization;
  ContactSolverStats& m_stats;
  int m_n;
  mutable Eigen::VectorXd m_scratch_dv, m_scratch_top;  // apply_B's (and the rounding floor's) work space, #DoF
  ProblemPreconditioner m_P;  // P_A^-1 (momentum_preconditioner.h)
  std::vector<Eigen::Vector3d> m_inverse_masses;  // per contact, effective_inverse_mass of its rows
  Eigen::VectorXd m_y, m_d, m_r, m_z, m_p, m_q, m_t, m_bz;
  // Per constraint row (3 #contacts), set with the right-hand side
  // (build_rhs), whenever states or rows change: what scaled_square_sum multiplies
  // the row by (1 when selected, its effective inverse mass w otherwise), and
  // what P_S^-1 divides it by (w when selected, 1 otherwise).
  Eigen::VectorXd m_row_scale, m_row_divisor;
  bool m_residual_norm_known = false;  // m_residual_norm / m_residual_inf describe m_r
  double m_residual_norm = 0.0, m_residual_inf = 0.0;
  double m_rho = 0.0;
  int m_since_restart = 0;
  KrylovStart m_start = KrylovStart::first_solve;  // what started the current Krylov solve
  bool m_residual_true = false;
  bool m_stationary = false;       // scaled |B C^-1 r| < epsilon_1 (Algorithm 1 line 21)
  FrictionAcceleration m_acceleration;  // Algorithm 3's pairs since the system last changed otherwise
  bool m_relinearized_ok = false;  // the last relinearize moved nothing beyond epsilon_2, and nothing changed since
  BestIterate m_best;  // handed back when the solve ends unconverged
};

void CrSolver::start_from_warm_states() {
  const int m = contacts();
  m_inverse_masses.assign(static_cast<size_t>(m), Eigen::Vector3d::Zero());
  // dv starts at zero (step 3), or where the problem says (start_dv: the
  // contact-free solution of bodies no contact touches). Starting every body
  // from the World's contact-free solution instead was measured on the
  // bunny-drop demo: 2.0x the CR iterations and 3.4x the unconverged steps,
  // because resting contacts end near dv = 0 while the free solution falls through.
  m_y = Eigen::VectorXd::Zero(m_n + 3 * m);
  if (m_problem.start_dv.size() == m_n) m_y.head(m_n) = m_problem.start_dv;
  for (int k = 0; k < m; ++k) {
    ContactState& s = m_problem.states[static_cast<size_t>(k)];
    const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
    if (rows.nodes.empty()) s = ContactState{};
    if (s.mode == ContactMode::sticking && rows.mu_static <= 0.0) {
      s.mode = ContactMode::sliding;
      s.gamma.setZero();
    }
    if (s.mode == ContactMode::sliding) {
      s.lambda_kinetic = std::max(s.lambda_kinetic, 0.0);
      s.slip = s.slip.norm() > 0.0 ? Eigen::Vector2d(s.slip.normalized()) : Eigen::Vector2d::Zero();
      // A contact whose sides are at rest is no longer slipping, so Coulomb's
      // law is static again: it starts the step sticking, warm-started with
      // the impulse its friction applied, and the cone test decides whether
      // it breaks away. Kept sliding, it would push that impulse, at the
      // cone's rim, into whatever holds it still, step after step.
      if (rows.mu_static > 0.0 && sides_at_rest(rows, m_settings.constraint_tolerance)) {
        s.gamma = tangent_impulse(rows, s);
        s.mode = ContactMode::sticking;
        s.lambda_kinetic = 0.0;
        s.slip.setZero();
        s.impending = false;
      }
    }
    if (s.mode != ContactMode::inactive) m_y[m_n + 3 * k] = s.lambda;
    if (s.mode == ContactMode::sticking) m_y.segment<2>(m_n + 3 * k + 1) = s.gamma;
  }
}

void CrSolver::grow_contacts() {
  const int m = contacts();
  RECOIL_CHECK(m_problem.states.size() == m_problem.rows.size());
  const int old = static_cast<int>(m_inverse_masses.size());
  RECOIL_CHECK(m >= old);
  m_inverse_masses.resize(static_cast<size_t>(m), Eigen::Vector3d::Zero());
  m_y.conservativeResize(m_n + 3 * m);
  m_y.tail(3 * (m - old)).setZero();
  for (int k = old; k < m; ++k) m_problem.states[static_cast<size_t>(k)] = ContactState{};
}

void CrSolver::refresh_rows() {
  for (size_t k = 0; k < m_inverse_masses.size(); ++k)
    m_inverse_masses[k] = effective_inverse_mass(m_problem.rows[k], m_P.get());
}

void CrSolver::build_rhs() {
  const int m = contacts();
  m_d.setZero(m_n + 3 * m);
  m_d.head(m_n) = m_problem.b;
  for (int k = 0; k < m; ++k) {
    const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
    const ContactState& s = m_problem.states[static_cast<size_t>(k)];
    if (s.mode == ContactMode::sliding) {
      Eigen::Vector3d f;
      f << 0.0, tangent_impulse(rows, s);
      add_rows_transpose_times(rows, f, m_d);
    }
    if (normal_on(k)) m_d[m_n + 3 * k] = -rows.rhs_normal;
    if (tangent_on(k)) m_d.segment<2>(m_n + 3 * k + 1) = -rows.rhs_tangent;
  }
  // The per-row factors follow the states here, as the right-hand side does
  // (and the residual's norm, which reads them, is stale).
  m_residual_norm_known = false;
  m_row_scale.resize(3 * m);
  m_row_divisor.resize(3 * m);
  for (int k = 0; k < m; ++k)
    for (int r = 0; r < 3; ++r) {
      const double w = row_w(k, r);
      m_row_scale[3 * k + r] = row_on(k, r) || w <= 0.0 ? 1.0 : w;
      m_row_divisor[3 * k + r] = row_on(k, r) && w > 0.0 ? w : 1.0;
    }
}

void CrSolver::apply_B(const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
  const int m = contacts();
  out.resize(m_n + 3 * m);
  // Scratch vectors reused across iterations: this runs once per CR iteration.
  Eigen::VectorXd& dv = m_scratch_dv;
  Eigen::VectorXd& top = m_scratch_top;
  dv = x.head(m_n);
  m_problem.A->multiply(dv, top);
  // An unselected row reads -f; only the selected rows touch J (most
  // candidates are inactive, and a sliding contact selects its normal only).
  for (int k = 0; k < m; ++k) {
    const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
    const int base = m_n + 3 * k;
    if (tangent_on(k)) {
      const Eigen::Vector3d f = x.segment<3>(base);
      add_rows_transpose_times(rows, -f, top);
      out.segment<3>(base) = -rows_times(rows, dv);
    } else if (normal_on(k)) {
      add_normal_row_transpose_times(rows, -x[base], top);
      out[base] = -normal_row_times(rows, dv);
      out.segment<2>(base + 1) = -x.segment<2>(base + 1);
    } else {
      out.segment<3>(base) = -x.segment<3>(base);
    }
  }
  out.head(m_n) = top;
}

// C = diag(P_A, P_S): P_A^-1 of momentum_preconditioner.h, P_S = diag(J P_A^-1 J^T)
// on selected rows, 1 on the others (whose B entry is -1).
void CrSolver::apply_Cinv(const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
  out.resize(x.size());
  if (!m_preconditioned) {
    out = x;
    return;
  }
  m_P.get().apply(x.head(m_n), out.head(m_n));
  out.tail(x.size() - m_n) = x.tail(x.size() - m_n).cwiseQuotient(m_row_divisor);
}

// The residual as velocities (m/s): momentum rows through P_A^-1, selected
// rows as they are, unselected rows (a multiplier that should be zero)
// through the row's effective inverse mass. Independent of the
// preconditioner, so cr and cr_plain stop at the same accuracy.
// Returns the sum of squares; it stops early, with a partial sum above
// `stop_above`, once the sum passes it (the sum only grows). The few
// constraint rows go first: they alone pass a stationarity bound on most
// iterations, and then P_A^-1 need not be applied at all.
double CrSolver::scaled_square_sum(const Eigen::VectorXd& r, double stop_above, double& constraint_inf) const {
  const double sum = constraint_square_sum(r, constraint_inf);
  if (sum > stop_above) return sum;
  return sum + m_P.get().applied_squared_norm(r.head(m_n), stop_above - sum);
}

// The constraint rows' part of scaled_square_sum, and their largest entry.
double CrSolver::constraint_square_sum(const Eigen::VectorXd& r, double& constraint_inf) const {
  RECOIL_CHECK(m_row_scale.size() == 3 * contacts(), "row factors out of step with the contacts");
  constraint_inf = 0.0;
  double sum = 0.0;
  for (int i = 0; i < 3 * contacts(); ++i) {
    const double v = r[m_n + i] * m_row_scale[i];
    sum += v * v;
    constraint_inf = std::max(constraint_inf, std::abs(v));
  }
  return sum;
}

// Called where z = C^-1 r has just been made to hold: explicitly after a
// restart, by the recurrence after a CR step (to rounding; every stop is
// re-checked on the explicit residual). Preconditioned, C's momentum block
// is P_A^-1, so z then holds the momentum rows of the scaled residual, and
// its norm costs no further application of P_A^-1.
void CrSolver::note_residual_from_z() {
  m_residual_norm_known = false;
  if (!m_preconditioned) return;
  m_residual_norm = std::sqrt(constraint_square_sum(m_r, m_residual_inf) + m_z.head(m_n).squaredNorm());
  m_residual_norm_known = true;
}

// The scaled residual's norm, kept until m_r changes: the iteration asks for it up to
// three times per step (restart interval, convergence and stationarity tests).
double CrSolver::residual_norm(double& constraint_inf) {
  if (!m_residual_norm_known) {
    m_residual_norm = std::sqrt(scaled_square_sum(m_r, std::numeric_limits<double>::infinity(), m_residual_inf));
    m_residual_norm_known = true;
  }
  constraint_inf = m_residual_inf;
  return m_residual_norm;
}

// r = d - B y, explicitly; y is left as it is.
void CrSolver::recompute_residual() {
  apply_B(m_y, m_r);
  m_r = m_d - m_r;
  m_residual_norm_known = false;
  m_residual_true = true;
}

// What rounding can leave in the explicit residual's momentum rows at y,
// m/s: eps (|A| |dv| + |d|) through P_A^-1; a worst case, as if every
// rounding error had the same sign (random signs give about sqrt(#nodes)
// less). A stiff body's A dv cancels terms of h^2 k |dv| down to m dv, so at
// E = 1e12 Pa and dt = 0.1 s no iterate gets below about 1e-6 m/s. For soft
// bodies it is far below epsilon_1 and changes nothing.
double CrSolver::rounding_floor() const {
  m_problem.A->multiply_magnitudes(m_y.head(m_n), m_scratch_dv);
  m_scratch_dv = std::numeric_limits<double>::epsilon() * (m_scratch_dv + m_d.head(m_n).cwiseAbs());
  return std::sqrt(m_P.get().applied_squared_norm(m_scratch_dv, std::numeric_limits<double>::infinity()));
}

void CrSolver::update_stationary() {
  double constraint_inf = 0.0;
  const double res = residual_norm(constraint_inf);
  // |B C^-1 r| below both bounds; summing stops once well past them, which
  // it is on almost every iteration (4 bound^2 leaves rounding no say).
  const double bound = std::min(m_settings.tolerance, kStationary * res);
  m_stationary = !std::isnan(res) &&
                 std::sqrt(scaled_square_sum(m_bz, 4.0 * bound * bound, constraint_inf)) < bound;
}

// Restart from the explicitly recomputed residual.
void CrSolver::restart_true() {
  recompute_residual();
  restart_recurrence();
}

// restart_true(), counted in the stats (the first start is not a restart);
// the iterate it restarts from is a candidate to hand back (cr_best_iterate.h).
void CrSolver::restart(KrylovStart cause) {
  ++m_stats.restarts;
  m_start = cause;
  ++m_stats.starts[static_cast<size_t>(cause)];
  restart_true();
  m_best.offer(m_y);
}

void CrSolver::count_iteration() {
  ++m_stats.iterations;
  ++m_stats.start_iterations[static_cast<size_t>(m_start)];
}

// Search directions from the current residual: z = C^-1 r, p = z, q = B z.
void CrSolver::start_directions() {
  apply_Cinv(m_r, m_z);
  note_residual_from_z();
  m_p = m_z;
  apply_B(m_z, m_bz);
  m_q = m_bz;
  m_rho = m_z.dot(m_bz);
  m_since_restart = 0;
  update_stationary();
}

void CrSolver::restart_recurrence() {
  start_directions();
  // A stationary residual is final (run() stops on it): z^T B z ~ 0 is then
  // expected, and a rescue step would only move y off the explicit residual,
  // so that the next recheck restarts again, to the end of the budget.
  double constraint_inf = 0.0;
  if (!m_stationary && std::abs(m_rho) <= kBreakdown * m_z.norm() * m_bz.norm() &&
      residual_norm(constraint_inf) >= m_settings.tolerance)
    rescue_step();
}

// z^T B z ~ 0 right after a restart: no progress along z is possible, so
// take one minimal-residual step along C^-1 B z, whose residual decrease
// z^T B C^-1 B z is positive, and restart the recurrence from there.
void CrSolver::rescue_step() {
  Eigen::VectorXd dir, bdir, cbdir;
  apply_Cinv(m_bz, dir);
  apply_B(dir, bdir);
  apply_Cinv(bdir, cbdir);
  const double den = bdir.dot(cbdir);
  if (!(den > 0.0)) return;
  const double alpha = m_z.dot(bdir) / den;
  m_y += alpha * dir;
  m_r -= alpha * bdir;
  m_residual_true = false;
  count_iteration();
  start_directions();
}

// The active set, the friction state or the rows changed: the right-hand
// side follows and the Krylov space restarts from the true residual. The
// iterate moves on from here, so an earlier re-linearisation no longer
// describes where it will end, and convergence needs a fresh one.
void CrSolver::restart_after_change(KrylovStart cause) {
  m_relinearized_ok = false;
  if (cause != KrylovStart::friction_update) m_acceleration.reset();
  build_rhs();
  restart(cause);
}

// One CR iteration (Algorithm 1 lines 9-21). Returns false when it had to
// restart instead.
bool CrSolver::step() {
  apply_Cinv(m_q, m_t);
  const double den = m_q.dot(m_t);
  if (!(den > 0.0)) {
    restart(KrylovStart::breakdown);
    return false;
  }
  const double alpha = m_rho / den;
  m_y += alpha * m_p;
  m_r -= alpha * m_q;
  m_z -= alpha * m_t;
  note_residual_from_z();
  m_residual_true = false;
  count_iteration();
  ++m_since_restart;
  if (alpha > 0.0) {
    double constraint_inf = 0.0;
    const double res = residual_norm(constraint_inf);
    const double decades = res > m_settings.tolerance ? std::log10(res / m_settings.tolerance) : 0.0;
    const int interval = std::max(1, static_cast<int>(std::floor(decades * decades / 2.0)));
    if (m_since_restart % interval == 0 &&
        evaluate_constraints(m_problem, m_inverse_masses, m_y, m_P.get(), m_settings, false)
                .total() > 0) {
      restart_after_change(KrylovStart::contact_switch);
      return false;
    }
  }
  apply_B(m_z, m_bz);
  update_stationary();
  const double rho = m_z.dot(m_bz);
  if (std::abs(rho) <= kBreakdown * m_z.norm() * m_bz.norm()) {
    restart(KrylovStart::breakdown);
    return false;
  }
  const double beta = rho / m_rho;
  m_rho = rho;
  m_p = m_z + beta * m_p;
  m_q = m_bz + beta * m_q;
  return true;
}

// Algorithm 1 lines 22-31 once the residual is below epsilon_1 (or
// stationary): re-check on the true residual, evaluate every constraint,
// look for new contacts, re-linearise. Done only when a re-linearisation
// moved nothing beyond epsilon_2 and the system it left was solved without
// any further change; at the re-linearisation cap the solve ends unconverged.
CrSolver::Finish CrSolver::finish_or_continue() {
  if (!m_residual_true) {
    restart(KrylovStart::recheck);
    return Finish::go_on;
  }
  const double eps2 = m_settings.constraint_tolerance;
  // An iterate that already meets every contact law to epsilon_2 (the KKT
  // residual, the measure all solvers are compared by) is a solution, and
  // goes on to the new-contact check and re-linearisation unchanged: its
  // evaluation could only propose changes of about epsilon_2, each costing a
  // restarted solve that may wander off again.
  const bool meets_laws = m_best.offer(m_y) <= eps2;
  if (!meets_laws) {
    const EvaluationChanges changes =
        evaluate_constraints(m_problem, m_inverse_masses, m_y, m_P.get(), m_settings, true, &m_acceleration);
    if (changes.total() > 0) {
      restart_after_change(changes.mode_changes > 0 ? KrylovStart::mode_change : KrylovStart::friction_update);
      return Finish::go_on;
    }
  }
  if (m_linearization == nullptr) return Finish::converged;
  const Eigen::VectorXd dv = m_y.head(m_n);
  const int added = m_linearization->add_new_contacts(dv, m_problem);
  if (added > 0) {
    m_stats.new_contacts += added;
    grow_contacts();
    refresh_rows();
    m_best.remeasure();
    restart_after_change(KrylovStart::new_contacts);
    return Finish::go_on;
  }
  if (m_relinearized_ok) return Finish::converged;
  if (m_stats.relinearizations >= m_settings.max_relinearizations) return Finish::not_converged;
  const double change = m_linearization->relinearize(dv, m_problem);
  ++m_stats.relinearizations;
  RECOIL_CHECK(m_problem.rows.size() == m_inverse_masses.size(), "relinearize must not add contacts");
  m_relinearized_ok = change <= eps2;
  // The normals and tangents may have turned even when the right-hand sides
  // barely moved: solve again on the recomputed residual before returning.
  refresh_rows();
  m_best.remeasure();
  build_rhs();
  m_acceleration.reset();
  restart(KrylovStart::relinearization);
  return Finish::go_on;
}

void CrSolver::run(Eigen::VectorXd& dv) {
  start_from_warm_states();
  refresh_rows();
  build_rhs();
  ++m_stats.starts[static_cast<size_t>(KrylovStart::first_solve)];
  restart_true();
  m_best.offer(m_y);  // the warm start
  m_stats.converged = false;
  while (!out_of_budget()) {
    double constraint_inf = 0.0;
    const double res = residual_norm(constraint_inf);
    // A recheck that finds the explicit residual above epsilon_1 while the
    // recurrence's was below it is at rounding's floor, if anywhere: only
    // then is the floor worth its product with |A|, and the solve counts
    // as converged when the residual lies within it.
    const bool below = res < m_settings.tolerance ||
                       (m_residual_true && m_start == KrylovStart::recheck && res < rounding_floor());
    const bool small = below &&
                       (!m_residual_true || constraint_inf < m_settings.constraint_tolerance);
    if (small || m_stationary) {
      const Finish finish = finish_or_continue();
      if (finish == Finish::go_on) continue;
      // A stationary residual above epsilon_1 is as near as CR gets to this
      // system (rows whose right-hand sides disagree): it ends unconverged.
      m_stats.converged = finish == Finish::converged && below;
      break;
    }
    // In exact arithmetic CR ends within as many iterations as B has rows; a
    // solve still going has lost to rounding the orthogonality that this rests
    // on (a stack of stiff cubes on all-sticking rows crawled 4800 iterations
    // on 432 rows), so it starts again from the explicit residual.
    if (step() && m_since_restart >= m_y.size()) restart(KrylovStart::past_dimension);
  }
  if (!m_stats.converged && m_best.restore_if_better(m_y)) {
    build_rhs();
    recompute_residual();
  }
  // Hand back what the iterate says, converged or not: dv, the multipliers
  // and the residual all describe the same y (no step after this point).
  if (!m_residual_true) recompute_residual();
  double constraint_inf = 0.0;
  m_stats.residual = residual_norm(constraint_inf);
  dv = m_y.head(m_n);
  hand_back_states(m_problem, m_y, m_stats);
}

}  // namespace

void solve_contacts_cr(ContactProblem& problem, const ContactSolverSettings& settings, bool preconditioned,
                       Eigen::VectorXd& dv, ContactLinearization* linearization, ContactSolverStats& stats) {
  CrSolver solver(problem, settings, preconditioned, linearization, stats);
  solver.run(dv);
}

}  // namespace recoil::sim
