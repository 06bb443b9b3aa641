// World::step and its stages: assemble -> collide -> solve -> integrate -> health.
#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>

#include "core/check.h"
#include "sim/collision/collision_detector.h"
#include "sim/collision/initial_overlap.h"
#include "sim/fem/assembly.h"
#include "sim/solver/contact_rows_ops.h"
#include "sim/world.h"

namespace recoil::sim {

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// True when no contact is warm-started active and every normal row holds
// at dv (J_n dv >= rhs_normal: no gap closes below zero).
bool free_solution_is_feasible(const ContactProblem& problem, const Eigen::VectorXd& dv) {
  for (size_t k = 0; k < problem.rows.size(); ++k) {
    if (problem.states[k].mode != ContactMode::inactive) return false;
    if (rows_times(problem.rows[k], dv)[0] < problem.rows[k].rhs_normal) return false;
  }
  return true;
}

}  // namespace

StepReport World::step() {
  StepReport report;
  const auto start = Clock::now();
  auto t = Clock::now();
  assemble();
  report.profile.assemble = ms_since(t);

  // The contact-free solve: the prediction the collision search uses, and
  // the step's answer when there are no candidates.
  t = Clock::now();
  m_preconditioner.emplace(momentum_preconditioner());
  const PcgResult pcg = solve_pcg(m_A, *m_preconditioner, m_b, m_dv, m_solver);
  report.profile.solve = ms_since(t);
  report.solver_iterations = pcg.iterations;
  report.solver_residual = pcg.relative_residual;
  report.solver_converged = pcg.converged;

  collide_and_solve(report);

  t = Clock::now();
  integrate();
  report.profile.integrate = ms_since(t);

  t = Clock::now();
  check_health(report);
  report.profile.health = ms_since(t);
  report.profile.total = ms_since(start);

  m_time += m_dt;
  ++m_counters.steps;
  if (!report.solver_converged) ++m_counters.solver_not_converged;
  report.step = m_counters.steps;
  report.time = m_time;
  return report;
}

void World::assemble() {
  m_A.set_zero();
  m_b = Eigen::VectorXd::Zero(m_x.size());
  for (size_t i = 0; i < m_bodies.size(); ++i)
    m_elastic[i] = assemble_body(m_bodies[i], m_x, m_v, m_dt, m_gravity, m_A, m_b);
  // Rigid bodies: A = diag(m I, I_world), b = (h m g, 0); no stiffness, no
  // gyroscopic torque (integrate() keeps the angular momentum instead).
  for (int r : m_dynamic) {
    const RigidBody& body = m_rigid[static_cast<size_t>(r)];
    const int n = body.linear_node;
    m_A.block(m_A.find(n, n)) = body.mass * Eigen::Matrix3d::Identity();
    m_A.block(m_A.find(n + 1, n + 1)) = body.world_inertia();
    m_b.segment<3>(3 * n) = m_dt * body.mass * m_gravity;
  }
  m_A.fix(m_fixed);
}

MomentumPreconditioner World::momentum_preconditioner() const {
  std::vector<RigidModeNodes> modes;
  for (const DeformableBody& body : m_bodies) {
    RigidModeNodes m;
    for (int node = body.node_offset; node < body.node_offset + body.num_nodes; ++node) {
      if (m_fixed[static_cast<size_t>(node)]) continue;
      m.nodes.push_back(node);
      m.positions.push_back(m_x.segment<3>(3 * node));
    }
    modes.push_back(std::move(m));
  }
  return MomentumPreconditioner(m_A, modes);
}

std::vector<ContactSurface> World::contact_surfaces() const {
  std::vector<ContactSurface> out;
  for (size_t i = 0; i < m_bodies.size(); ++i) {
    const DeformableBody& body = m_bodies[i];
    ContactSurface s;
    s.kind = BodyKind::deformable;
    s.mu_static = m_mu_static[i];
    s.mu_kinetic = m_mu_kinetic[i];
    s.self_contact = m_self_contact[i] != 0;
    s.rest = &body.surface.vertices;
    s.triangles = body.surface.triangles;
    s.embedding = &body.embedding;
    s.tets = &body.rest.tets;
    s.pinned = &body.pinned;
    s.node_offset = body.node_offset;
    out.push_back(std::move(s));
  }
  for (const RigidBody& body : m_rigid) {
    ContactSurface s;
    s.kind = body.kind;
    s.mu_static = body.friction.static_coefficient;
    s.mu_kinetic = body.friction.kinetic_coefficient;
    s.triangles = body.triangles;
    s.local = &body.local;
    s.pose = body.pose;
    s.velocity = body.velocity;
    s.angular_velocity = body.angular_velocity;
    s.linear_node = body.linear_node;
    out.push_back(std::move(s));
  }
  return out;
}

bool World::ran_away(const std::vector<ContactCandidate>& candidates, const std::vector<CollisionSurface>& surfaces,
                     StepReport& report) const {
  long long vertices = 0;
  for (const CollisionSurface& s : surfaces) vertices += s.x0.rows();
  if (static_cast<long long>(candidates.size()) <= kMaxCandidatesPerVertex * vertices) return false;
  // Named after the surface with the most candidates.
  std::vector<long long> per_surface(surfaces.size(), 0);
  for (const ContactCandidate& c : candidates) ++per_surface[static_cast<size_t>(c.surface_a)];
  const auto worst = std::max_element(per_surface.begin(), per_surface.end()) - per_surface.begin();
  report.status = StepStatus::runaway;
  report.body = surface_body_name(static_cast<int>(worst));
  report.contacts = static_cast<int>(candidates.size());
  return true;
}

std::vector<ContactPlane> World::contact_planes() const {
  std::vector<ContactPlane> planes;
  for (size_t i = 0; i < m_planes.size(); ++i) {
    ContactPlane p;
    p.plane.body = static_cast<int>(i);
    p.plane.point = m_planes[i].point;
    p.plane.normal = m_planes[i].normal;
    p.mu_static = m_planes[i].friction.static_coefficient;
    p.mu_kinetic = m_planes[i].friction.kinetic_coefficient;
    planes.push_back(p);
  }
  return planes;
}

std::optional<InitialOverlap> World::initial_overlap() const {
  const ContactModel model(contact_surfaces(), contact_planes(), DofState{&m_x, &m_v, m_dt}, m_contact.margin,
                           m_detector.get(), m_contact.solver.policy);
  std::vector<CollisionSurface> surfaces = model.collision_surfaces(Eigen::VectorXd::Zero(m_v.size()));
  for (CollisionSurface& s : surfaces) s.x1 = s.x0;  // where they are, not where they move
  const std::vector<CollisionPlane> planes = model.collision_planes();
  const std::optional<SurfaceOverlap> found =
      deepest_overlap(surfaces, planes, m_detector->detect(surfaces, planes), m_contact.margin);
  if (!found) return std::nullopt;
  return InitialOverlap{surface_body_name(found->surface),
                        found->inside_plane >= 0 ? m_planes[static_cast<size_t>(found->inside_plane)].name
                                                 : surface_body_name(found->inside_surface),
                        found->depth};
}

const std::string& World::surface_body_name(int s) const {
  const size_t i = static_cast<size_t>(s);
  return i < m_bodies.size() ? m_bodies[i].name : m_rigid[i - m_bodies.size()].name;
}

void World::collide_and_solve(StepReport& report) {
  // A state that is already broken is reported by the health stage; the
  // collision search needs finite positions.
  if (!m_x.allFinite() || !m_v.allFinite() || !m_dv.allFinite() ||
      !std::all_of(m_rigid.begin(), m_rigid.end(), [](const RigidBody& body) { return body.pose.finite(); })) {
    m_memory.clear();
    return;
  }
  // Without a degree of freedom (only static and kinematic bodies) a contact has nothing to act on.
  if (m_x.size() == 0) return;
  auto t = Clock::now();
  ContactModel model(contact_surfaces(), contact_planes(), DofState{&m_x, &m_v, m_dt}, m_contact.margin,
                     m_detector.get(), m_contact.solver.policy);
  const std::vector<CollisionSurface> surfaces = model.collision_surfaces(m_dv);
  const std::vector<ContactCandidate> candidates = m_detector->detect(surfaces, model.collision_planes());
  report.profile.collide = ms_since(t);
  if (candidates.empty()) {
    m_memory.clear();
    return;
  }
  if (ran_away(candidates, surfaces, report)) {
    m_memory.clear();
    return;
  }

  t = Clock::now();
  ContactProblem problem;
  problem.A = &m_A;
  problem.preconditioner = &*m_preconditioner;
  problem.b = m_b;
  // Rows linearised at the contact-free prediction (the solver itself starts
  // from dv = 0 on the bodies they touch: contact_solve_start).
  model.build(candidates, m_dv, m_memory, problem);
  report.contacts = model.num_contacts();
  if (free_solution_is_feasible(problem, m_dv)) {
    // Every candidate stays apart with the contact-free velocities and none
    // carries an impulse: that solution is the constrained optimum too.
    model.remember(problem, m_memory);
    report.max_penetration = model.max_penetration(m_dv);
    report.profile.solve += ms_since(t);
    return;
  }
  problem.start_dv = contact_solve_start(problem);
  const ContactSolverStats stats = solve_contacts(problem, m_contact.solver, m_dv, &model);
  model.remember(problem, m_memory);
  report.max_penetration = model.max_penetration(m_dv);
  const double inner_collide = model.collide_ms();
  report.profile.collide += inner_collide;
  report.profile.solve += ms_since(t) - inner_collide;

  report.active = stats.active;
  report.sticking = stats.sticking;
  report.sliding = stats.sliding;
  report.solver_iterations = stats.iterations;
  report.solver_restarts = stats.restarts;
  report.krylov_starts = stats.starts;
  report.krylov_start_iterations = stats.start_iterations;
  report.solver_residual = stats.residual;
  report.solver_kkt = stats.kkt;
  report.solver_converged = stats.converged;
}

Eigen::VectorXd World::contact_solve_start(const ContactProblem& problem) const {
  std::vector<char> touched(static_cast<size_t>(m_dv.size() / 3), 0);
  for (const ContactRows& rows : problem.rows)
    for (int node : rows.nodes) touched[static_cast<size_t>(node)] = 1;
  Eigen::VectorXd start = Eigen::VectorXd::Zero(m_dv.size());
  for (int i = 0; i < num_dynamic_bodies(); ++i) {
    const DynamicBody body = dynamic_body(i);
    const auto first = touched.begin() + body.first_node;
    if (std::find(first, first + body.num_nodes, 1) != first + body.num_nodes) continue;
    start.segment(3 * body.first_node, 3 * body.num_nodes) = m_dv.segment(3 * body.first_node, 3 * body.num_nodes);
  }
  return start;
}

void World::integrate() {
  m_v += m_dv;
  const int fem_nodes = m_bodies.empty() ? 0 : m_bodies.back().node_offset + m_bodies.back().num_nodes;
  m_x.head(3 * fem_nodes) += m_dt * m_v.head(3 * fem_nodes);
  for (RigidBody& body : m_rigid) {
    if (body.kind == BodyKind::fixed) continue;
    if (body.kind == BodyKind::kinematic) {
      body.pose = advance_pose(body.pose, body.velocity, body.angular_velocity, m_dt);
      continue;
    }
    const int n = body.linear_node;
    const Eigen::Vector3d momentum = body.world_inertia() * m_v.segment<3>(3 * n + 3);  // L = I(t) w+
    body.pose.center += m_dt * m_v.segment<3>(3 * n);
    body.pose.orientation = advance_free_rotation(body.pose.orientation, body.principal, momentum, m_dt);
    // Gyroscopic effect: keep L with the turned inertia, w = I(t+h)^-1 L.
    m_v.segment<3>(3 * n + 3) = body.world_inertia().ldlt().solve(momentum);
  }
}

}  // namespace recoil::sim
