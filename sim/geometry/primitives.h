#pragma once
// Watertight primitives of scene files (`primitive`), centred on their local origin.
// Every primitive is a closed, consistently outward-oriented, vertex-welded
// triangle surface (each edge shared by exactly two triangles), so it can be
// tetrahedralized and its volume computed. Flat faces are subdivided so that
// smooth per-vertex normals only round a thin band along sharp edges.
#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

// size: full edge lengths (x, y, z), metres; `cells` subdivisions per edge.
TriMesh make_box(const Eigen::Vector3d& size, int cells = 8);

// Icosphere: `subdivisions` 3 gives 1280 triangles.
TriMesh make_sphere(double radius, int subdivisions = 3);

// Axis along local y, from -height/2 to +height/2.
TriMesh make_cylinder(double radius, double height, int segments = 48);

// height: length of the cylindrical part (axis along y); total length height + 2 radius.
TriMesh make_capsule(double radius, double height, int segments = 48);

// In the local x-z plane: major radius R to the tube centre, minor radius r of the tube.
TriMesh make_torus(double major_radius, double minor_radius, int major_segments = 64, int minor_segments = 24);

}  // namespace recoil::sim
