#pragma once
// Anderson acceleration of Algorithm 3's fixed point: the sliding contacts'
// lambda' and slip angles, x, and what one solve with them gives, G(x) (the
// normal impulses and the isolated-contact aims). The plain iteration x <- G(x)
// converges linearly where sliding contacts are coupled through their bodies
// (a landing bunny: hundreds of solves at a contraction near 1); the
// extrapolation from the last few pairs (x, G(x)) is a secant method on all
// of them together, as GMRES is on a linear system.
#include <Eigen/Core>
#include <deque>
#include <vector>

namespace recoil::sim {

class FrictionAcceleration {
 public:
  // Pairs remembered; one more than the secant directions used.
  static constexpr int kDepth = 6;

  // The next x from x and g = G(x), both ordered by `members` (contact index
  // per entry, two entries each: lambda' in N s and the slip angle in rad).
  // `weights` (m/s per unit) make every entry a velocity, as the KKT residual
  // measures it; `mixing` in (0, 1] is the share of the residual G(x) - x a
  // step takes. A history of other members is dropped first, and so is one
  // whose residual grew after an extrapolated step; the step is then the
  // damped plain one, x + mixing (g - x). A residual grown after that plain
  // step keeps its pair: where G's slope is below 1 - 2 / mixing (-3.5 on the
  // bulging bottom face of a loaded jelly cube) the plain step diverges, and
  // starting afresh would take it again on every call.
  Eigen::VectorXd next(const std::vector<int>& members, const Eigen::VectorXd& x, const Eigen::VectorXd& g,
                       const Eigen::VectorXd& weights, double mixing);
  // Forgets every pair: the system changed (contacts on or off, modes, rows).
  void reset();

 private:
  std::vector<int> m_members;
  std::deque<Eigen::VectorXd> m_x;  // x of each remembered pair
  std::deque<Eigen::VectorXd> m_f;  // its residual G(x) - x, angles wrapped
};

}  // namespace recoil::sim
