#pragma once
// Mesh simplification through meshoptimizer (sim/'s only includer of
// meshoptimizer.h): quadric-error edge collapses that keep a subset of the
// input's vertices, so the result lies on the input surface at its vertices.
#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

struct SimplifiedMesh {
  TriMesh mesh;                  // unused vertices dropped
  double relative_error = 0.0;   // meshoptimizer's error estimate, as a share of the input's extent
  Eigen::VectorXi source;        // #V of `mesh`: the input vertex each one is
};

// Collapses edges until at most `target_triangles` remain; when borders (holes,
// separate shells) stop it at more than six times the target, clusters vertices
// instead (meshopt_simplifySloppy), which ignores topology.
SimplifiedMesh simplify_mesh(const TriMesh& mesh, int target_triangles);

}  // namespace recoil::sim
