#pragma once
// `recoil info SCENE.json`: a scene's bodies and statistics (types, triangles,
// the tetrahedra each deformable body gets, masses), without simulating.
#include <filesystem>

namespace recoil::cli {

// Prints to stdout, as text or one JSON object. Returns the exit code.
int print_scene_info(const std::filesystem::path& file, bool json);

}  // namespace recoil::cli
