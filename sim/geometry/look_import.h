#pragma once
// The materials of an assimp scene as SurfaceLook materials: base colours and
// base-colour textures, decoded to pixels (stb_image: PNG, JPEG, TGA, BMP...).
// Runs inside the mesh reader's child (isolated_reader.h) with the rest of the
// assimp code, so a texture that crashes the decoder ends only the child.
#include <filesystem>
#include <string>
#include <vector>

#include "sim/geometry/surface_look.h"

struct aiScene;

namespace recoil::sim {

// One entry per material of the scene, in its order. A texture that is missing
// or cannot be decoded adds a line to `warnings` and leaves that material
// untextured. External texture paths are relative to the mesh file's folder.
std::vector<LookMaterial> read_materials(const aiScene& scene, const std::filesystem::path& mesh_file,
                                         std::vector<std::string>& warnings);

}  // namespace recoil::sim
