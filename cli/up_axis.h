#pragma once
// The up axis of a mesh file (`--up`, a body's "up"): recoil is Y-up, so the
// mesh's given axis is turned onto world +Y before anything else happens to it
// (a body's own transform comes after). STL, OBJ, OFF and PLY carry no up axis
// and CAD tools often write Z-up; glTF is Y-up by its specification (assimp
// reads it so), so glTF files need no --up.
#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

#include "sim/geometry/tet_mesh.h"
#include "sim/geometry/tri_mesh.h"

namespace recoil::cli {

enum class UpAxis { pos_x, neg_x, pos_y, neg_y, pos_z, neg_z };

// "+X", "-x", "Z" (a bare letter is +): nullopt for anything else.
std::optional<UpAxis> parse_up_axis(std::string_view text);
// The canonical spelling: "+X", "-X", "+Y", "-Y", "+Z", "-Z".
const char* to_string(UpAxis axis);
// The accepted spellings, for messages.
inline constexpr const char* kUpAxisChoices = "+X, -X, +Y, -Y, +Z or -Z";

// The proper rotation (3 by 3, entries 0 and +-1, so applying it is exact)
// taking `axis` to +Y by a quarter or half turn about X (for +-Z, -Y) or Z
// (for +-X): +Z up maps (x, y, z) to (x, z, -y), as Blender's Y-up export does.
Eigen::Matrix3d up_rotation(UpAxis axis);

// Rotates the mesh's vertices (nodes) in place; no-op for +Y.
void apply_up(UpAxis axis, sim::TriMesh& mesh);
void apply_up(UpAxis axis, sim::TetMesh& mesh);

// Adds `--up AXIS` (default +Y) to a mesh command; a bad value is a usage
// error naming the option (exit 2).
void add_up_option(CLI::App& command, UpAxis& up);

}  // namespace recoil::cli
