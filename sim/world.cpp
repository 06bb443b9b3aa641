#include "sim/world.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>

#include "core/check.h"
#include "core/error.h"
#include "sim/collision/collision_detector.h"
#include "sim/collision/embree_scene.h"
#include "sim/fem/assembly.h"

namespace recoil::sim {

namespace {

// A body's energy may grow at most this many times its reference scale above
// its initial value before the step is reported as a blow-up. Implicit Euler
// only dissipates, so any real growth is numerical trouble.
constexpr double kBlowupFactor = 10.0;

void check_friction(double static_coefficient, double kinetic_coefficient, const std::string& where) {
  if (!std::isfinite(static_coefficient) || !std::isfinite(kinetic_coefficient) || static_coefficient < 0.0 ||
      kinetic_coefficient < 0.0)
    throw bad_input(where + ": friction coefficients must be finite and >= 0");
}

}  // namespace

const char* to_string(StepStatus status) {
  switch (status) {
    case StepStatus::ok: return "ok";
    case StepStatus::nan: return "nan";
    case StepStatus::inverted: return "inverted";
    case StepStatus::energy_blowup: return "energy blow-up";
    case StepStatus::runaway: return "runaway contacts";
  }
  return "?";
}

World::World(const WorldDesc& desc)
    : m_device(std::make_unique<EmbreeDevice>()), m_dt(desc.dt), m_gravity(desc.gravity), m_solver(desc.solver),
      m_contact(desc.contact) {
  // The scene file's keys under /simulation, where they have one.
  const std::string simulation = desc.origin.where("simulation");
  if (!(desc.dt > 0.0) || !std::isfinite(desc.dt)) throw bad_input(simulation + "/dt: must be > 0");
  if (!desc.gravity.allFinite()) throw bad_input(simulation + "/gravity: must be finite");
  if (!(desc.solver.relative_tolerance > 0.0) || desc.solver.max_iterations < 1)
    throw bad_input(simulation + ": the linear solver's tolerance must be > 0 and max_iterations >= 1");
  if (!(desc.contact.margin > 0.0) || !std::isfinite(desc.contact.margin))
    throw bad_input(simulation + "/contact/margin: must be > 0");
  if (desc.contact.num_threads < 1) throw bad_input("contact num_threads (--threads) must be >= 1");
  if (!(desc.contact.solver.tolerance > 0.0) || desc.contact.solver.max_iterations < 1)
    throw bad_input(simulation + "/solver: tolerance must be > 0 and max_iterations >= 1");
  int nodes = 0;
  for (size_t i = 0; i < desc.bodies.size(); ++i) {
    const std::string where = desc.bodies[i].origin.where("bodies/" + std::to_string(i));
    check_friction(desc.bodies[i].static_friction, desc.bodies[i].kinetic_friction, where + "/friction");
    m_bodies.push_back(build_deformable_body(desc.bodies[i], *m_device, where, desc.contact.margin,
                                             desc.contact.num_threads));
    m_bodies.back().node_offset = nodes;
    nodes += m_bodies.back().num_nodes;
    m_mu_static.push_back(desc.bodies[i].static_friction);
    m_mu_kinetic.push_back(desc.bodies[i].kinetic_friction);
    m_self_contact.push_back(desc.bodies[i].self_contact);
  }
  // Contacts act only on degrees of freedom: without a deformable or dynamic
  // body nothing collides, and a fixed or kinematic mesh keeps its own surface
  // instead of paying for a simplified one.
  const bool anything_collides =
      !desc.bodies.empty() || std::any_of(desc.rigid_bodies.begin(), desc.rigid_bodies.end(),
                                          [](const RigidBodyDesc& r) { return r.kind == BodyKind::rigid; });
  for (size_t i = 0; i < desc.rigid_bodies.size(); ++i) {
    const std::string where = desc.rigid_bodies[i].origin.where("rigid_bodies/" + std::to_string(i));
    if (anything_collides) {
      m_rigid.push_back(build_rigid_body(desc.rigid_bodies[i], *m_device, where, desc.contact.margin,
                                      desc.contact.num_threads));
    } else {
      RigidBodyDesc own_surface = desc.rigid_bodies[i];
      own_surface.collision.keep_mesh = true;
      m_rigid.push_back(build_rigid_body(own_surface, *m_device, where, desc.contact.margin, desc.contact.num_threads));
    }
    if (m_rigid.back().kind == BodyKind::rigid) {
      m_rigid.back().linear_node = nodes;
      nodes += 2;
      m_dynamic.push_back(static_cast<int>(i));
    }
  }
  for (size_t i = 0; i < desc.planes.size(); ++i) {
    PlaneDesc p = desc.planes[i];
    const std::string where = p.origin.where("planes/" + std::to_string(i));
    if (!p.point.allFinite() || !p.normal.allFinite() || !(p.normal.norm() > 0.0))
      throw bad_input(where + ": point must be finite and normal non-zero");
    check_friction(p.friction.static_coefficient, p.friction.kinetic_coefficient, where + "/friction");
    p.normal.normalize();
    m_planes.push_back(std::move(p));
  }

  m_x.setZero(3 * nodes);
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
  for (int r : m_dynamic) {
    const RigidBody& body = m_rigid[static_cast<size_t>(r)];
    m_v.segment<3>(3 * body.linear_node) = body.velocity;
    m_v.segment<3>(3 * body.linear_node + 3) = body.angular_velocity;
  }
  m_A = BlockSparseMatrix(nodes, std::move(pairs));  // rigid nodes: diagonal blocks only
  for (auto& body : m_bodies) index_blocks(body, m_A);
  m_detector = std::make_unique<CollisionDetector>(CollisionSettings{m_contact.margin, m_contact.num_threads});

  m_elastic.assign(m_bodies.size(), 0.0);
  reset_energy_reference();
}

World::~World() = default;

Eigen::VectorXd World::positions() const {
  Eigen::VectorXd x = m_x;
  for (int r : m_dynamic) {
    const RigidBody& body = m_rigid[static_cast<size_t>(r)];
    x.segment<3>(3 * body.linear_node) = body.pose.center;
    x.segment<3>(3 * body.linear_node + 3) = rotation_vector(body.pose.orientation);
  }
  return x;
}

World::DynamicBody World::dynamic_body(int i) const {
  const size_t k = static_cast<size_t>(i);
  DynamicBody out;
  if (k < m_bodies.size()) {
    out.deformable = &m_bodies[k];
    out.first_node = out.deformable->node_offset;
    out.num_nodes = out.deformable->num_nodes;
  } else {
    out.rigid = &m_rigid[static_cast<size_t>(m_dynamic[k - m_bodies.size()])];
    out.first_node = out.rigid->linear_node;
    out.num_nodes = 2;
  }
  return out;
}

const std::string& World::DynamicBody::name() const { return deformable ? deformable->name : rigid->name; }

void World::reset_energy_reference() {
  const size_t count = static_cast<size_t>(num_dynamic_bodies());
  m_energy0.assign(count, 0.0);
  m_energy_scale.assign(count, 0.0);
  // The fastest surface point of any kinematic body, m/s.
  double drive = 0.0;
  for (const RigidBody& body : m_rigid)
    if (body.kind == BodyKind::kinematic)
      drive = std::max(drive, body.velocity.norm() +
                                  body.angular_velocity.norm() * body.local.rowwise().norm().maxCoeff());
  // Per body: J of kinetic and elastic energy; J that gravity releases over a fall of 10 body sizes.
  std::vector<double> held(count, 0.0), fall(count, 0.0);
  const std::vector<BodyStats> stats = this->stats();
  for (size_t i = 0; i < count; ++i) {
    const DynamicBody body = dynamic_body(static_cast<int>(i));
    const double elastic = stats[i].elastic_energy;  // J, zero for rigid bodies
    if (body.deformable) m_elastic[i] = elastic;
    const Aabb box = body.deformable ? bounding_box(body.deformable->surface) : bounding_box(body.rigid->local);
    m_energy0[i] = total_energy(static_cast<int>(i), elastic);
    held[i] = stats[i].kinetic_energy + elastic;
    fall[i] = stats[i].mass * m_gravity.norm() * 10.0 * (box.valid() ? box.extent().norm() : 1.0);
  }
  const double all = std::accumulate(held.begin(), held.end(), 0.0) + std::accumulate(fall.begin(), fall.end(), 0.0);
  for (size_t i = 0; i < count; ++i) {
    // Energy scale: its own, and what gravity can release in its fall; what
    // contact can hand it from the other bodies (struck in zero g, a body at
    // rest takes its share of the striker's); what a kinematic body can give
    // it (2 m V^2: a bounce off a surface moving at V); a floor for bodies
    // at rest in zero g.
    m_energy_scale[i] = std::abs(m_energy0[i]) + fall[i] + (all - held[i] - fall[i]) +
                        2.0 * stats[i].mass * drive * drive + stats[i].mass * 1e-6;
  }
}

void World::hold_kinematic(bool held) {
  if (held == m_kinematic_held) return;
  m_kinematic_held = held;
  size_t k = 0;
  for (RigidBody& body : m_rigid) {
    if (body.kind != BodyKind::kinematic) continue;
    if (held) {
      m_held_scripts.emplace_back(body.velocity, body.angular_velocity);
      body.velocity.setZero();
      body.angular_velocity.setZero();
    } else {
      std::tie(body.velocity, body.angular_velocity) = m_held_scripts[k++];
    }
  }
  if (!held) m_held_scripts.clear();
}

double World::total_energy(int i, double elastic) const {
  const DynamicBody dynamic = dynamic_body(i);
  if (dynamic.rigid) {
    const RigidBody& body = *dynamic.rigid;
    const Eigen::Vector3d v = m_v.segment<3>(3 * body.linear_node), w = m_v.segment<3>(3 * body.linear_node + 3);
    return 0.5 * body.mass * v.squaredNorm() + 0.5 * w.dot(body.world_inertia() * w) -
           body.mass * m_gravity.dot(body.pose.center);
  }
  const DeformableBody& body = *dynamic.deformable;
  double e = elastic;
  for (int n = 0; n < body.num_nodes; ++n) {
    const int g = body.node_offset + n;
    e += body.mass[n] * (0.5 * m_v.segment<3>(3 * g).squaredNorm() - m_gravity.dot(m_x.segment<3>(3 * g)));
  }
  return e;
}

void World::check_health(StepReport& report) {
  // Worst status wins (nan > runaway > energy blow-up > inverted); the first body found names it.
  auto severity = [](StepStatus s) {
    switch (s) {
      case StepStatus::ok: return 0;
      case StepStatus::inverted: return 1;
      case StepStatus::energy_blowup: return 2;
      case StepStatus::runaway: return 3;
      case StepStatus::nan: return 4;
    }
    return 0;
  };
  auto raise = [&](StepStatus s, const std::string& body) {
    if (severity(s) > severity(report.status)) {
      report.status = s;
      report.body = body;
    }
  };
  for (int i = 0; i < num_dynamic_bodies(); ++i) {
    const size_t k = static_cast<size_t>(i);
    const DynamicBody body = dynamic_body(i);
    const std::string& name = body.name();
    const bool finite_pose =
        body.deformable ? m_x.segment(3 * body.first_node, 3 * body.num_nodes).allFinite() : body.rigid->pose.finite();
    if (!finite_pose || !m_v.segment(3 * body.first_node, 3 * body.num_nodes).allFinite()) {
      raise(StepStatus::nan, name);
      continue;
    }
    double elastic = 0.0;
    if (body.deformable) {
      const ElasticState s = elastic_state(*body.deformable, m_x, /*with_energy=*/false);
      report.inverted_tets += s.inverted;
      if (s.inverted > 0) raise(StepStatus::inverted, name);
      // The elastic part lags one step (it comes from assembly): a blow-up
      // shows in the kinetic energy first anyway.
      elastic = m_elastic[k];
    }
    if (total_energy(i, elastic) - m_energy0[k] > kBlowupFactor * m_energy_scale[k])
      raise(StepStatus::energy_blowup, name);
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
  for (int r : m_dynamic) {
    RigidBody& body = m_rigid[static_cast<size_t>(r)];
    body.pose.center = m_x.segment<3>(3 * body.linear_node);
    body.pose.orientation = from_rotation_vector(m_x.segment<3>(3 * body.linear_node + 3));
    m_x.segment<6>(3 * body.linear_node).setZero();  // the pose is the body's alone
  }
  m_memory.clear();
  if (reset_energy_ref && positions.allFinite() && velocities.allFinite()) reset_energy_reference();
}

std::vector<BodySurface> World::surfaces() const {
  std::vector<BodySurface> out;
  for (const DeformableBody& body : m_bodies) {
    BodySurface s;
    s.name = body.name;
    Points nodes(body.num_nodes, 3);
    for (int n = 0; n < body.num_nodes; ++n) nodes.row(n) = m_x.segment<3>(3 * (body.node_offset + n)).transpose();
    const bool own_render = !body.render_surface.empty();
    embedded_positions(own_render ? body.render_embedding : body.embedding, body.rest.tets, nodes, s.positions);
    s.triangles = own_render ? body.render_surface.triangles : body.surface.triangles;
    s.look = own_render ? body.render_surface.look : body.surface.look;
    out.push_back(std::move(s));
  }
  for (const RigidBody& body : m_rigid) {
    BodySurface s;
    s.name = body.name;
    s.kind = body.kind;
    const bool own_render = body.render_triangles.rows() > 0;
    world_points(own_render ? body.render_local : body.local, body.pose, s.positions);
    s.triangles = own_render ? body.render_triangles : body.triangles;
    s.look = body.look;
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Aabb> World::body_bounds() const {
  std::vector<Aabb> out;
  Points posed;
  for (const DeformableBody& body : m_bodies) {
    Points nodes(body.num_nodes, 3);
    for (int n = 0; n < body.num_nodes; ++n) nodes.row(n) = m_x.segment<3>(3 * (body.node_offset + n)).transpose();
    embedded_positions(body.embedding, body.rest.tets, nodes, posed);
    out.push_back(bounding_box(posed));
  }
  for (const RigidBody& body : m_rigid) {
    world_points(body.local, body.pose, posed);
    out.push_back(bounding_box(posed));
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
  for (int r : m_dynamic) {
    const RigidBody& body = m_rigid[static_cast<size_t>(r)];
    BodyStats s;
    s.name = body.name;
    s.num_nodes = 2;
    s.mass = body.mass;
    s.center_of_mass = body.pose.center;
    const Eigen::Vector3d v = m_v.segment<3>(3 * body.linear_node), w = m_v.segment<3>(3 * body.linear_node + 3);
    s.momentum = body.mass * v;
    s.kinetic_energy = 0.5 * body.mass * v.squaredNorm() + 0.5 * w.dot(body.world_inertia() * w);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace recoil::sim
