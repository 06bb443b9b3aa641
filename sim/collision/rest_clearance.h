#pragma once
// The self-contact broad phase's bound on what deformation can bring close.
//
// Two primitives of one surface within the margin of each other in the rest
// shape are never a contact (collision_types.h). Every other pair starts at
// least its rest distance apart, and deformation closes that distance by at
// most the two primitives' displacements from a rigid motion of the rest
// shape: |x_a - x_b| >= |X_a - X_b| - |u_a| - |u_b| for any rotation R and
// shift t, with u = x - (R X + t). So a vertex (or edge) whose rest clearance
// (its rest distance to the nearest primitive it may contact) minus its own
// displacement and the surface's largest one exceeds the self query's radius
// has no self candidate, and the detector skips it: a body falling freely, or
// resting without deforming, searches nothing of itself; a body folding onto
// itself searches where it folds.
#include <array>
#include <vector>

#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

class EmbreeDevice;

// Rest distance (m) between a vertex and a triangle, and between two edges,
// of the rest shape `rest` (#V by 3): the quantity the self-contact rule
// compares with the margin.
double rest_distance(const Points& rest, int vertex, const std::array<int, 3>& triangle);
double rest_distance(const Points& rest, const std::array<int, 2>& e, const std::array<int, 2>& f);

// Per vertex and per edge, the rest distance to the nearest triangle (edge)
// that is not within `margin` at rest and shares no vertex (for edges), in
// metres, capped at `reach` (>= margin): a lower bound that is exact below it.
struct RestClearance {
  std::vector<double> vertex;  // #V
  std::vector<double> edge;    // #E, in the order of `edges`
};

RestClearance rest_clearance(EmbreeDevice& device, const Points& rest, const Triangles& triangles,
                             const std::vector<std::array<int, 2>>& edges, double margin, double reach);

// How far clearances are measured, m: deformation up to about this far from
// a rigid motion keeps the culling; beyond it every primitive is searched.
inline double clearance_reach(double margin) { return 4.0 * margin; }

// The least-squares rigid motion x ~ R X + t of `from` (X, #V by 3) onto
// `to` (x, #V by 3), and what is left: |x_v - (R X_v + t)| per vertex, m.
struct RigidFit {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // m
  std::vector<double> residual;                           // #V, m
};
RigidFit fit_rigid_motion(const Points& from, const Points& to);

}  // namespace recoil::sim
