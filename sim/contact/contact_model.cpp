#include "sim/contact/contact_model.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/check.h"
#include "sim/collision/candidate_reduction.h"
#include "sim/collision/collision_detector.h"
#include "sim/contact/tangent_basis.h"

namespace recoil::sim {

namespace {

bool is_plane(const ContactCandidate& c) { return c.kind == ContactKind::vertex_plane; }

// Re-expresses a 2-vector given in basis (t1o, t2o) in basis (t1n, t2n).
Eigen::Vector2d rebase(const Eigen::Vector2d& g, const Eigen::Vector3d& t1o, const Eigen::Vector3d& t2o,
                       const Eigen::Vector3d& t1n, const Eigen::Vector3d& t2n) {
  const Eigen::Vector3d w = g.x() * t1o + g.y() * t2o;
  return Eigen::Vector2d(t1n.dot(w), t2n.dot(w));
}

void rebase_state(ContactState& s, const Eigen::Vector3d& t1o, const Eigen::Vector3d& t2o, const Eigen::Vector3d& t1n,
                  const Eigen::Vector3d& t2n) {
  s.gamma = rebase(s.gamma, t1o, t2o, t1n, t2n);
  const Eigen::Vector2d slip = rebase(s.slip, t1o, t2o, t1n, t2n);
  const double norm = slip.norm();
  s.slip = norm > 0.0 ? Eigen::Vector2d(slip / norm) : Eigen::Vector2d::Zero();
}

}  // namespace

ContactState ContactMemory::recall(const CandidateKey& key, const Eigen::Vector3d& t1, const Eigen::Vector3d& t2) const {
  const auto it = m_entries.find(key);
  if (it == m_entries.end()) return ContactState{};
  ContactState s = it->second.state;
  rebase_state(s, it->second.t1, it->second.t2, t1, t2);
  return s;
}

ContactModel::ContactModel(std::vector<ContactSurface> surfaces, std::vector<ContactPlane> planes, DofState state,
                           double margin, CollisionDetector* detector, const ContactPolicy& policy)
    : m_surfaces(std::move(surfaces)), m_planes(std::move(planes)), m_state(state), m_margin(margin),
      m_rest_gap(policy.rest_gap_fraction * margin), m_detector(detector) {
  RECOIL_CHECK(state.x && state.v && state.h > 0.0);
  m_start.resize(m_surfaces.size());
  for (size_t s = 0; s < m_surfaces.size(); ++s) start_positions(m_surfaces[s], m_state, m_start[s]);
}

std::vector<CollisionSurface> ContactModel::collision_surfaces(const Eigen::VectorXd& dv) const {
  std::vector<CollisionSurface> out(m_surfaces.size());
  for (size_t s = 0; s < m_surfaces.size(); ++s) {
    out[s].body = static_cast<int>(s);
    out[s].kind = m_surfaces[s].kind;
    out[s].x0 = m_start[s];
    predicted_positions(m_surfaces[s], m_state, dv, out[s].x1);
    out[s].triangles = m_surfaces[s].triangles;
    out[s].self_contact = m_surfaces[s].self_contact;
    out[s].rest = m_surfaces[s].rest;
    if (m_surfaces[s].embedding != nullptr) {
      out[s].vertex_element = &m_surfaces[s].embedding->tet;
      out[s].elements = m_surfaces[s].tets;
    }
  }
  return out;
}

std::vector<CollisionPlane> ContactModel::collision_planes() const {
  std::vector<CollisionPlane> out;
  for (const ContactPlane& p : m_planes) out.push_back(p.plane);
  return out;
}

void ContactModel::predict(const Eigen::VectorXd& dv, Configuration& out) const {
  out.dv = dv;
  out.positions.resize(m_surfaces.size());
  for (size_t s = 0; s < m_surfaces.size(); ++s) predicted_positions(m_surfaces[s], m_state, dv, out.positions[s]);
}

Eigen::Vector3d ContactModel::point_a(const Contact& c, const std::vector<Points>& x) const {
  return c.candidate.a.evaluate(x[static_cast<size_t>(c.candidate.surface_a)]);
}

Eigen::Vector3d ContactModel::point_b(const Contact& c, const std::vector<Points>& x) const {
  if (is_plane(c.candidate)) return c.candidate.plane_point;
  return c.candidate.b.evaluate(x[static_cast<size_t>(c.candidate.surface_b)]);
}

Eigen::Vector3d ContactModel::rotated_normal(const Contact& c, const std::vector<Points>& x) const {
  const ContactCandidate& k = c.candidate;
  Eigen::Vector3d from, to;
  if (k.kind == ContactKind::vertex_plane) {
    return m_planes[static_cast<size_t>(k.surface_b)].plane.normal.normalized();
  } else if (k.kind == ContactKind::vertex_triangle) {
    const auto tri = m_surfaces[static_cast<size_t>(k.surface_b)].triangles.row(k.primitive_b);
    auto face = [&](const Points& p) {
      const Eigen::Vector3d a = p.row(tri[0]).transpose();
      return Eigen::Vector3d((p.row(tri[1]).transpose() - a).cross(p.row(tri[2]).transpose() - a));
    };
    from = face(m_start[static_cast<size_t>(k.surface_b)]);
    to = face(x[static_cast<size_t>(k.surface_b)]);
  } else {
    auto edges = [&](const std::vector<Points>& p) {
      const Points& pa = p[static_cast<size_t>(k.surface_a)];
      const Points& pb = p[static_cast<size_t>(k.surface_b)];
      const Eigen::Vector3d ea = (pa.row(k.a.vertex[1]) - pa.row(k.a.vertex[0])).transpose();
      const Eigen::Vector3d eb = (pb.row(k.b.vertex[1]) - pb.row(k.b.vertex[0])).transpose();
      return Eigen::Vector3d(ea.cross(eb));
    };
    from = edges(m_start);
    to = edges(x);
  }
  // Rotate the contact normal with the frame of its primitives; degenerate
  // frames (parallel edges, slivers) keep it.
  if (from.norm() < 1e-14 || to.norm() < 1e-14) return c.normal0;
  if (from.dot(c.normal0) < 0.0) {
    from = -from;
    to = -to;
  }
  return (Eigen::Quaterniond::FromTwoVectors(from, to) * c.normal0).normalized();
}

void ContactModel::linearize(Contact& c, const Configuration& conf, ContactRows& rows) const {
  const ContactCandidate& k = c.candidate;
  c.normal = rotated_normal(c, conf.positions);
  const TangentBasis basis = tangent_basis(c.normal);
  c.t1 = basis.t1;
  c.t2 = basis.t2;
  Eigen::Matrix3d frame;  // rows n, t1, t2
  frame.row(0) = c.normal.transpose();
  frame.row(1) = c.t1.transpose();
  frame.row(2) = c.t2.transpose();

  PointJacobian jac;
  const ContactSurface& sa = m_surfaces[static_cast<size_t>(k.surface_a)];
  point_jacobian(sa, m_state, conf.dv, conf.positions[static_cast<size_t>(k.surface_a)], k.a, 1.0, jac);
  double mu_s = sa.mu_static, mu_k = sa.mu_kinetic;
  if (is_plane(k)) {
    const ContactPlane& p = m_planes[static_cast<size_t>(k.surface_b)];
    mu_s = std::sqrt(mu_s * p.mu_static);
    mu_k = std::sqrt(mu_k * p.mu_kinetic);
  } else {
    const ContactSurface& sb = m_surfaces[static_cast<size_t>(k.surface_b)];
    point_jacobian(sb, m_state, conf.dv, conf.positions[static_cast<size_t>(k.surface_b)], k.b, -1.0, jac);
    mu_s = std::sqrt(mu_s * sb.mu_static);
    mu_k = std::sqrt(mu_k * sb.mu_kinetic);
  }
  // Sum per node in ascending node order (std::map), so self-contacts and
  // shared tet nodes give one block each.
  std::map<int, Eigen::Matrix3d> blocks;
  for (const auto& [node, m] : jac.terms) {
    auto it = blocks.try_emplace(node, Eigen::Matrix3d::Zero()).first;
    it->second += frame * m;
  }
  rows.nodes.clear();
  rows.blocks.clear();
  Eigen::Vector3d jdv = Eigen::Vector3d::Zero();
  for (const auto& [node, block] : blocks) {
    rows.nodes.push_back(node);
    rows.blocks.push_back(block);
    jdv += block * conf.dv.segment<3>(3 * node);
  }
  const Eigen::Vector3d p = point_a(c, conf.positions), q = point_b(c, conf.positions);
  const Eigen::Vector3d d = (p - point_a(c, m_start)) - (q - point_b(c, m_start));
  const double h = m_state.h;
  rows.rhs_normal = jdv[0] - (c.normal.dot(p - q) - c.rest_gap) / h;
  rows.rhs_tangent = Eigen::Vector2d(jdv[1] - c.t1.dot(d) / h, jdv[2] - c.t2.dot(d) / h);
  rows.mu_static = mu_s;
  rows.mu_kinetic = mu_k;
}

ContactModel::Contact ContactModel::make_contact(const ContactCandidate& candidate) const {
  const Eigen::Vector3d n = candidate.normal.normalized();
  Contact c{candidate, n, n, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0};
  c.rest_gap = std::clamp(candidate.gap, 0.0, m_rest_gap);
  return c;
}

void ContactModel::build(const std::vector<ContactCandidate>& candidates, const Eigen::VectorXd& dv,
                         const ContactMemory& memory, ContactProblem& problem) {
  Configuration conf;
  predict(dv, conf);
  m_contacts.clear();
  problem.rows.clear();
  problem.states.clear();
  for (const ContactCandidate& cand : candidates) {
    Contact c = make_contact(cand);
    ContactRows rows;
    linearize(c, conf, rows);
    problem.states.push_back(memory.recall(candidate_key(cand), c.t1, c.t2));
    problem.rows.push_back(std::move(rows));
    m_contacts.push_back(std::move(c));
  }
}

int ContactModel::add_new_contacts(const Eigen::VectorXd& dv, ContactProblem& problem) {
  if (!m_detector) return 0;
  // The solver often asks again at the very dv it asked last (a
  // re-linearisation that moved nothing solves to the same dv): the search
  // is a function of the positions alone, so its answer is kept.
  if (m_searched_dv.size() != dv.size() || m_searched_dv != dv) {
    const auto start = std::chrono::steady_clock::now();
    m_searched = m_detector->detect(collision_surfaces(dv), collision_planes());
    m_searched_dv = dv;
    m_collide_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  const std::vector<ContactCandidate>& found = m_searched;
  // A contact already in the problem may be found again through another
  // triangle of the same vertex: that is not a new contact (candidate_reduction.h).
  std::vector<ContactCandidate> known;
  known.reserve(m_contacts.size());
  for (const Contact& c : m_contacts) known.push_back(c.candidate);
  const std::vector<char> is_known = already_known(known, found);
  Configuration conf;
  predict(dv, conf);
  int added = 0;
  for (size_t i = 0; i < found.size(); ++i) {
    const ContactCandidate& cand = found[i];
    if (is_known[i]) continue;
    Contact c = make_contact(cand);
    ContactRows rows;
    linearize(c, conf, rows);
    // Only pairs within the margin at x* are contacts; the rest stay out.
    if (c.normal.dot(point_a(c, conf.positions) - point_b(c, conf.positions)) > m_margin) continue;
    problem.rows.push_back(std::move(rows));
    problem.states.emplace_back();
    m_contacts.push_back(std::move(c));
    ++added;
  }
  return added;
}

double ContactModel::relinearize(const Eigen::VectorXd& dv, ContactProblem& problem) {
  RECOIL_CHECK(problem.rows.size() == m_contacts.size(), "rows " << problem.rows.size() << " contacts " << m_contacts.size());
  Configuration conf;
  predict(dv, conf);
  double change = 0.0;
  for (size_t k = 0; k < m_contacts.size(); ++k) {
    Contact& c = m_contacts[k];
    ContactRows& rows = problem.rows[k];
    const double rhs_n = rows.rhs_normal;
    const Eigen::Vector2d rhs_t = rows.rhs_tangent;
    const Eigen::Vector3d t1 = c.t1, t2 = c.t2;
    linearize(c, conf, rows);
    rebase_state(problem.states[k], t1, t2, c.t1, c.t2);
    change = std::max({change, std::abs(rows.rhs_normal - rhs_n), (rows.rhs_tangent - rhs_t).cwiseAbs().maxCoeff()});
  }
  return change;
}

double ContactModel::gap(int k, const Eigen::VectorXd& dv) const {
  Configuration conf;
  predict(dv, conf);
  const Contact& c = m_contacts[static_cast<size_t>(k)];
  return c.normal.dot(point_a(c, conf.positions) - point_b(c, conf.positions));
}

Eigen::Vector3d ContactModel::displacement(int k, const Eigen::VectorXd& dv) const {
  Configuration conf;
  predict(dv, conf);
  const Contact& c = m_contacts[static_cast<size_t>(k)];
  return (point_a(c, conf.positions) - point_a(c, m_start)) - (point_b(c, conf.positions) - point_b(c, m_start));
}

double ContactModel::max_penetration(const Eigen::VectorXd& dv) const {
  Configuration conf;
  predict(dv, conf);
  double worst = 0.0;
  for (const Contact& c : m_contacts) {
    const Eigen::Vector3d n = rotated_normal(c, conf.positions);
    worst = std::max(worst, -n.dot(point_a(c, conf.positions) - point_b(c, conf.positions)));
  }
  return worst;
}

void ContactModel::remember(const ContactProblem& problem, ContactMemory& memory) const {
  memory.clear();
  for (size_t k = 0; k < m_contacts.size(); ++k)
    memory.store(candidate_key(m_contacts[k].candidate), {problem.states[k], m_contacts[k].t1, m_contacts[k].t2});
}

}  // namespace recoil::sim
