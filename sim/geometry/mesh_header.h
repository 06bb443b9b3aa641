#pragma once
// Element counts declared by mesh files (PLY headers and ASCII list counts,
// OFF headers), checked against the file's size before assimp reserves memory
// for them: assimp allocates what a file declares, so a 100-byte PLY claiming
// 4e9 vertices asks for ~48 GB.
#include <filesystem>

namespace recoil::sim {

// Throws bad_input naming `path` when that file is a PLY or OFF file whose
// counts need more bytes than it has; any other content passes (assimp judges it).
void check_declared_mesh_counts(const std::filesystem::path& path);

}  // namespace recoil::sim
