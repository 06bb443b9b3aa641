#pragma once
// ContactModel: the step's contacts as the solver's rows. Built from the collision candidates of one step; implements the
// solver's call-backs (new contacts at the predicted positions,
// re-linearisation at x* = x + h (v + dv) with the contact weights held).
//
// Per contact k between point p (side A) and q (side B, or a plane) with
// unit normal n from q to p, everything evaluated at the predicted
// configuration for the current dv with the candidate's weights held:
//   gap g*        = n.(p* - q*)
//   displacement  d* = (p* - p0) - (q* - q0)   (relative, over the step)
//   J_n h = d g / d dv, J_t h = d (t.d) / d dv  (n, t held)
//   rhs_normal    = J_n dv - (g* - g_rest)/h   so J_n dv' >= rhs  <=>  g(dv') >= g_rest to first order
//   rhs_tangent   = J_t dv - t.d*/h            so sticking means no relative tangential motion
// Resting distance g_rest = clamp(g0, 0, rest_gap_fraction * margin) (ContactPolicy), with g0
// the candidate's gap at the start of the step: contacts that approach stop a
// share of the margin apart (a tenth by default) instead of exactly touching. At zero distance the
// next step cannot tell a vertex resting on a corner from one beside it (the
// top and side faces both contain the corner), and a stack of boxes then
// falls through itself; a small positive distance keeps p - q meaningful. A
// pair that is already closer keeps its gap (no push apart, no energy
// injected), and a penetrating pair is pushed back to zero, as before.
// The normal follows the contact: it is rotated with the triangle (vertex-
// triangle) or the pair of edges (edge-edge) from the start of the step to
// x*; a plane's normal is fixed. Tangents come from tangent_basis(n).
#include <Eigen/Core>
#include <map>
#include <vector>

#include "sim/collision/collision_types.h"
#include "sim/contact/contact_surface.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

class CollisionDetector;

struct ContactPlane {
  CollisionPlane plane;
  double mu_static = 0.5, mu_kinetic = 0.5;
};

// Each contact's state at the end of a step with its tangent basis, keyed by
// candidate identity: the warm start of the next step.
class ContactMemory {
 public:
  struct Entry {
    ContactState state;
    Eigen::Vector3d t1 = Eigen::Vector3d::Zero(), t2 = Eigen::Vector3d::Zero();
  };
  void clear() { m_entries.clear(); }
  void store(const CandidateKey& key, const Entry& entry) { m_entries[key] = entry; }
  // The remembered state re-expressed in the basis (t1, t2); inactive when unknown.
  ContactState recall(const CandidateKey& key, const Eigen::Vector3d& t1, const Eigen::Vector3d& t2) const;
  size_t size() const { return m_entries.size(); }

 private:
  std::map<CandidateKey, Entry> m_entries;
};

class ContactModel final : public ContactLinearization {
 public:
  // surfaces: one per collision surface, in the detector's order; planes in
  // the candidates' plane order. `detector` (may be null) re-runs the search
  // for add_new_contacts; `margin` in m; `policy` gives the rest gap.
  ContactModel(std::vector<ContactSurface> surfaces, std::vector<ContactPlane> planes, DofState state, double margin,
               CollisionDetector* detector, const ContactPolicy& policy);

  // The detector's input for the step x0 -> predicted(dv).
  std::vector<CollisionSurface> collision_surfaces(const Eigen::VectorXd& dv) const;
  std::vector<CollisionPlane> collision_planes() const;

  // Replaces problem.rows/states with one contact per candidate, linearised
  // at dv (usually zero), warm-started from `memory`.
  void build(const std::vector<ContactCandidate>& candidates, const Eigen::VectorXd& dv, const ContactMemory& memory,
             ContactProblem& problem);

  int add_new_contacts(const Eigen::VectorXd& dv, ContactProblem& problem) override;
  double relinearize(const Eigen::VectorXd& dv, ContactProblem& problem) override;

  // Largest penetration max(0, -g*) over the contacts at the end of the step
  // with velocity change dv, m.
  double max_penetration(const Eigen::VectorXd& dv) const;
  // Stores every contact's final state and basis into `memory` (cleared first).
  void remember(const ContactProblem& problem, ContactMemory& memory) const;

  int num_contacts() const { return static_cast<int>(m_contacts.size()); }
  const ContactCandidate& candidate(int k) const { return m_contacts[static_cast<size_t>(k)].candidate; }
  const Eigen::Vector3d& normal(int k) const { return m_contacts[static_cast<size_t>(k)].normal; }
  // Gap g* and relative displacement d* of contact k at the end of the step for dv,
  // with the contact's current normal and held weights.
  double gap(int k, const Eigen::VectorXd& dv) const;
  Eigen::Vector3d displacement(int k, const Eigen::VectorXd& dv) const;
  // Milliseconds spent in the detector inside add_new_contacts.
  double collide_ms() const { return m_collide_ms; }

 private:
  struct Contact {
    ContactCandidate candidate;
    Eigen::Vector3d normal0;   // the candidate's normal (start of the step / time of impact)
    Eigen::Vector3d normal;    // at the last linearisation
    Eigen::Vector3d t1, t2;
    double rest_gap = 0.0;     // g_rest above, m
  };
  Contact make_contact(const ContactCandidate& candidate) const;
  struct Configuration {       // predicted positions of every surface for one dv
    Eigen::VectorXd dv;
    std::vector<Points> positions;
  };

  void predict(const Eigen::VectorXd& dv, Configuration& out) const;
  Eigen::Vector3d point_a(const Contact& c, const std::vector<Points>& x) const;
  Eigen::Vector3d point_b(const Contact& c, const std::vector<Points>& x) const;
  Eigen::Vector3d rotated_normal(const Contact& c, const std::vector<Points>& x) const;
  // Recomputes c's normal and basis and fills `rows` at configuration `conf`.
  void linearize(Contact& c, const Configuration& conf, ContactRows& rows) const;

  std::vector<ContactSurface> m_surfaces;
  std::vector<ContactPlane> m_planes;
  DofState m_state;
  double m_margin;
  double m_rest_gap;  // the largest resting distance, m
  CollisionDetector* m_detector;
  std::vector<Points> m_start;  // per surface: positions at the start of the step
  std::vector<Contact> m_contacts;
  double m_collide_ms = 0.0;
  Eigen::VectorXd m_searched_dv;               // the dv of the last search in add_new_contacts
  std::vector<ContactCandidate> m_searched;    // what it found
};

}  // namespace recoil::sim
