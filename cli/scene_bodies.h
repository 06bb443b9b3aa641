#pragma once
// The `bodies` array of a scene file: geometry (mesh files, tet files,
// primitives), materials, friction, transforms and motion, into the WorldDesc.
#include <filesystem>
#include <vector>

#include "cli/json_cursor.h"
#include "cli/scene_desc.h"

namespace recoil::cli {

// Parses the bodies (cursors at /bodies/i) and appends them to `scene`
// (scene.bodies and the matching WorldDesc lists). Names must be unique; a
// mesh file named by several bodies is read once.
void parse_bodies(const std::vector<JsonCursor>& bodies, const std::filesystem::path& base_dir, SceneDesc& scene);

// SPEC's single `damping` (a damping ratio zeta) as Rayleigh coefficients
// D = alpha M + beta K, split evenly between the two terms at the body's
// fundamental frequency estimate omega0 = (pi / L) sqrt(E / rho) (a free bar
// of length L, the body's longest side): alpha = zeta omega0 (1/s),
// beta = zeta / omega0 (s), so the damping ratio at omega0 is exactly zeta.
void rayleigh_from_damping(double zeta, double youngs_modulus, double density, double length, double& alpha,
                           double& beta);

}  // namespace recoil::cli
