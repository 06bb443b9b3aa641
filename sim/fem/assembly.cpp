#include "sim/fem/assembly.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <limits>

#include "core/check.h"

namespace recoil::sim {

std::vector<std::pair<int, int>> block_pairs(const DeformableBody& body) {
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(static_cast<size_t>(body.rest.num_tets()) * 16);
  for (int t = 0; t < body.rest.num_tets(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c)
        pairs.emplace_back(body.node_offset + body.rest.tets(t, a), body.node_offset + body.rest.tets(t, c));
  return pairs;
}

void index_blocks(DeformableBody& body, const BlockSparseMatrix& A) {
  body.block_index.resize(static_cast<size_t>(body.rest.num_tets()));
  for (int t = 0; t < body.rest.num_tets(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c) {
        const int k = A.find(body.node_offset + body.rest.tets(t, a), body.node_offset + body.rest.tets(t, c));
        RECOIL_CHECK(k >= 0, "block missing for tet " << t);
        body.block_index[static_cast<size_t>(t)][static_cast<size_t>(4 * a + c)] = k;
      }
}

Vector12d gather(const DeformableBody& body, int t, const Eigen::VectorXd& global) {
  Vector12d out;
  for (int k = 0; k < 4; ++k) out.segment<3>(3 * k) = global.segment<3>(3 * (body.node_offset + body.rest.tets(t, k)));
  return out;
}

double assemble_body(const DeformableBody& body, const Eigen::VectorXd& x, const Eigen::VectorXd& v, double h,
                     const Eigen::Vector3d& gravity, BlockSparseMatrix& A, Eigen::VectorXd& b) {
  RECOIL_CHECK(body.block_index.size() == static_cast<size_t>(body.rest.num_tets()));
  const double beta = body.damping_beta;
  const double k_scale = h * beta + h * h;
  double energy = 0.0;
  for (int t = 0; t < body.rest.num_tets(); ++t) {
    const ElementEval e = evaluate_element(body.material.model, body.lame, body.elements[static_cast<size_t>(t)],
                                           gather(body, t, x), /*want_hessian=*/true, /*project=*/true);
    energy += e.energy;
    const Vector12d rhs = -h * e.gradient - h * (beta + h) * (e.hessian * gather(body, t, v));
    const auto& idx = body.block_index[static_cast<size_t>(t)];
    for (int a = 0; a < 4; ++a) {
      const int node = body.node_offset + body.rest.tets(t, a);
      b.segment<3>(3 * node) += rhs.segment<3>(3 * a);
      for (int c = 0; c < 4; ++c) A.block(idx[static_cast<size_t>(4 * a + c)]) += k_scale * e.hessian.block<3, 3>(3 * a, 3 * c);
    }
  }
  for (int i = 0; i < body.num_nodes; ++i) {
    const int node = body.node_offset + i;
    const double m = body.mass[i];
    A.block(A.find(node, node)).diagonal().array() += m;
    b.segment<3>(3 * node) += h * m * gravity;
    if (body.pinned[static_cast<size_t>(i)]) b.segment<3>(3 * node).setZero();
  }
  return energy;
}

ElasticState elastic_state(const DeformableBody& body, const Eigen::VectorXd& x, bool with_energy) {
  ElasticState s;
  s.min_volume_ratio = body.rest.num_tets() > 0 ? std::numeric_limits<double>::infinity() : 1.0;
  for (int t = 0; t < body.rest.num_tets(); ++t) {
    const ElementRest& rest = body.elements[static_cast<size_t>(t)];
    const Vector12d xe = gather(body, t, x);
    if (with_energy) s.energy += evaluate_element(body.material.model, body.lame, rest, xe, false, false).energy;
    const double ratio = deformation_gradient(rest, xe).determinant();
    s.min_volume_ratio = std::min(s.min_volume_ratio, ratio);
    if (!(ratio > 0.0)) ++s.inverted;
  }
  return s;
}

}  // namespace recoil::sim
