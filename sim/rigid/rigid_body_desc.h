#pragma once
// The description a rigid body is built from (plain data with defaults), and
// the friction coefficients every body and plane carries.
#include <Eigen/Core>
#include <string>

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

// Bodies that move as a whole. `dynamic` bodies have 6 DoF (mass and inertia
// from their closed surface and density); `kinematic` ones follow a scripted
// constant velocity and angular velocity about transform.position; `fixed`
// ones (scene type "static") never move.
enum class RigidMotion { dynamic, kinematic, fixed };

struct RigidBodyDesc {
  std::string name = "rigid";
  RigidMotion motion = RigidMotion::dynamic;
  TriMesh mesh;                 // surface in local coordinates (closed for dynamic bodies)
  Transform transform;          // local -> world at time 0
  double density = 1000.0;      // kg/m^3, dynamic only
  FrictionDesc friction;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // m/s, world: initial (dynamic) or constant (kinematic)
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, world, same
  CollisionSurfaceDesc collision;  // its default edge is that of a deformable body at the default resolution
};

}  // namespace recoil::sim
