#pragma once
// The collision surface of a body: for a mesh finer than the simulation
// needs, a simplified copy (sim/geometry/mesh_simplify.h) pushed outward,
// each part by its own measured deviation, so that the original (the render surface) stays
// inside what contact sees and never visibly sinks into the ground or into
// another body. A deformable body's surface also has no edge longer than its
// tets' longest (sim/geometry/mesh_refine.h): contact on a coarse mesh's
// corners alone leaves the cells between them to sag through the ground.
// A mesh within both bounds is its own collision surface.
#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

class EmbreeDevice;

// What a body's scene description asks of its collision surface.
struct CollisionSurfaceDesc {
  int max_triangles = 0;     // > 0: at most this many triangles
  double edge_length = 0.0;  // m, > 0: as many as a tiling at this edge length needs
  bool keep_mesh = false;    // the mesh itself, however fine
  // None of these: default_collision_edge.
};

// The triangle budget the description gives `mesh` (0: keep the mesh) for a
// body whose tet-lattice cells are `cell` metres across, with contact margin
// `margin` (m).
int collision_budget(const CollisionSurfaceDesc& desc, const TriMesh& mesh, double cell, double margin);

struct CollisionProxy {
  TriMesh surface;         // what contact sees (the mesh itself when not `separate`)
  bool separate = false;   // simplified or refined: the mesh is kept apart, to draw
  // How far the original's vertices stood outside the simplified surface, m:
  // the largest offset along the vertex normals that put them inside it
  // (each collision vertex moves by what its own neighbourhood needed).
  double deviation = 0.0;
};

// Collision surface for `mesh` (#V by 3, #F by 3) with at most
// `max_triangles` triangles (<= 0: no bound) and no edge longer than
// `max_edge` m (<= 0: no bound); a mesh within both keeps the mesh.
CollisionProxy make_collision_proxy(EmbreeDevice& device, const TriMesh& mesh, int max_triangles, double max_edge = 0.0);

// Triangles of the surface tiled by equilateral triangles of edge `edge`
// (m): area / (sqrt(3) / 4 edge^2), at least 4.
int triangles_for_edge_length(const TriMesh& mesh, double edge);

// The default collision edge length, m: a quarter of a tet-lattice cell
// `cell` (four surface edges per cell keep the shape the lattice deforms,
// curvature included), and never below twice the contact `margin` (finer
// detail is within the margin of its neighbours and adds candidates, not shape).
double default_collision_edge(double cell, double margin);

}  // namespace recoil::sim
