#include "cli/turntable_scene.h"

#include <filesystem>

#include "cli/drop_scene.h"
#include "cli/scene_limits.h"

namespace recoil::cli {

nlohmann::json build_turntable_scene(const TurntableSettings& settings, ImportedMeshes* imported) {
  DropSettings drop;
  drop.meshes = {settings.mesh};
  drop.material = settings.settle > 0.0 ? settings.material : "static";
  // A static mesh stands on the ground; a settling one is released a tenth of
  // its size above it (its collision surface may reach below the drawn mesh)
  // and falls and tips into its stable pose.
  drop.height = 0.0;
  drop.height_per_size = settings.settle > 0.0 ? 0.1 : 0.0;
  drop.up = settings.up;
  drop.collision = settings.collision;
  drop.seconds = (settings.turn_frames - 1) / settings.fps;
  nlohmann::json scene = build_drop_scene(drop, imported);
  scene["name"] = name_from_stem(std::filesystem::path(settings.mesh).stem().string());
  scene["description"] = "built by recoil turntable";
  scene["simulation"]["settle"] = settings.settle;
  scene["render"] = {{"fps", settings.fps},
                     // A three-quarter view first, which shows two sides of a box, not one.
                     {"camera", {{"mode", "orbit"}, {"azimuth", 30}, {"elevation", settings.elevation}, {"turns", 1}}}};
  return scene;
}

}  // namespace recoil::cli
