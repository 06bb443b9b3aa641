#pragma once
// The normal rows one evaluation has already taken (the hold-back of
// constraint_evaluation.cpp), indexed so that a proposed row is measured
// only against the rows it can be parallel to in the P_A^-1 metric: those
// sharing a DoF node with it, and those on a body it touches whose
// rigid-motion parts alone could reach the cosine. Rows without a shared
// node couple only through P_A^-1's rigid-motion term, and by
// Cauchy-Schwarz that coupling is at most r_a r_b sqrt(w_a w_b), r being the
// share of a row's norm in that term (at most 1): below the cosine unless
// both shares are above it. Measuring every pair made an evaluation that
// proposes thousands of activations (a crushed soft body) quadratic.
#include <unordered_map>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/constraint_evaluation.h"
#include "sim/solver/contact_problem.h"
#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

class TakenNormalRows {
 public:
  // cosine: ContactPolicy::parallel; inverse_masses: per contact, effective_inverse_mass.
  TakenNormalRows(const ContactProblem& problem, const std::vector<Eigen::Vector3d>& inverse_masses,
                  const MomentumPreconditioner& P, double cosine);

  // Whether contact k's normal row has a cosine above `cosine` with a taken row.
  bool parallel_to_taken(int k);
  void take(int k);

 private:
  // Contact k's normal-row rigid motions and their share r, computed once.
  struct Modes {
    NormalRowModes modes;
    double share = -1.0;  // negative: not computed yet
  };
  const Modes& modes(int k);
  bool measure(int k, int t);  // the exact test for one pair, each pair once per proposal

  const ContactProblem& m_problem;
  const std::vector<Eigen::Vector3d>& m_inverse_masses;
  const MomentumPreconditioner& m_P;
  double m_cosine;
  std::unordered_map<int, std::vector<int>> m_by_node;  // DoF node -> taken contacts touching it
  std::unordered_map<int, std::vector<int>> m_by_body;  // body -> taken contacts with r above the cosine
  std::vector<Modes> m_modes;                           // per contact
  std::vector<int> m_measured;                          // per contact: the proposal it was last measured for
  int m_proposal = 0;
};

}  // namespace recoil::sim
