#pragma once
// How the vertices of one collision surface move with the World's DoFs
//: an embedded surface vertex of a deformable body is
// sum_k w_k x_k over its tet's 4 nodes; a rigid body's vertex is
// c + R r_local, moving with v + w x r; kinematic and fixed bodies move on
// their own (no DoFs). The contact code only sees these maps, not bodies.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "sim/collision/collision_types.h"
#include "sim/geometry/embedding.h"
#include "sim/rigid/rigid_body.h"

namespace recoil::sim {

struct ContactSurface {
  BodyKind kind = BodyKind::deformable;
  double mu_static = 0.5, mu_kinetic = 0.5;
  bool self_contact = false;
  const Points* rest = nullptr;  // #V by 3, rest shape for the self-contact rule (collision_types.h)
  Triangles triangles;  // #F by 3
  // Deformable: the embedding of the surface in the body's tets, whose local
  // node numbers start at node_offset in the DoF layout.
  const Embedding* embedding = nullptr;
  const Tets* tets = nullptr;
  const std::vector<char>* pinned = nullptr;  // per body node
  int node_offset = 0;
  // Rigid, kinematic, fixed: body-frame vertices (#V by 3) and the pose at
  // the start of the step. Dynamic bodies take v, w from the DoF vectors at
  // linear_node, linear_node + 1; kinematic ones move with these constants.
  const Points* local = nullptr;
  RigidPose pose;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  int linear_node = -1;

  int num_vertices() const;
};

// The motion of one point of a surface, linearised at a configuration:
// displacement over the step = h * (sum_i terms[i].second * (v + dv)[node i])
// for DoF parts, plus the prescribed part already contained in the positions.
struct PointJacobian {
  std::vector<std::pair<int, Eigen::Matrix3d>> terms;  // (DoF node, 3x3 map), pinned nodes left out
};

// The step's configuration of the DoFs: positions x, velocities v (3 per
// node), time step h. Surfaces evaluate "predicted" positions for a given dv
// as the integrator will: x + h (v + dv) for nodes, the exact pose update for
// rigid bodies, the scripted pose for kinematic ones.
struct DofState {
  const Eigen::VectorXd* x = nullptr;
  const Eigen::VectorXd* v = nullptr;
  double h = 0.0;
};

// Surface positions (#V by 3) at the start of the step.
void start_positions(const ContactSurface& s, const DofState& state, Points& out);
// Surface positions (#V by 3) at the end of the step with velocity change dv.
void predicted_positions(const ContactSurface& s, const DofState& state, const Eigen::VectorXd& dv, Points& out);
// The pose of a rigid surface at the end of the step with velocity change dv.
RigidPose predicted_pose(const ContactSurface& s, const DofState& state, const Eigen::VectorXd& dv);

// Jacobian of the end-of-step position of point `point` of surface s with
// respect to h * dv, at the predicted configuration for dv (positions
// `predicted` of that surface, #V by 3), appended to `out` scaled by `sign`.
void point_jacobian(const ContactSurface& s, const DofState& state, const Eigen::VectorXd& dv, const Points& predicted,
                    const SurfacePoint& point, double sign, PointJacobian& out);

}  // namespace recoil::sim
