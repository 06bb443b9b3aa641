#pragma once
// The `bodies` array of a scene file: geometry (mesh files, tet files,
// primitives), materials, friction, transforms and motion, into the WorldDesc.
#include <filesystem>
#include <vector>

#include "cli/imported_meshes.h"
#include "cli/json_cursor.h"
#include "cli/scene_desc.h"

namespace recoil::cli {

// Parses the bodies (cursors at /bodies/i) and appends them to `scene`
// (scene.bodies and the matching WorldDesc lists). Names must be unique; a
// mesh file named by several bodies is read once, and one in `imported` not
// at all.
void parse_bodies(const std::vector<JsonCursor>& bodies, const std::filesystem::path& base_dir, SceneDesc& scene,
                  ImportedMeshes imported = {});

// Whether `path` names a tetrahedral mesh file (.msh, .node, .ele) by its extension.
bool is_tet_file(const std::filesystem::path& path);

}  // namespace recoil::cli
