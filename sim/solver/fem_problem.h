#pragma once
// A contact problem with a real FEM system matrix, for the solver's tests
// and benchmarks: a tetrahedralized cube of linear co-rotated
// material at rest on the ground plane z = 0, its bottom nodes in contact
// (one frictional contact each), the whole body drifting along x. A and b
// are the implicit-Euler system of sim/fem/assembly.h at the rest shape, so
// the stiffness spread is that of the World's bodies, not of a toy lattice.
#include <string>

#include "sim/solver/problem_builders.h"

namespace recoil::sim {

struct FemBlockParams {
  double size = 0.5;          // m, cube side
  int resolution = 8;         // lattice cells along a side
  double youngs_modulus = 1e6;  // Pa
  double density = 1000.0;    // kg/m^3
  double h = 1.0 / 60.0;      // s
  double mu = 0.5;            // static = kinetic friction
  double drift = 0.2;         // m/s along x at the start of the step
};

OwnedProblem fem_block_on_ground(const FemBlockParams& params);

// A short description for tables and test output ("cube 0.5 m, res 8, E 1e6").
std::string describe(const FemBlockParams& params);

}  // namespace recoil::sim
