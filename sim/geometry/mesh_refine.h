#pragma once
// Splits a surface's long edges: the counterpart of simplification for a
// mesh coarser than a deformable body's lattice. A flat face of a CAD part
// or an exported box is two triangles; contact on their corners alone leaves
// the lattice cells between them unsupported, and they sag through what the
// body rests on.
#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

// A copy of `mesh` whose every edge is at most `max_edge` (m): the longest
// edge left is split at its midpoint, in both triangles that share it, until
// none is longer. Midpoints of straight edges lie on the surface, so the
// shape is exactly the input's; the result stays conforming (no T-junctions)
// and deterministic. Edges used by more than two triangles are split in all of them.
TriMesh split_long_edges(const TriMesh& mesh, double max_edge);

// The longest edge of `mesh`, m (0 for no triangles).
double longest_edge(const TriMesh& mesh);

}  // namespace recoil::sim
