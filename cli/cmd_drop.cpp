// `recoil drop MESH...`: builds a drop-test scene (cli/drop_scene.cpp) and
// runs it like `recoil run`.
#include "cli/commands.h"
#include "cli/drop_scene.h"
#include "cli/number_range.h"
#include "cli/run_options.h"
#include "cli/scene_parser.h"
#include "cli/utf8_arguments.h"
#include "core/error.h"

namespace recoil::cli {
namespace {

struct DropCommandOptions {
  DropSettings drop;
  RunOptions run;
};

int run_drop(const DropCommandOptions& options, const GlobalOptions& global) {
  ImportedMeshes imported;
  const nlohmann::json document = build_drop_scene(options.drop, &imported);
  const std::string& saved = options.run.save_scene;
  SceneDesc scene =
      parse_scene(document, saved.empty() ? "drop" : saved, std::filesystem::current_path(), std::move(imported));
  return execute_run(std::move(scene), options.run, global, "drop");
}

}  // namespace

void add_drop_command(CLI::App& app, const GlobalOptions& global, Action& action) {
  auto options = std::make_shared<DropCommandOptions>();
  CLI::App* cmd = app.add_subcommand("drop", "Drop meshes onto a ground plane and render the result");
  cmd->add_option("MESH", options->drop.meshes, "Mesh files (anything assimp reads)")->required();
  cmd->add_option("--material", options->drop.material, "Material preset")
      ->check(CLI::IsMember({"soft", "rubber", "jelly", "stiff", "rigid"}))->capture_default_str();
  cmd->add_option("--height", options->drop.height, "Drop height of the lowest body above the ground, m")
      ->check(NumberIn(0.0, 100.0))->capture_default_str();
  cmd->add_option("--friction", options->drop.friction, "Friction coefficient of the ground and the bodies")
      ->check(NumberIn(0.0, 10.0))->capture_default_str();
  cmd->add_option("--count", options->drop.count, "Drop this many bodies in a loose pile, the meshes taking turns (seeded: reruns match); 1: each mesh once, side by side")
      ->check(WholeNumberIn(1, 1000))->capture_default_str();
  cmd->add_option("--seconds", options->drop.seconds, "Simulated seconds")
      ->check(NumberIn(0.0, 3600.0))->capture_default_str();
  add_up_option(*cmd, options->drop.up);
  add_collision_options(*cmd, options->drop.collision);
  cmd->add_option("--save-scene", options->run.save_scene,
                  "Also write the scene built, to edit and rerun with `recoil run`");
  add_run_options(*cmd, options->run);
  cmd->footer(
      "Meshes between 5 cm and 2 m keep their size; others are scaled to 30 cm. --up names the\n"
      "mesh files' up axis (recorded as each body's \"up\" in the scene): a Z-up STL stands as\n"
      "modelled with --up +Z. Open meshes (holes, flipped faces) work: inside and outside are\n"
      "decided by the winding number, and the summary names them. A mesh finer than the\n"
      "simulation needs collides through a simplified copy (see `recoil info` on the saved scene)\n"
      "while the mesh itself is drawn; --collision-triangles and --collision-edge set its size.\n\n"
      "Examples:\n"
      "  recoil drop assets/meshes/bunny.obj\n"
      "  recoil drop assets/meshes/bunny.obj --count 8 --material jelly --seconds 4\n"
      "  recoil drop part.stl --material rigid --friction 0.3 --save-scene part-drop.json\n"
      "  recoil drop bracket.stl --up +Z          # exported Z-up: stands as in the CAD tool\n"
      "  recoil drop statue.ply --collision-triangles 4000   # a 2M-triangle scan, 4000 for contact\n");
  cmd->callback([options, &global, &action] {
    action = [options, &global] {
      require_utf8_arguments(global);
      return run_drop(*options, global);
    };
  });
}

}  // namespace recoil::cli
