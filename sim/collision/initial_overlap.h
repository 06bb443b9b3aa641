#pragma once
// Bodies that start inside one another: the contact model only resolves
// penetrations within its margin, so a scene whose bodies overlap deeper than
// that at the start is a set-up error to report, not a state to simulate.
#include <optional>
#include <vector>

#include "sim/collision/collision_types.h"

namespace recoil::sim {

struct SurfaceOverlap {
  int surface = -1;        // the surface with a vertex inside something
  int inside_surface = -1; // the surface that vertex is inside, or -1 for a plane
  int inside_plane = -1;   // the plane it is behind, or -1
  double depth = 0.0;      // m, the vertex's distance to that surface or plane
};

// The deepest vertex of one surface (at x0) that lies inside another surface
// (winding number above 1/2) or behind a plane by more than `margin`, metres.
// Pairs of prescribed (static or kinematic) surfaces, and prescribed surfaces
// against planes, are never reported: nothing is solved between them.
std::optional<SurfaceOverlap> deepest_overlap(const std::vector<CollisionSurface>& surfaces,
                                              const std::vector<CollisionPlane>& planes, double margin);

}  // namespace recoil::sim
