#pragma once
// Faces of fixed bodies that other fixed bodies cover: where static tiles
// abut, each tile's side face lies against its neighbour's, and the edge
// along the seam is, for the union of the two, a line across one flat top.
// Each tile is a closed surface of its own, so without this the narrow phase
// sees a wall and a corner at every seam, and a body sliding over it is
// caught by them (horizontal rows at its lower edge) and trips.
//
// A triangle of a fixed closed surface is covered by another fixed closed
// surface when all of it lies in that surface's solid: each vertex inside
// (winding number above 1/2) or within `tolerance` of it, and its centroid
// inside by more, or within `tolerance` of one of the other's faces turned
// against it (two faces pressed together; a face flush with the other's
// face and turned the same way is still outside). Planes cover by the same
// rule, with the half-space behind them as the solid: the sides of a static
// box sunk into the ground up to its top. A covered triangle is no
// contact candidate, and its normal is left out of the cones of its edges and
// vertices (narrow_phase.h). Fixed bodies never move, so this is computed once.
// A triangle only partly covered stays: covering follows the lattices, not the
// exact outline of the contact region.
#include <vector>

#include "sim/collision/collision_types.h"

namespace recoil::sim {

// Per surface, one flag per triangle (1: covered); empty for every surface
// that is not fixed and closed, or has nothing covered.
std::vector<std::vector<char>> covered_triangles(const std::vector<CollisionSurface>& surfaces,
                                                 const std::vector<CollisionPlane>& planes, double tolerance);

}  // namespace recoil::sim
