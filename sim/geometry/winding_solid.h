#pragma once
// The solid an open surface bounds, weighed by the lattice's own inside rule
// (|winding number| > 1/2, tetrahedralize.h) on a grid much finer than the
// simulation's: a closed surface's enclosed volume is exact, but an open one's
// signed volume counts each hole as the cone from wherever it is summed, and
// the simulation lattice is too coarse to weigh a body thinner than its cells
// (a figure's limbs and torso).
#include <Eigen/Core>
#include <vector>

#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

// Cells along the surface's longest side when weighing its solid: a limb a
// twentieth of the figure's height is three cells across.
inline constexpr int kWeighingResolution = 64;

struct WindingSolid {
  double cell = 0.0;                     // m, side of a grid cell
  std::vector<Eigen::Vector3d> centers;  // m, centres of the cells inside, in grid order (x fastest)
  double volume() const { return static_cast<double>(centers.size()) * cell * cell * cell; }  // m^3
};

// surface: #V by 3 / #F by 3, any winding, open or closed. No cell inside
// (an empty solid) means the surface encloses nothing: a sheet, parts thinner
// than a cell everywhere, or a surface flat along an axis. Deterministic:
// the same cells, in the same order, for any number of `threads` (>= 1),
// which is how many run the grid (a batch of several items gives each a
// share of the cores).
WindingSolid winding_solid(const TriMesh& surface, int resolution = kWeighingResolution, int threads = 1);

}  // namespace recoil::sim
