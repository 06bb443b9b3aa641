#pragma once
// The normal rows that will be on after an evaluation, indexed by DoF node,
// so that a proposed activation can be tested for linear dependence on them.
// A rigid pair has six relative DoFs, so its seventh normal row depends on
// the others; switched on, such a row makes the active rows' equalities
// inconsistent unless its right-hand side agrees with theirs, and CR's
// multipliers then grow without bound (docs/decisions/023-dependent-rows-exchange.md).
#include <optional>
#include <unordered_map>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_problem.h"
#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

// How a normal row depends on the rows that are on: row_k = sum c_t row_t
// to rounding, and what the rows' right-hand sides then leave for k.
struct NormalRowDependence {
  bool dependent = false;
  std::vector<int> contacts;        // the rows t it depends on (empty when it does not)
  std::vector<double> coefficients; // c_t, per contact above; rounding-level ones are 0
  double mismatch = 0.0;            // m/s: rhs_k - sum c_t rhs_t, how far k stays violated with every t at equality
};

class OnNormalRows {
 public:
  OnNormalRows(const ContactProblem& problem, const MomentumPreconditioner& P);

  void add(int k);
  void remove(int k);
  bool on(int k) const { return m_on[static_cast<size_t>(k)] != 0; }

  // Contact k's normal row against the on rows sharing a DoF node with it.
  // A row can also depend on rows it shares no node with, through a chain of
  // bodies (A-C, C-D, D-B for a row between A and B): those are missed, and
  // the row counts as independent.
  NormalRowDependence dependence(int k);

 private:
  const NormalRowModes& modes(int k);

  const ContactProblem& m_problem;
  const MomentumPreconditioner& m_P;
  std::unordered_map<int, std::vector<int>> m_by_node;  // DoF node -> contacts ever added touching it
  std::vector<char> m_on;                               // per contact
  std::vector<std::optional<NormalRowModes>> m_modes;   // per contact, computed once
  std::vector<int> m_seen;                              // per contact: the query it was last gathered for
  int m_query = 0;
};

}  // namespace recoil::sim
