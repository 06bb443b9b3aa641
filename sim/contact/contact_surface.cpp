#include "sim/contact/contact_surface.h"

#include "core/check.h"
#include "sim/geometry/skew.h"

namespace recoil::sim {

namespace {

void embedded(const ContactSurface& s, const Eigen::VectorXd& nodes_global, Points& out) {
  const Embedding& e = *s.embedding;
  out.resize(e.tet.size(), 3);
  for (Eigen::Index i = 0; i < e.tet.size(); ++i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) {
      const int node = s.node_offset + (*s.tets)(e.tet[i], k);
      p += e.weights(i, k) * nodes_global.segment<3>(3 * node);
    }
    out.row(i) = p.transpose();
  }
}

}  // namespace

int ContactSurface::num_vertices() const {
  if (kind == BodyKind::deformable) return static_cast<int>(embedding->tet.size());
  return static_cast<int>(local->rows());
}

void start_positions(const ContactSurface& s, const DofState& state, Points& out) {
  if (s.kind == BodyKind::deformable) {
    embedded(s, *state.x, out);
  } else {
    world_points(*s.local, s.pose, out);
  }
}

RigidPose predicted_pose(const ContactSurface& s, const DofState& state, const Eigen::VectorXd& dv) {
  switch (s.kind) {
    case BodyKind::rigid: {
      const int n = s.linear_node;
      const Eigen::Vector3d v = state.v->segment<3>(3 * n) + dv.segment<3>(3 * n);
      const Eigen::Vector3d w = state.v->segment<3>(3 * n + 3) + dv.segment<3>(3 * n + 3);
      return advance_pose(s.pose, v, w, state.h);
    }
    case BodyKind::kinematic: return advance_pose(s.pose, s.velocity, s.angular_velocity, state.h);
    case BodyKind::fixed: return s.pose;
    case BodyKind::deformable: break;
  }
  RECOIL_CHECK(false, "predicted_pose of a deformable surface");
  return s.pose;
}

void predicted_positions(const ContactSurface& s, const DofState& state, const Eigen::VectorXd& dv, Points& out) {
  if (s.kind == BodyKind::deformable) {
    const Eigen::VectorXd nodes = *state.x + state.h * (*state.v + dv);
    embedded(s, nodes, out);
  } else {
    world_points(*s.local, predicted_pose(s, state, dv), out);
  }
}

void point_jacobian(const ContactSurface& s, const DofState& state, const Eigen::VectorXd& dv, const Points& predicted,
                    const SurfacePoint& point, double sign, PointJacobian& out) {
  if (s.kind == BodyKind::deformable) {
    const Embedding& e = *s.embedding;
    for (int j = 0; j < point.count; ++j) {
      const int vertex = point.vertex[static_cast<size_t>(j)];
      for (int k = 0; k < 4; ++k) {
        const int local = (*s.tets)(e.tet[vertex], k);
        if ((*s.pinned)[static_cast<size_t>(local)]) continue;
        const double c = sign * point.weight[static_cast<size_t>(j)] * e.weights(vertex, k);
        out.terms.emplace_back(s.node_offset + local, c * Eigen::Matrix3d::Identity());
      }
    }
    return;
  }
  if (s.kind != BodyKind::rigid) return;  // prescribed motion: no DoFs
  // p* = c + h v+ + exp(h w+) R r_local: d p*/d(h v) = I and
  // d p*/d(h w) = -[r*]x J_l(h w+), r* = p* - c* (held weights).
  const RigidPose pose = predicted_pose(s, state, dv);
  const Eigen::Vector3d r = point.evaluate(predicted) - pose.center;
  const int n = s.linear_node;
  const Eigen::Vector3d w = state.v->segment<3>(3 * n + 3) + dv.segment<3>(3 * n + 3);
  out.terms.emplace_back(n, sign * Eigen::Matrix3d::Identity());
  out.terms.emplace_back(n + 1, -sign * skew(r) * so3_left_jacobian(state.h * w));
}

}  // namespace recoil::sim
