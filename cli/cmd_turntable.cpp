// `recoil turntable MESH`: builds a turntable scene (cli/turntable_scene.cpp)
// and runs it like `recoil run`.
#include "cli/commands.h"
#include "cli/number_range.h"
#include "cli/render_options.h"
#include "cli/run_options.h"
#include "cli/scene_parser.h"
#include "cli/turntable_scene.h"
#include "cli/utf8_arguments.h"

namespace recoil::cli {
namespace {

struct TurntableOptions {
  TurntableSettings turntable;
  bool settle = false;
  double settle_seconds = 5.0;
  RunOptions run;
};

int run_turntable(TurntableOptions options, const GlobalOptions& global) {
  to_render_settings(options.run.render);  // --fps and --resolution, named, before they size the scene
  options.turntable.settle = options.settle ? options.settle_seconds : 0.0;
  options.turntable.fps = options.run.render.fps;
  ImportedMeshes imported;
  const nlohmann::json document = build_turntable_scene(options.turntable, &imported);
  const std::string& saved = options.run.save_scene;
  SceneDesc scene =
      parse_scene(document, saved.empty() ? "turntable" : saved, std::filesystem::current_path(), std::move(imported));
  return execute_run(std::move(scene), options.run, global, "turntable");
}

}  // namespace

void add_turntable_command(CLI::App& app, const GlobalOptions& global, Action& action) {
  auto options = std::make_shared<TurntableOptions>();
  CLI::App* cmd = app.add_subcommand("turntable", "Orbit the camera once around a mesh and render every frame");
  cmd->add_option("MESH", options->turntable.mesh, "Mesh file (anything assimp reads: OBJ, PLY, STL, glTF, ...)")
      ->required();
  cmd->add_option("--turn-frames", options->turntable.turn_frames, "Frames in one full turn")
      ->check(WholeNumberIn(1, 1000000))->capture_default_str();
  cmd->add_option("--elevation", options->turntable.elevation, "Camera height above the horizon, degrees")
      ->check(NumberIn(-89.0, 89.0))->capture_default_str();
  add_up_option(*cmd, options->turntable.up);
  CLI::Option* settle = cmd->add_flag(
      "--settle", options->settle, "Release the mesh on the ground and let it come to rest before the orbit");
  cmd->add_option("--settle-seconds", options->settle_seconds, "Simulated seconds of settling at most")
      ->check(NumberIn(0.001, 3600.0))->capture_default_str()->needs(settle);
  cmd->add_option("--material", options->turntable.material, "What a settling mesh is made of (a drop preset)")
      ->check(CLI::IsMember({"soft", "rubber", "jelly", "stiff", "rigid"}))->capture_default_str()->needs(settle);
  add_collision_options(*cmd, options->turntable.collision);
  for (const char* name : {"--collision-triangles", "--collision-edge"}) cmd->get_option(name)->needs(settle);
  cmd->add_option("--save-scene", options->run.save_scene,
                  "Also write the scene built, to edit and rerun with `recoil run`");
  add_run_options(*cmd, options->run);
  cmd->footer(
      "The mesh is stood on a ground plane, its --up axis (default +Y) turned to world +Y, and the\n"
      "camera circles it once in --turn-frames frames; frames are written as DIR/frame_0001.png, ...\n"
      "--frames picks which of them to write, as in `run` (--turn-frames makes the turn longer).\n"
      "With --settle the mesh is released just above where it stands and simulated (not drawn) until\n"
      "it rests, at most --settle-seconds, so the physics picks its stable pose; the orbit then frames\n"
      "the resting mesh. Like `run`, it writes\n"
      "scene.json, stats.jsonl and run.json beside the frames, and takes --video, --resume and --no-render.\n"
      "As in `drop`, a mesh whose longest side is outside 5 cm - 2 m is scaled to 30 cm, and a settling\n"
      "mesh collides through a simplified copy sized by --collision-triangles or --collision-edge.\n\n"
      "Examples:\n"
      "  recoil turntable assets/meshes/bunny.obj\n"
      "  recoil turntable model.glb --turn-frames 240 --elevation 35 --resolution 1920x1080 -o preview/\n"
      "  recoil turntable part.stl --color '#8fb3d9' --background transparent --msaa 0\n"
      "  recoil turntable bracket.stl --up +Z       # a Z-up CAD export, stood as modelled\n"
      "  recoil turntable rock.obj --settle         # lying on its most stable side\n"
      "  recoil turntable scan.ply --settle --collision-triangles 3000   # a fine scan settles on 3000\n"
      "  recoil turntable model.glb --frames 1,31,61,91 -o views/   # four views of the 120\n"
      "  recoil turntable model.glb --video model.mp4               # needs ffmpeg\n");
  cmd->callback([options, &global, &action] {
    action = [options, &global] {
      require_utf8_arguments(global);
      return run_turntable(*options, global);
    };
  });
}

}  // namespace recoil::cli
