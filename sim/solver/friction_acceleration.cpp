#include "sim/solver/friction_acceleration.h"

#include <Eigen/QR>
#include <cmath>
#include <numbers>

#include "core/check.h"

namespace recoil::sim {
namespace {

// Angle differences into [-pi, pi]: entries 2i+1 are angles.
void wrap_angles(Eigen::VectorXd& v) {
  for (Eigen::Index i = 1; i < v.size(); i += 2) v[i] = std::remainder(v[i], 2.0 * std::numbers::pi);
}

}  // namespace

void FrictionAcceleration::reset() {
  m_members.clear();
  m_x.clear();
  m_f.clear();
}

Eigen::VectorXd FrictionAcceleration::next(const std::vector<int>& members, const Eigen::VectorXd& x,
                                           const Eigen::VectorXd& g, const Eigen::VectorXd& weights,
                                           double mixing) {
  RECOIL_CHECK(mixing > 0.0 && mixing <= 1.0, "mixing " << mixing);
  RECOIL_CHECK(x.size() == g.size() && x.size() == weights.size() &&
               x.size() == 2 * static_cast<Eigen::Index>(members.size()));
  Eigen::VectorXd f = g - x;
  wrap_angles(f);
  const bool same = members == m_members;  // the remembered residuals are of these contacts
  const bool grew = same && !m_f.empty() && weights.cwiseProduct(f).norm() > weights.cwiseProduct(m_f.back()).norm();
  // A residual that grew after an extrapolated step discredits the pairs it
  // came from. After the damped plain step (one pair) it shows that step
  // diverging, and that pair with this one is the secant along the growth.
  if (!same || (grew && m_f.size() > 1)) reset();
  m_members = members;
  m_x.push_back(x);
  m_f.push_back(f);
  if (static_cast<int>(m_f.size()) > kDepth) {
    m_x.pop_front();
    m_f.pop_front();
  }
  const int columns = static_cast<int>(m_f.size()) - 1;
  if (columns == 0) return x + mixing * f;
  Eigen::MatrixXd dF(f.size(), columns), dX(x.size(), columns);
  for (int j = 0; j < columns; ++j) {
    Eigen::VectorXd df = m_f[static_cast<size_t>(j + 1)] - m_f[static_cast<size_t>(j)];
    wrap_angles(df);
    dF.col(j) = df;
    Eigen::VectorXd dx = m_x[static_cast<size_t>(j + 1)] - m_x[static_cast<size_t>(j)];
    wrap_angles(dx);
    dX.col(j) = dx;
  }
  // min |W (f_k - dF gamma)|: every entry a velocity.
  const Eigen::VectorXd gamma = (weights.asDiagonal() * dF).colPivHouseholderQr().solve(weights.cwiseProduct(f));
  return x + mixing * f - (dX + mixing * dF) * gamma;
}

}  // namespace recoil::sim
