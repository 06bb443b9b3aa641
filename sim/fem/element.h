#pragma once
// Linear tetrahedral elements: rest shape data and the energy, gradient and
// (projected) Hessian of one element with respect to its 12 node coordinates.
#include <Eigen/Core>
#include <vector>

#include "sim/fem/material.h"
#include "sim/geometry/tet_mesh.h"

namespace recoil::sim {

using Vector12d = Eigen::Matrix<double, 12, 1>;
using Matrix12d = Eigen::Matrix<double, 12, 12>;

struct ElementRest {
  Eigen::Matrix3d Bm;      // inverse of the rest edge matrix [X1-X0, X2-X0, X3-X0], 1/m
  double volume = 0.0;     // rest volume, m^3 (> 0)
};

// Rest data of every tet. RECOIL_CHECKs positive volumes.
std::vector<ElementRest> element_rest(const TetMesh& rest);

// x: the element's 4 node positions (12 entries, node-major). F = Ds Bm.
Eigen::Matrix3d deformation_gradient(const ElementRest& rest, const Vector12d& x);

struct ElementEval {
  double energy = 0.0;  // J
  Vector12d gradient;   // dE/dx, N (the elastic force is its negative)
  Matrix12d hessian;    // d2E/dx2, N/m; projected PSD when requested
};

// `project`: clamp the 9x9 dP/dF to PSD before mapping to nodes, which makes
// the 12x12 Hessian PSD (G^T C G with C PSD) for less than the cost of an
// eigen-decomposition of the 12x12 (analytic for the co-rotated model).
ElementEval evaluate_element(MaterialModel model, const Lame& lame, const ElementRest& rest, const Vector12d& x,
                             bool want_hessian, bool project);

}  // namespace recoil::sim
