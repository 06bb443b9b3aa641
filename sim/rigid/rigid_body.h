#pragma once
// Rigid bodies at run time: the pose (centre, orientation quaternion) and
// velocities of a dynamic, kinematic or fixed body, with its surface kept in
// body coordinates. The body frame is the world frame at time 0 translated to
// the reference point: the centre of mass for dynamic bodies, the
// description's transform.position for kinematic and fixed ones (kinematic
// bodies turn about their position).
//
// A dynamic body owns two DoF nodes in the World: the
// linear velocity (A block m I) and the angular velocity (A block I_world =
// R I_body R^T). Gyroscopic term: the solve is linear in omega with I_world
// frozen at the start of the step; the body then turns freely with the
// angular momentum L = I_world(t) omega+ (advance_free_rotation) and omega is
// recomputed from it, omega = I_world(t+h)^-1 L, so a free body keeps L
// exactly (the effect of -omega x I omega over the step) and its energy
// without drift.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "sim/geometry/tri_mesh.h"
#include "sim/rigid/rigid_body_desc.h"

namespace recoil::sim {

struct RigidPose {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();              // m, world
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body -> world, unit

  bool finite() const { return center.allFinite() && orientation.coeffs().allFinite(); }
};

// A body-frame inertia tensor in its principal form: I = axes diag(moments) axes^T.
struct PrincipalInertia {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // principal axes in the body frame, as columns; a rotation
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();    // kg m^2, ascending
};
PrincipalInertia principal_inertia(const Eigen::Matrix3d& inertia);

struct RigidBody {
  std::string name;
  BodyKind kind = BodyKind::rigid;  // rigid (dynamic), kinematic or fixed
  Points local;           // #V by 3, collision surface vertices relative to the reference point, body frame
  Triangles triangles;    // #F by 3
  // The imported mesh, body frame, when the collision surface is a simplified
  // copy of it (empty otherwise: local/triangles are also what is drawn).
  Points render_local;
  Triangles render_triangles;
  std::shared_ptr<const SurfaceLook> look;  // of what is drawn (render_triangles, else triangles); null: plain
  double collision_deviation = 0.0;  // m: the outward offset of a simplified collision surface
  double mass = 0.0;                                      // kg (dynamic only)
  bool encloses_nothing = false;  // winding_solid.h: an open mesh whose mass is that of the lattice cells it crosses
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();      // kg m^2, body frame, about the centre of mass
  PrincipalInertia principal;  // of `inertia`, for the free turn (advance_free_rotation); dynamic only
  FrictionDesc friction;
  RigidPose pose;
  // Kinematic: the prescribed motion; dynamic: the initial one only (the
  // World's velocity vector holds it from then on, at linear_node).
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // m/s, world, of the reference point
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, world
  int linear_node = -1;   // dynamic: DoF node of the velocity; the angular velocity is node linear_node + 1

  Eigen::Matrix3d rotation() const { return pose.orientation.toRotationMatrix(); }
  // R I R^T, kg m^2.
  Eigen::Matrix3d world_inertia() const;
  double kinetic_energy() const;
};

// Throws bad_input naming `where` (e.g. "rigid_bodies/2") for an invalid
// description: a deformable kind, empty or non-finite mesh, a dynamic body
// with non-positive density or enclosed volume. Mass properties come from the
// mesh when it is closed, else from the lattice solid its winding number fills
// (sim/geometry/tetrahedralize.h); `margin` (m, the world's contact margin)
// sets the default collision surface; `threads` weigh an open surface's solid.
RigidBody build_rigid_body(const RigidBodyDesc& desc, EmbreeDevice& device, const std::string& where, double margin,
                           int threads = 1);

// The pose after moving for h seconds at constant velocity and angular
// velocity: c + h v, exp(h w) q (exact rotation, then re-normalised).
RigidPose advance_pose(const RigidPose& pose, const Eigen::Vector3d& velocity, const Eigen::Vector3d& angular_velocity,
                       double h);

// The orientation after h seconds of torque-free rotation with world
// angular momentum L (kg m^2/s), `inertia` the body-frame tensor: the
// symmetric splitting of the free rigid body into turns about its principal
// axes, each exact (axis 1 for h/2, 2 for h/2, 3 for h, 2, 1). It keeps L
// exactly and the kinetic energy within O(h^2) of its start, without drift,
// where one turn about the step's first angular velocity, exp(h I^-1 L),
// feeds energy into a body tumbling about its intermediate axis.
Eigen::Quaterniond advance_free_rotation(const Eigen::Quaterniond& orientation, const PrincipalInertia& inertia,
                                         const Eigen::Vector3d& L, double h);

// World positions of body-frame points `local` (#V by 3) at `pose`. out: #V by 3.
void world_points(const Points& local, const RigidPose& pose, Points& out);

// The rotation vector (angle * axis, rad) of a unit quaternion and back.
Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q);
Eigen::Quaterniond from_rotation_vector(const Eigen::Vector3d& phi);

// Left Jacobian of SO(3) at phi: d/dphi (exp(phi) r) = -[exp(phi) r]x J_l(phi).
Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& phi);

}  // namespace recoil::sim
