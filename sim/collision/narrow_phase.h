#pragma once
// The exact (double precision) half of collision detection, shared by the
// Embree detector and the brute-force oracle so that both define the same
// candidate set; they differ only in which pairs they offer to these tests.
//
// The candidate rule (all distances at the start of the step, x0; r is how
// far the pair's primitives move with respect to each other over the step:
// the largest |(x1 - x0)_i - (x1 - x0)_j| over a vertex i of one and j of the
// other):
// - vertex v (surface A) / triangle t (surface B), d0 and d1 their
//   distances at x0 and x1:
//     d0 <= margin + r, d1 <= margin + r and d0 + d1 <= 2 margin + r,
//   necessary conditions for the pair to come within the margin at some time
//   during the step (linear motion): any point of t is a fixed blend of its
//   vertices, so v moves by at most r with respect to it, and the distance
//   changes by at most r |s - s'| between fractions s and s' of the step, so
//   it stays above (d0 + d1 - r) / 2. A pair as far apart at the end as at
//   the start, moving past rather than towards each other (two sides of a
//   landing body squashed by the step), is thus no candidate. Bodies falling
//   together (a pile before it lands) therefore give no candidates until they
//   meet; the broad phase bounds r by |x1 - x0|(v) + |x1 - x0|(t). Pairs that
//   do meet (continuous check) always pass.
// - edge e (A) / edge f (B): the same three conditions on dist(e, f), the
//   closest points (at the impact, if the continuous check found one) lie
//   more than margin/10 from both edges' ends, and the edges are not
//   parallel to within the margin (sine of their angle times the longer
//   edge's length at least the margin), and neither edge is flat (its two
//   triangles within margin/10 of one plane, as the diagonal of a box's
//   face or a line of a jelly cube's face grid).
//   A closest point at an end is a vertex, already a vertex-triangle
//   candidate with the edge as its feature; parallel edges that overlap have
//   an end of one within the margin of the other, and that vertex holds
//   them, whereas their own closest points could be anywhere along the
//   overlap. An edge crossing a flat edge touches the plane the flat
//   edge's triangles span, and the gap along it is linear there: it is
//   smallest at its own end (a vertex-triangle candidate) or where it leaves
//   that plane across a bent edge (an edge-edge candidate), so the crossing
//   adds a row the others imply. In a stack of turned boxes these crossings
//   of face diagonals sat 1-2 mm from the crossings of the face's border
//   (normal rows with cosine 0.9999): near-duplicates that the contact
//   solver cannot tell apart.
// - a vertex of a rigid, static or kinematic closed surface whose
//   uncovered triangles are coplanar (to 1e-7 of the body's size, the
//   precision of a float mesh file; a flat vertex: inside a box face's
//   lattice or on a seam of tiles, not on a sheet's border, nor anywhere on
//   a finely faceted ball, which is flat within the margin everywhere) is
//   no candidate against another surface or a plane, by the argument for
//   flat edges: the gap from the patch to a triangle of B (or to a plane)
//   is linear over it, so it is smallest at B's vertices (against A's
//   faces), where B's edges leave the patch across bent edges, or at the
//   patch's own border, never at a vertex inside the patch. Such a pair gave the normal of B's face, not of the
//   patch: a faceted ball landing on a box's lattice vertex was pushed
//   sideways along its tilted facet, and a block sliding on a box floor was
//   held against its front face. A deformable surface's flat vertices stay
//   (its patch is flat at x0 only), as its lattice vertices carry the load
//   spread over a resting face.
// - vertex v / plane: min(signed distance at x0, at x1) <= margin (flat
//   vertices of bodies that keep their shape excepted, above).
// Self-contact takes a pair of one surface only within min(margin, rest
// distance - margin) (collision_types.h): never a pair within the margin of
// each other in the rest shape (a vertex and its own triangles, edges
// sharing a vertex, neighbours on a fine mesh, a narrow modelled gap), and a
// pair just past it only once deformation has closed a margin of its rest
// distance, not when the step's motion alone reaches it. So a body at rest
// or falling freely has no self candidates while a body that folds onto
// itself does. Nor is a pair whose lattice elements are one or share a face
// ever a self-contact (collision_types.h). Pairs of two prescribed (static or kinematic)
// surfaces, and prescribed surfaces against planes, are never tested.
// A triangle that another fixed body covers (covered_faces.h) is no
// candidate, nor is a vertex whose triangles are all covered or an edge
// beside a covered triangle, and covered triangles are left out of every
// feature's normal cone.
//
// Closest-point weights: a vertex-triangle closest point on an edge or vertex
// of the triangle has zero weights elsewhere, and one within margin/10 of an
// edge or vertex is moved onto it (the smallest weights are zeroed while
// the point moves less than that); the normal still comes from the exact
// point. The detector then reduces the candidates
// (candidate_reduction.h): one per vertex and touched feature, one per pair of
// vertices found from both sides.
//
// Between two different closed surfaces a vertex-triangle pair's normal and
// whether it is a candidate at all follow feature_cone.h: p - q where it
// lies in both features' normal cones, else the qualifying face normal
// nearest it, else no candidate; at an impact, also no candidate on a face p
// started behind, and a vertex facing none of the faces is held by one it
// started more than a margin in front of; a fallback normal of
// another face that p lies over is left to that face's own pair. The rest of this
// paragraph is the rule for every other pair, and for a closed pair whose
// triangles round a feature are all degenerate.
// Normal (from q on B to p on A): (p - q)/|p - q| while the points are apart
// (so the gap is the distance, >= 0, and open or thin surfaces work from both
// sides). At an impact found by the continuous check: the face normal
// (vertex-triangle) or the cross product of the edges (edge-edge) at the
// impact, turned towards the side p started on. When they already touch at
// the start, that side is unknown: a face normal keeps its outward sign
// (counter-clockwise triangles; A is assumed outside B), an edge cross product
// is turned against the relative motion. Between two different closed
// surfaces, an edge-edge p - q that leaves B's edge below both its
// triangles' planes while q - p leaves A's edge below both of its says the
// edges have already crossed (a ridge slipped through a flat face grid,
// which has no edge candidates, between two vertices): the normal is turned
// round, out of B, and the gap is the negative depth (pairs within the
// margin only, without an impact this step). Degenerate features
// fall back to the direction of p - q, then the reversed relative motion,
// finally +z.
// Touching at the start is ambiguous where the closest point is a triangle's
// edge or vertex (a corner resting exactly on a corner touches the top face
// and the side faces alike): there a triangle gives a candidate only if the
// vertex moves into its face (normal . relative motion < 0), so a box set
// down exactly on an equal box is held by the top face, not pushed sideways
// by a side face. The contact solver then keeps resting contacts a small
// distance apart (contact_model.h), and p - q decides from the next step on.
#include <memory>
#include <vector>

#include "sim/collision/collision_types.h"

namespace recoil::sim {

// The triangles around each vertex of a triangle list: those of vertex v are
// faces[start[v] .. start[v + 1]), in ascending order.
struct VertexFaces {
  std::vector<int> start;  // #V + 1
  std::vector<int> faces;
};
VertexFaces vertex_faces(const Triangles& triangles, int num_vertices);

// Per-surface data derived once per step: motions, edges, adjacency.
struct PreparedSurface {
  const CollisionSurface* surface = nullptr;
  int index = -1;                             // position in the detector's input
  std::vector<double> vertex_motion;          // #V, |x1 - x0|
  std::vector<double> triangle_motion;        // #F, max over its vertices
  std::vector<std::array<int, 2>> edges;      // #E, (lo, hi), sorted, unique
  std::vector<double> edge_motion;            // #E
  std::vector<std::array<int, 2>> edge_opposite;  // #E: third vertices of the edge's two triangles, the one
                                                  // running lo -> hi first (-1, -1 on a boundary,
                                                  // non-manifold or inconsistently wound edge)
  std::shared_ptr<const VertexFaces> vertex_faces;  // the triangles around each vertex
  bool closed = false;                        // every edge has both triangles, wound consistently
  const std::vector<char>* covered = nullptr;  // #F, 1 where another fixed body covers the triangle
                                               // (covered_faces.h); null: none
  double max_motion = 0.0;                    // over all vertices
  double length_scale = 0.0;                  // largest |coordinate|, for tolerances
  Aabb box0;                                  // bounding box of x0

  int num_vertices() const { return static_cast<int>(vertex_motion.size()); }
  int num_triangles() const { return static_cast<int>(triangle_motion.size()); }
  int num_edges() const { return static_cast<int>(edges.size()); }
};

// Checks shapes and indices (a mismatch is a caller bug: RECOIL_CHECK).
// `edges` and `edge_opposite`, if given (both or neither), are
// unique_edges(surface.triangles) and edge_opposites of them from an
// earlier step with the same triangles, and `faces` its vertex_faces:
// topology, computed once.
PreparedSurface prepare_surface(const CollisionSurface& surface, int index,
                                const std::vector<std::array<int, 2>>* edges = nullptr,
                                const std::vector<std::array<int, 2>>* edge_opposite = nullptr,
                                std::shared_ptr<const VertexFaces> faces = nullptr);

// The undirected edges of a triangle list as (lo, hi) vertex pairs, sorted, unique.
std::vector<std::array<int, 2>> unique_edges(const Triangles& triangles);

// For each of `edges` (unique_edges(triangles)), the third vertices of its
// two triangles: first of the triangle that runs the edge from its lower to
// its higher vertex, then of the one running it back; (-1, -1) unless
// exactly two triangles share it, one each way round.
std::vector<std::array<int, 2>> edge_opposites(const Triangles& triangles, const std::vector<std::array<int, 2>>& edges);

// A closest point this close to an edge or vertex of the triangle is taken
// to be on it (candidate_reduction.h), and a surface this close to a plane
// is flat there: as a share of the contact margin.
inline constexpr double kFeatureSnapShare = 0.1;

// Whether another fixed body covers triangle f of `s` (covered_faces.h).
inline bool is_covered(const PreparedSurface& s, int f) {
  return s.covered != nullptr && (*s.covered)[static_cast<size_t>(f)] != 0;
}

// Whether `edge` may be an edge-edge candidate: it is not flat at x0 (its
// two triangles within margin/10 of one plane) and neither of its triangles
// is covered. The broad phase may leave the others out.
bool edge_may_contact(const PreparedSurface& s, int edge, double margin);

// False when no pair of primitives of a and b can satisfy the candidate rule:
// their x0 boxes, each inflated by margin/2 + its largest motion, are apart.
bool boxes_may_interact(const PreparedSurface& a, const PreparedSurface& b, double margin);

// Whether two different surfaces are tested against each other / a surface
// against itself / a surface against planes.
bool surfaces_interact(const PreparedSurface& a, const PreparedSurface& b);
bool self_interacts(const PreparedSurface& a);
bool interacts_with_planes(const PreparedSurface& a);

// The exact tests; each returns a candidate if the pair satisfies the rule.
// For self-contact pass the same surface twice; edge_edge then needs ea < eb.
std::optional<ContactCandidate> test_vertex_triangle(const PreparedSurface& a, int vertex, const PreparedSurface& b,
                                                     int triangle, double margin);
std::optional<ContactCandidate> test_edge_edge(const PreparedSurface& a, int edge_a, const PreparedSurface& b,
                                               int edge_b, double margin);
std::optional<ContactCandidate> test_vertex_plane(const PreparedSurface& a, int vertex, const CollisionPlane& plane,
                                                  int plane_index, double margin);

}  // namespace recoil::sim
