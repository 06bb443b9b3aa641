#include "sim/world.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/check.h"
#include "core/error.h"
#include "sim/collision/embree_scene.h"
#include "sim/fem/assembly.h"

namespace recoil::sim {

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A body's energy may grow at most this many times its reference scale above
// its initial value before the step is reported as a blow-up. Implicit Euler
// only dissipates, so any real growth is numerical trouble.
constexpr double kBlowupFactor = 10.0;

}  // namespace

const char* to_string(StepStatus status) {
  switch (status) {
    case StepStatus::ok: return "ok";
    case StepStatus::nan: return "nan";
    case StepStatus::inverted: return "inverted";
    case StepStatus::energy_blowup: return "energy blow-up";
  }
  return "?";
}

World::World(const WorldDesc& desc)
    : m_device(std::make_unique<EmbreeDevice>()), m_dt(desc.dt), m_gravity(desc.gravity), m_solver(desc.solver) {
  if (!(desc.dt > 0.0) || !std::isfinite(desc.dt)) throw bad_input("simulation/dt: must be > 0");
  if (!desc.gravity.allFinite()) throw bad_input("simulation/gravity: must be finite");
  if (!(desc.solver.relative_tolerance > 0.0) || desc.solver.max_iterations < 1)
    throw bad_input("simulation/solver: tolerance must be > 0 and max_iterations >= 1");
  int nodes = 0;
  for (size_t i = 0; i < desc.bodies.size(); ++i) {
    m_bodies.push_back(build_deformable_body(desc.bodies[i], *m_device, "bodies/" + std::to_string(i)));
    m_bodies.back().node_offset = nodes;
    nodes += m_bodies.back().num_nodes;
  }
  m_x.resize(3 * nodes);
  m_v.resize(3 * nodes);
  m_fixed.assign(static_cast<size_t>(nodes), 0);
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < m_bodies.size(); ++i) {
    const DeformableBody& body = m_bodies[i];
    for (int n = 0; n < body.num_nodes; ++n) {
      const int g = body.node_offset + n;
      m_x.segment<3>(3 * g) = body.rest.nodes.row(n).transpose();
      const bool pinned = body.pinned[static_cast<size_t>(n)] != 0;
      m_v.segment<3>(3 * g) = pinned ? Eigen::Vector3d::Zero() : desc.bodies[i].velocity;
      m_fixed[static_cast<size_t>(g)] = pinned;
    }
    const auto p = block_pairs(body);
    pairs.insert(pairs.end(), p.begin(), p.end());
  }
  m_A = BlockSparseMatrix(nodes, std::move(pairs));
  for (auto& body : m_bodies) index_blocks(body, m_A);

  m_elastic.assign(m_bodies.size(), 0.0);
  reset_energy_reference();
}

void World::reset_energy_reference() {
  m_energy0.assign(m_bodies.size(), 0.0);
  m_energy_scale.assign(m_bodies.size(), 0.0);
  for (size_t i = 0; i < m_bodies.size(); ++i) {
    const ElasticState s = elastic_state(m_bodies[i], m_x, /*with_energy=*/true);
    m_elastic[i] = s.energy;
    m_energy0[i] = total_energy(static_cast<int>(i), s.energy);
    const Aabb box = bounding_box(m_bodies[i].surface);
    const double size = box.valid() ? box.extent().norm() : 1.0;
    // Energy scale: initial kinetic + elastic, plus what gravity can release
    // over a fall of 10 body sizes, plus a floor for bodies at rest in zero g.
    m_energy_scale[i] = std::abs(m_energy0[i]) + m_bodies[i].mass.sum() * m_gravity.norm() * 10.0 * size +
                        m_bodies[i].mass.sum() * 1e-6;
  }
}

World::~World() = default;

StepReport World::step() {
  StepReport report;
  const auto start = Clock::now();
  auto t = Clock::now();
  assemble();
  report.profile.assemble = ms_since(t);

  t = Clock::now();
  const PcgResult pcg = solve();
  report.profile.solve = ms_since(t);
  report.solver_iterations = pcg.iterations;
  report.solver_residual = pcg.relative_residual;
  report.solver_converged = pcg.converged;

  t = Clock::now();
  integrate();
  report.profile.integrate = ms_since(t);

  t = Clock::now();
  check_health(report);
  report.profile.health = ms_since(t);
  report.profile.total = ms_since(start);

  m_time += m_dt;
  ++m_counters.steps;
  if (!pcg.converged) ++m_counters.solver_not_converged;
  report.step = m_counters.steps;
  report.time = m_time;
  return report;
}

void World::assemble() {
  m_A.set_zero();
  m_b = Eigen::VectorXd::Zero(m_x.size());
  for (size_t i = 0; i < m_bodies.size(); ++i)
    m_elastic[i] = assemble_body(m_bodies[i], m_x, m_v, m_dt, m_gravity, m_A, m_b);
  m_A.fix(m_fixed);
}

PcgResult World::solve() { return solve_pcg(m_A, m_b, m_dv, m_solver); }

void World::integrate() {
  m_v += m_dv;
  m_x += m_dt * m_v;
}

double World::total_energy(int i, double elastic) const {
  const DeformableBody& body = m_bodies[static_cast<size_t>(i)];
  double e = elastic;
  for (int n = 0; n < body.num_nodes; ++n) {
    const int g = body.node_offset + n;
    e += body.mass[n] * (0.5 * m_v.segment<3>(3 * g).squaredNorm() - m_gravity.dot(m_x.segment<3>(3 * g)));
  }
  return e;
}

void World::check_health(StepReport& report) {
  // Worst status wins (nan > energy blow-up > inverted); the first body found names it.
  auto severity = [](StepStatus s) {
    switch (s) {
      case StepStatus::ok: return 0;
      case StepStatus::inverted: return 1;
      case StepStatus::energy_blowup: return 2;
      case StepStatus::nan: return 3;
    }
    return 0;
  };
  auto raise = [&](StepStatus s, const std::string& body) {
    if (severity(s) > severity(report.status)) {
      report.status = s;
      report.body = body;
    }
  };
  for (size_t i = 0; i < m_bodies.size(); ++i) {
    const DeformableBody& body = m_bodies[i];
    const auto xs = m_x.segment(3 * body.node_offset, 3 * body.num_nodes);
    const auto vs = m_v.segment(3 * body.node_offset, 3 * body.num_nodes);
    if (!xs.allFinite() || !vs.allFinite()) {
      raise(StepStatus::nan, body.name);
      continue;
    }
    const ElasticState s = elastic_state(body, m_x, /*with_energy=*/false);
    report.inverted_tets += s.inverted;
    if (s.inverted > 0) raise(StepStatus::inverted, body.name);
    // The elastic part lags one step (it comes from assembly): a blow-up shows
    // in the kinetic energy first anyway.
    if (total_energy(static_cast<int>(i), m_elastic[i]) - m_energy0[i] > kBlowupFactor * m_energy_scale[i])
      raise(StepStatus::energy_blowup, body.name);
  }
  if (report.status == StepStatus::nan) ++m_counters.nan_steps;
  if (report.status == StepStatus::energy_blowup) ++m_counters.energy_blowup_steps;
  if (report.inverted_tets > 0) ++m_counters.inverted_steps;
}

void World::set_state(const Eigen::VectorXd& positions, const Eigen::VectorXd& velocities,
                      bool reset_energy_ref) {
  RECOIL_CHECK(positions.size() == m_x.size() && velocities.size() == m_v.size());
  m_x = positions;
  m_v = velocities;
  if (reset_energy_ref && positions.allFinite() && velocities.allFinite()) reset_energy_reference();
}

std::vector<BodySurface> World::surfaces() const {
  std::vector<BodySurface> out;
  for (const DeformableBody& body : m_bodies) {
    BodySurface s;
    s.name = body.name;
    Points nodes(body.num_nodes, 3);
    for (int n = 0; n < body.num_nodes; ++n) nodes.row(n) = m_x.segment<3>(3 * (body.node_offset + n)).transpose();
    embedded_positions(body.embedding, body.rest.tets, nodes, s.positions);
    s.triangles = body.surface.triangles;
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<BodyStats> World::stats() const {
  std::vector<BodyStats> out;
  for (size_t i = 0; i < m_bodies.size(); ++i) {
    const DeformableBody& body = m_bodies[i];
    BodyStats s;
    s.name = body.name;
    s.num_nodes = body.num_nodes;
    s.num_tets = body.rest.num_tets();
    for (int n = 0; n < body.num_nodes; ++n) {
      const int g = body.node_offset + n;
      const double m = body.mass[n];
      s.mass += m;
      s.center_of_mass += m * m_x.segment<3>(3 * g);
      s.momentum += m * m_v.segment<3>(3 * g);
      s.kinetic_energy += 0.5 * m * m_v.segment<3>(3 * g).squaredNorm();
    }
    if (s.mass > 0.0) s.center_of_mass /= s.mass;
    const ElasticState e = elastic_state(body, m_x, /*with_energy=*/true);
    s.elastic_energy = e.energy;
    s.min_volume_ratio = e.min_volume_ratio;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace recoil::sim
