#pragma once
// Scene file v1 -> SceneDesc. Every error is a
// recoil::Error(bad_input) naming the file and the JSON pointer, e.g.
//   scene.json: /bodies/2/material/poisson_ratio: must be in [0, 0.5), got 0.7
// and syntax errors give the file, line and column.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/imported_meshes.h"
#include "cli/scene_desc.h"

namespace recoil::cli {

// Reads and parses a scene file; relative paths inside resolve against its folder.
SceneDesc load_scene(const std::filesystem::path& file);

// Parses an already loaded document. `file` names it in messages; relative
// paths resolve against `base_dir`; mesh files in `imported` are taken from
// there instead of being read again.
SceneDesc parse_scene(const nlohmann::json& document, const std::string& file, const std::filesystem::path& base_dir,
                      ImportedMeshes imported = {});

}  // namespace recoil::cli
