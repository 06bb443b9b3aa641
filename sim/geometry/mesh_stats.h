#pragma once
// Surface statistics for `recoil info` and for physics set-up (mass from the
// enclosed volume, checks before tetrahedralization).
#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

struct MeshStats {
  int vertices = 0;
  int triangles = 0;
  int components = 0;         // connected through shared vertices
  int boundary_edges = 0;     // edges used by one triangle
  int non_manifold_edges = 0; // edges used by three or more triangles
  int inconsistent_edges = 0; // edges whose two triangles traverse it the same way
  bool watertight = false;    // closed, manifold and consistently oriented
  Aabb bounds;
  double area = 0.0;          // m^2
  double volume = 0.0;        // m^3, signed enclosed volume (only meaningful when watertight)
};

MeshStats compute_mesh_stats(const TriMesh& mesh);

// Signed volume enclosed by the surface (divergence theorem), positive for an
// outward-oriented closed surface. #F triangles, O(#F).
double enclosed_volume(const TriMesh& mesh);

double surface_area(const TriMesh& mesh);

}  // namespace recoil::sim
