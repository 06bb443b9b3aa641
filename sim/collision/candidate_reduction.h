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
// - no point beyond a closer face of a prescribed surface: a vertex-
//   triangle candidate against a kinematic or fixed surface whose closest
//   point on its triangle is an edge or a vertex of it (the vertex lies
//   outside the triangle's prism) is dropped when a triangle sharing that
//   edge or vertex is closer to the same vertex by more than
//   kCloserFaceTolerance (and met no later). The vertex is then over that
//   face, which gives the contact; the dropped row's normal p - q runs
//   along the surface, not across it, and with its weights held for the
//   step (contact_model.h) it is a wall through a fixed point of the edge,
//   moving as the surface's script says, whatever impulse it takes. A block
//   squeezed between counter-rotating faceted rollers had each corner
//   vertex held by 3-4 of these besides the facet it touched, normals all
//   round the vertex: the facet edges pushed it along like gear teeth
//   whatever the friction, a normal impulse grew by 0.1 N s per solve
//   without bound, and 8 of the block's first 21 steps between the rollers
//   ended at the iteration cap (1 now, as with pgs). Between two dynamic
//   bodies the walls are kept for now: there they push both bodies and act
//   as extra friction, and the rigid box stack stands with CR only with them (its
//   sticking face contacts are redundant, and without the walls CR breaks
//   them away where pgs holds all 28: 0.29 m of drift in 5 s);
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
// How much closer (m) a face must be to rule out a vertex's candidate at an
// edge or vertex beside it. Far below any real difference: a face closer
// by less than a tenth of the margin along the surface snaps the closest
// point onto the shared edge (narrow_phase.h), so the two touch the same
// feature and rule 1 decides between them.
inline constexpr double kCloserFaceTolerance = 1e-9;

// `surfaces`: the detector's input, which the candidates' surface indices name.
void finalize_candidates(std::vector<ContactCandidate>& candidates, const std::vector<CollisionSurface>& surfaces);

// For each candidate of `found`, whether one of `known` already describes
// that contact: the same vertex against the same surface in a similar
// direction (whatever the feature: a looser test than rule 1, since that
// vertex is already held that way), the same pair of vertices seen from the
// other side, or the same pair of primitives. What the contact solver's
// mid-solve search for new collisions must not add a second time.
std::vector<char> already_known(const std::vector<ContactCandidate>& known, const std::vector<ContactCandidate>& found);

}  // namespace recoil::sim
