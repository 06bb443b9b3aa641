#pragma once
// The kind of a mesh body, in a folder of its own below sim/collision so that
// collision, the rigid bodies, the World and cli/ share the one enum. Planes
// are not bodies (PlaneDesc).

namespace recoil::sim {

// deformable: FEM nodes (DeformableBodyDesc); rigid: 6 DoF, mass and inertia
// from its closed surface; kinematic: a scripted constant velocity and angular
// velocity; fixed (scene type "static"): never moves. The last three are
// RigidBodyDesc kinds.
enum class BodyKind { deformable, rigid, kinematic, fixed };

// True for kinds whose motion is prescribed (never solved for): collision
// never tests two such bodies against each other.
inline bool is_prescribed(BodyKind kind) { return kind == BodyKind::kinematic || kind == BodyKind::fixed; }

}  // namespace recoil::sim
