#include "sim/collision/feature_cone.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace recoil::sim {
namespace {

// cos 45 degrees: how squarely A's surface must face the contact's reverse.
constexpr double kFacingCosine = 0.7071067811865476;
// A direction within rounding of a cone is in it (cosine deficit).
constexpr double kInsideDeficit = 1e-12;

bool faces(const Eigen::Vector3d& n, const std::vector<Eigen::Vector3d>& cone_a) {
  return cone_cosine(-n, cone_a) >= kFacingCosine;
}
bool inside(const Eigen::Vector3d& n, const std::vector<Eigen::Vector3d>& cone) {
  return cone_cosine(n, cone) >= 1.0 - kInsideDeficit;
}

// The candidate with the largest score among those `accept` lets through.
template <typename Accept, typename Score>
std::optional<ConeNormal> best_generator(const std::vector<Eigen::Vector3d>& cone_b,
                                         const std::vector<Eigen::Vector3d>& cone_a, Accept accept, Score score) {
  std::optional<ConeNormal> best;
  double best_score = -std::numeric_limits<double>::infinity();
  const int kb = static_cast<int>(cone_b.size());
  for (int i = 0; i < kb + static_cast<int>(cone_a.size()); ++i) {
    const Eigen::Vector3d n = i < kb ? cone_b[static_cast<size_t>(i)] : Eigen::Vector3d(-cone_a[static_cast<size_t>(i - kb)]);
    if (!accept(n)) continue;
    const double s = score(n);
    if (s > best_score) {
      best_score = s;
      best = ConeNormal{n, i};
    }
  }
  return best;
}

}  // namespace

void distinct_directions(const std::vector<Eigen::Vector3d>& directions, std::vector<Eigen::Vector3d>& distinct) {
  distinct.clear();
  for (const Eigen::Vector3d& g : directions)
    if (std::none_of(distinct.begin(), distinct.end(),
                     [&](const Eigen::Vector3d& h) { return (g - h).squaredNorm() < 1e-24; }))
      distinct.push_back(g);
}

double cone_cosine(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& generators) {
  const size_t k = generators.size();
  double best = -1.0;
  for (const Eigen::Vector3d& g : generators) best = std::max(best, x.dot(g));
  // In 3D the nearest direction of the cone to x is x itself (inside the
  // cone of some three generators), or lies on the plane of two of them.
  for (size_t i = 0; i < k; ++i) {
    for (size_t j = i + 1; j < k; ++j) {
      const Eigen::Vector3d& gi = generators[i];
      const Eigen::Vector3d& gj = generators[j];
      const double c = gi.dot(gj), det = 1.0 - c * c;
      if (!(det > 1e-14)) continue;
      const double xi = x.dot(gi), xj = x.dot(gj);
      const double wi = (xi - c * xj) / det, wj = (xj - c * xi) / det;
      if (wi < 0.0 || wj < 0.0) continue;
      const Eigen::Vector3d y = wi * gi + wj * gj;
      const double length = y.norm();
      if (length > 0.0) best = std::max(best, x.dot(y) / length);
    }
  }
  if (best >= 1.0) return 1.0;
  // x = a gi + b gj + c gl with a, b, c >= 0 (Cramer's rule, by triple products).
  for (size_t i = 0; i < k; ++i)
    for (size_t j = i + 1; j < k; ++j) {
      const Eigen::Vector3d ij_normal = generators[i].cross(generators[j]);
      for (size_t l = j + 1; l < k; ++l) {
        const Eigen::Vector3d& gi = generators[i];
        const Eigen::Vector3d& gj = generators[j];
        const Eigen::Vector3d& gl = generators[l];
        const double det = ij_normal.dot(gl);
        if (!(std::abs(det) > 1e-12)) continue;
        const double a = x.dot(gj.cross(gl)) / det, b = gi.dot(x.cross(gl)) / det, c = ij_normal.dot(x) / det;
        if (a >= 0.0 && b >= 0.0 && c >= 0.0) return 1.0;
      }
    }
  return best;
}

std::optional<ConeNormal> feature_cone_normal(const Eigen::Vector3d& d, const Eigen::Vector3d& aim,
                                              const std::vector<Eigen::Vector3d>& cone_b,
                                              const std::vector<Eigen::Vector3d>& cone_a) {
  const double length = d.norm();
  if (length > 0.0) {
    const Eigen::Vector3d n = d / length;
    if (inside(n, cone_b) && inside(-n, cone_a)) return ConeNormal{n, -1};
  }
  const Eigen::Vector3d toward = length > 0.0 ? Eigen::Vector3d(d / length) : aim;
  return best_generator(
      cone_b, cone_a, [&](const Eigen::Vector3d& n) { return inside(n, cone_b) && faces(n, cone_a); },
      [&](const Eigen::Vector3d& n) { return n.dot(toward); });
}

std::optional<ConeNormal> impact_cone_normal(const Eigen::Vector3d& aim, const std::vector<Eigen::Vector3d>& cone_b,
                                             const Eigen::Vector3d& start, double margin) {
  return best_generator(
      cone_b, {}, [&](const Eigen::Vector3d& n) { return n.dot(start) > margin; },
      [&](const Eigen::Vector3d& n) { return n.dot(aim); });
}

}  // namespace recoil::sim
