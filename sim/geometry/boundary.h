#pragma once
// The boundary surface of a tet mesh: faces used by exactly one tet, wound
// counter-clockwise seen from outside, over the mesh's own node indices.
#include "sim/geometry/tet_mesh.h"

namespace recoil::sim {

// Returns a TriMesh whose vertices are ALL the tet nodes (so indices match the
// simulation's node numbering) and whose triangles are the boundary faces, in
// a deterministic order (sorted by their sorted node triple).
TriMesh boundary_surface(const TetMesh& mesh);


}  // namespace recoil::sim
