#pragma once
// Contact reduction: the last stage of collision detection, shared by the
// Embree detector and the brute-force oracle. The exact tests of
// narrow_phase.h report every primitive pair in reach; several of them often
// describe one physical contact, and the solver must not see them as
// separate constraints. Nearly equal rows with slightly different
// right-hand sides make the saddle system of the contact solve nearly
// singular and inconsistent: the active set then cycles between them and the
// solve never converges (two jelly cubes resting face to face with matching
// grids gave 107 vertex-triangle rows for 16 pairs of touching vertices,
// clusters of six rows with normals within 1.5 degrees, and the solve hit its
// iteration cap every step; reduced, 16 rows and 150-500 iterations).
//
// The rules, applied in this order:
// - one per vertex and feature: of the vertex-triangle candidates of one
//   vertex of A against surface B that touch the same feature of B (a
//   vertex, an edge or a triangle's interior: the vertices with a non-zero
//   closest-point weight), the strongest is kept (earliest impact, then
//   smallest gap, then lowest triangle id), and another only if its normal
//   is more than acos(kDistinctNormalCos) from every kept one (a corner
//   touching a corner may be held by a top face and by a side face);
// - one per pair of vertices: a vertex of A at a vertex w of B is found
//   again from w's side, as w against a triangle of A at the first vertex,
//   with the opposite normal. Only the one with the earlier impact (then the
//   smaller (surface, vertex) of side A) is kept;
// - the result is sorted with candidate_less.
// "At a vertex" and "on an edge" are decided by the exact tests, which snap
// a closest point lying within a tenth of the margin of a triangle's edge or
// vertex onto it (narrow_phase.h); they also leave out edge-edge pairs whose
// closest point is that close to an edge's end, and nearly parallel edges.
#include <vector>

#include "sim/collision/collision_types.h"

namespace recoil::sim {

// Two candidates of one vertex are distinct directions when their normals'
// cosine is below this (about 26 degrees apart).
inline constexpr double kDistinctNormalCos = 0.9;

void finalize_candidates(std::vector<ContactCandidate>& candidates);

// For each candidate of `found`, whether one of `known` already describes
// that contact: the same vertex against the same surface in a similar
// direction (whatever the feature: a looser test than rule 1, since that
// vertex is already held that way), the same pair of vertices seen from the
// other side, or the same pair of primitives. What the contact solver's
// mid-solve search for new collisions must not add a second time.
std::vector<char> already_known(const std::vector<ContactCandidate>& known, const std::vector<ContactCandidate>& found);

}  // namespace recoil::sim
