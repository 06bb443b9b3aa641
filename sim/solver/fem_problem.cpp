#include "sim/solver/fem_problem.h"

#include <cstdio>

#include "sim/collision/embree_scene.h"
#include "sim/fem/assembly.h"
#include "sim/fem/deformable_body.h"
#include "sim/geometry/primitives.h"

namespace recoil::sim {

OwnedProblem fem_block_on_ground(const FemBlockParams& params) {
  DeformableBodyDesc desc;
  desc.name = "fem_block";
  desc.mesh = make_box(Eigen::Vector3d::Constant(params.size), 1);
  desc.resolution = params.resolution;
  desc.material.youngs_modulus = params.youngs_modulus;
  desc.material.density = params.density;
  desc.transform.position = Eigen::Vector3d(0.0, 0.0, 0.5 * params.size);  // bottom face on z = 0
  EmbreeDevice device;
  DeformableBody body = build_deformable_body(desc, device, "fem_block_on_ground", /*margin=*/0.002);
  body.node_offset = 0;
  const int nodes = body.num_nodes;
  Eigen::VectorXd x(3 * nodes), v(3 * nodes);
  double z_min = body.rest.nodes.col(2).minCoeff();
  for (int n = 0; n < nodes; ++n) {
    x.segment<3>(3 * n) = body.rest.nodes.row(n).transpose();
    v.segment<3>(3 * n) = Eigen::Vector3d(params.drift, 0.0, 0.0);
  }
  OwnedProblem out;
  out.A = std::make_unique<BlockSparseMatrix>(nodes, block_pairs(body));
  index_blocks(body, *out.A);
  out.problem.b = Eigen::VectorXd::Zero(3 * nodes);
  assemble_body(body, x, v, params.h, Eigen::Vector3d(0.0, 0.0, -9.81), *out.A, out.problem.b);
  out.problem.A = out.A.get();
  const Eigen::Matrix3d frame = contact_frame(Eigen::Vector3d::UnitZ());
  const double touching = 1e-9 * params.size;
  for (int n = 0; n < nodes; ++n) {
    if (x[3 * n + 2] > z_min + touching) continue;
    // Gap 0 and no normal velocity: rhs_normal = 0; the rows read the
    // end-of-step tangential velocity.
    add_contact(out.problem, {n}, {1.0}, Eigen::Vector3d::UnitZ(), 0.0, params.mu, params.mu);
    out.problem.rows.back().rhs_tangent = -(frame.bottomRows<2>() * v.segment<3>(3 * n));
  }
  return out;
}

std::string describe(const FemBlockParams& params) {
  char text[96];
  std::snprintf(text, sizeof(text), "res %d, E %.0e, drift %.1f", params.resolution, params.youngs_modulus,
                params.drift);
  return text;
}

}  // namespace recoil::sim
