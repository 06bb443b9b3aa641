#pragma once
// The resolved scene: a SceneDesc written back as a scene file with every
// default filled in and every path absolute (DIR/scene.json, --save-scene).
// Reading it back gives the same description, so a run can be repeated from
// its output folder alone.
#include <nlohmann/json.hpp>

#include "cli/scene_desc.h"

namespace recoil::cli {

// The scene file (format version 1) that describes `scene`, command-line
// overrides included; parse_scene of it gives `scene` again.
nlohmann::json resolved_scene(const SceneDesc& scene);

}  // namespace recoil::cli
