#pragma once
// Mass, centre of mass and inertia tensor of a homogeneous solid bounded by a
// closed, outward-oriented triangle surface (divergence theorem: the solid is
// the signed sum of the tetrahedra (origin, a, b, c) over its triangles), or
// filled by tetrahedra.
#include <Eigen/Core>

#include "sim/geometry/tet_mesh.h"
#include "sim/geometry/tri_mesh.h"
#include "sim/geometry/winding_solid.h"

namespace recoil::sim {

struct MassProperties {
  double volume = 0.0;                                       // m^3 (signed: negative for an inward surface)
  double mass = 0.0;                                         // kg
  Eigen::Vector3d center = Eigen::Vector3d::Zero();          // m, centre of mass
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();         // kg m^2, about the centre, in the mesh's axes
};

// mesh: #V by 3 vertices, #F by 3 triangles (closed). density in kg/m^3.
MassProperties mass_properties(const TriMesh& mesh, double density);
// The same for the solid a tet mesh fills (positively oriented tets), e.g.
// the lattice cells an open surface that encloses nothing crosses.
MassProperties mass_properties(const TetMesh& solid, double density);
// The same for the grid cells an open surface's winding number fills.
MassProperties mass_properties(const WindingSolid& solid, double density);

}  // namespace recoil::sim
