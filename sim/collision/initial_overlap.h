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

// A vertex of one surface (at x0) that lies inside another surface (winding
// number above 1/2) or behind a plane by more than `margin`, metres: the
// deepest behind a plane, or the deepest of the first kDepthProbes vertices
// found inside a surface. `near` are the detector's candidates at x0 within
// the margin: a vertex with a vertex-triangle candidate against a surface is
// within the margin of it, so only the others have their depth measured.
// Pairs of prescribed (static or kinematic) surfaces, and prescribed surfaces
// against planes, are never reported: nothing is solved between them.
inline constexpr int kDepthProbes = 64;
std::optional<SurfaceOverlap> deepest_overlap(const std::vector<CollisionSurface>& surfaces,
                                              const std::vector<CollisionPlane>& planes,
                                              const std::vector<ContactCandidate>& near, double margin);

}  // namespace recoil::sim
