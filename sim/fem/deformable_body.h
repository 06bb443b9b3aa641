#pragma once
// A deformable body: its description (plain data with defaults, Box2D style)
// and the runtime model built from it: rest elements, lumped masses, pinned
// nodes and the embedded render/contact surface. Node positions and
// velocities live in the World's global DoF vectors (3 per node); the body
// owns the node range [node_offset, node_offset + num_nodes).
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sim/body/desc_origin.h"
#include "sim/collision/collision_proxy.h"
#include "sim/fem/element.h"
#include "sim/fem/material.h"
#include "sim/geometry/embedding.h"
#include "sim/geometry/tet_mesh.h"
#include "sim/geometry/tetrahedralize.h"
#include "sim/geometry/transform.h"

namespace recoil::sim {

class EmbreeDevice;

// A world-space box at the start; nodes inside (inclusive) are held fixed.
struct PinBox {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
};

struct DeformableBodyDesc {
  std::string name = "body";
  DescOrigin origin;
  TriMesh mesh;          // surface in local coordinates; may be empty when tets are given
  TetMesh tets;          // conforming tets in local coordinates; empty: tetrahedralize `mesh`
  int resolution = kDefaultResolution;  // lattice cells along the longest side when tetrahedralizing
  Material material;
  Transform transform;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s, initial, every node
  std::optional<PinBox> pinned;
  // Contact (consumed by the World's contact stage).
  double static_friction = 0.5;   // see FrictionDesc in sim/rigid/rigid_body_desc.h
  double kinetic_friction = 0.5;
  bool self_contact = true;
  CollisionSurfaceDesc collision;
};

struct DeformableBody {
  std::string name;
  int node_offset = 0;   // first node in the world's DoF layout
  int num_nodes = 0;
  TetMesh rest;          // world-space rest shape (after the initial transform), local node numbers
  std::vector<ElementRest> elements;
  Material material;
  Lame lame;
  // Stiffness-proportional damping D = beta K, s: beta = 2 zeta / omega_1 gives
  // the lowest mode omega_1 the ratio zeta (mode i gets zeta omega_i / omega_1).
  double damping_beta = 0.0;
  double lowest_frequency = 0.0;  // omega_1, rad/s; computed only for a damped body
  Eigen::VectorXd mass;          // #nodes lumped masses, kg
  std::vector<char> pinned;      // #nodes
  double surface_volume = 0.0;   // m^3 enclosed by the surface (mass = density * this)
  bool encloses_nothing = false;  // winding_solid.h: an open mesh whose mass is that of the lattice cells it crosses
  TriMesh surface;               // rest collision surface (what contact sees)
  Embedding embedding;           // its vertices in the tets
  // The imported mesh when the collision surface is a simplified copy of it
  // (empty otherwise: `surface` is also what is drawn), embedded in the same
  // tets so that it follows the simulation exactly.
  TriMesh render_surface;
  Embedding render_embedding;
  double collision_deviation = 0.0;  // m: the outward offset of a simplified collision surface
  std::vector<std::array<int, 16>> block_index;  // per tet: storage index of block (a, b) at 4a+b
};

// Builds the body (tetrahedralizing through `device` when needed). Throws
// bad_input naming `where` for invalid descriptions. Initial positions are
// the rest nodes; the caller copies them into the global vectors.
// `margin` (m) is the world's contact margin, for the default collision surface;
// `threads` weigh an open surface's solid (winding_solid.h).
DeformableBody build_deformable_body(const DeformableBodyDesc& desc, EmbreeDevice& device, const std::string& where,
                                     double margin, int threads = 1);

}  // namespace recoil::sim
