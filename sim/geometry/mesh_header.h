#pragma once
// Element counts declared by mesh file headers (PLY, OFF), checked against the
// file's size before assimp reserves memory for them: assimp allocates what a
// header declares, so a 100-byte PLY claiming 4e9 vertices asks for ~48 GB.
#include <cstdint>
#include <filesystem>
#include <string>

namespace recoil::sim {

// Throws bad_input naming `path` when `head` (the first bytes of that file,
// `file_size` bytes long) is a PLY or OFF header whose counts need more bytes
// than the file has; any other content passes (assimp judges it).
void check_declared_mesh_counts(const std::string& head, std::uintmax_t file_size, const std::filesystem::path& path);

}  // namespace recoil::sim
