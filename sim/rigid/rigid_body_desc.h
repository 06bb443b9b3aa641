#pragma once
// The description a rigid body is built from (plain data with defaults), and
// the friction coefficients every body and plane carries.
#include <Eigen/Core>
#include <string>

#include "sim/body/body_kind.h"
#include "sim/body/desc_origin.h"
#include "sim/collision/collision_proxy.h"
#include "sim/geometry/transform.h"
#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

// A scene's `friction`: the coefficient between two bodies is the geometric
// mean of theirs (static with static, kinetic with kinetic).
struct FrictionDesc {
  double static_coefficient = 0.5;
  double kinetic_coefficient = 0.5;
};

// A body that moves as a whole. A `rigid` one is dynamic: 6 DoF, mass and
// inertia from its density and the solid its surface bounds (closed or not); a `kinematic` one follows a
// scripted constant velocity and angular velocity about transform.position; a
// `fixed` one (scene type "static") never moves.
struct RigidBodyDesc {
  std::string name = "rigid";
  DescOrigin origin;
  BodyKind kind = BodyKind::rigid;  // rigid, kinematic or fixed; never deformable
  TriMesh mesh;                 // surface in local coordinates
  Transform transform;          // local -> world at time 0
  double density = 1000.0;      // kg/m^3, dynamic only
  FrictionDesc friction;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // m/s, world: initial (dynamic) or constant (kinematic)
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, world, same
  CollisionSurfaceDesc collision;  // its default edge is that of a deformable body at the default resolution
};

}  // namespace recoil::sim
