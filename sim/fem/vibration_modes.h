#pragma once
// The lowest vibration frequency of a deformable body at rest: the smallest
// non-zero omega with K phi = omega^2 M phi, where K is the rest stiffness
// (#3N by #3N, N/m) and M the lumped mass (kg). Stiffness-proportional damping
// is calibrated on it, so the body's slowest vibration decays at the ratio the
// user asked for.
#include <vector>

#include "sim/fem/element.h"
#include "sim/fem/material.h"
#include "sim/geometry/tet_mesh.h"

namespace recoil::sim {

struct VibrationInput {
  const TetMesh* rest = nullptr;                  // nodes in metres
  const std::vector<ElementRest>* elements = nullptr;
  MaterialModel model = MaterialModel::corotated;
  Lame lame;
  const Eigen::VectorXd* mass = nullptr;          // #N lumped masses, kg
  const std::vector<char>* pinned = nullptr;      // #N, pinned nodes are held (their DoF removed)
};

struct VibrationMode {
  double omega = 0.0;     // rad/s; 0 when every node is pinned
  Eigen::VectorXd shape;  // #3N, M-normalised (phi^T M phi = 1), zero on pinned nodes
};

// Inverse subspace iteration on (K + sigma M)^-1 M with a Rayleigh-Ritz step
// (a sparse LDL^T of the shifted stiffness, factored once). Rigid motions
// (zero modes of a free or partly held body) are skipped as numerical zeros.
VibrationMode lowest_vibration_mode(const VibrationInput& input);

}  // namespace recoil::sim
