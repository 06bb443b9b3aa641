#pragma once
// The constraint rows that will be on after an evaluation (every active
// contact's normal row, and a sticking one's two tangent rows too), indexed
// by DoF node, so that a row about to come on (an activation's normal row, a
// contact about to stick's tangent rows) can be tested for linear dependence
// on them. A rigid pair has six relative DoFs, so its
// seventh row depends on the others, and so does a row of a coarse lattice
// cell whose nodes the on rows already fix; switched on, such a row makes the
// on rows' equalities inconsistent unless its right-hand side agrees with
// theirs, and CR's multipliers then grow without bound or the row cycles on
// and off (docs/decisions/023-dependent-rows-exchange.md).
#include <optional>
#include <unordered_map>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// How a row depends on the rows that are on: row_k = sum c_t row_t to
// rounding, and what the rows' right-hand sides then leave for k.
struct RowDependence {
  bool dependent = false;
  std::vector<int> contacts;                  // the contacts whose on rows it depends on (empty when it does not)
  std::vector<Eigen::Vector3d> coefficients;  // per contact above, c of its (normal, t1, t2) rows; 0 for rows
                                              // not on and rounding-level ones
  double mismatch = 0.0;  // m/s: rhs_k - sum c_t rhs_t, how far k stays violated with every t at equality
};

class OnRows {
 public:
  OnRows(const ContactProblem& problem, const MomentumPreconditioner& P);

  // Contact k's normal row is on, and its tangent rows with it when `sticking`.
  void add(int k, bool sticking);
  void remove(int k);
  bool on(int k) const { return m_on[static_cast<size_t>(k)] != Off; }

  // Contact k's row `row` (0 normal, 1-2 tangents) against the on rows of
  // the contacts sharing a DoF node with it, its own rows from `row` on left
  // out. A row can also depend on rows it shares no node with, through a
  // chain of bodies (A-C, C-D, D-B for a row between A and B): those are
  // missed, and the row counts as independent.
  RowDependence dependence(int k, int row = 0);

 private:
  enum Mode : char { Off, Normal, NormalAndTangents };
  // A contact's rows in coordinates where the dot product is the P_A^-1
  // one: per DoF node J_i L_i, per deformable body (J Z_b) L_b, with
  // L L^T the node's D^-1 and the body's (Z_b^T A Z_b)^-1.
  struct WhitenedRows {
    std::vector<int> nodes;
    std::vector<Eigen::Matrix3d> blocks;  // per node
    std::vector<int> bodies;
    std::vector<MomentumPreconditioner::ModeBlock> modes;  // per body
  };
  const WhitenedRows& whitened(int k);
  double right_hand_side(int k, int row) const;

  const ContactProblem& m_problem;
  const MomentumPreconditioner& m_P;
  std::unordered_map<int, std::vector<int>> m_by_node;  // DoF node -> contacts ever added touching it
  std::vector<Mode> m_on;                               // per contact
  std::vector<std::optional<WhitenedRows>> m_whitened;  // per contact, computed once
  std::vector<int> m_seen;                              // per contact: the query it was last gathered for
  int m_query = 0;
};

}  // namespace recoil::sim
