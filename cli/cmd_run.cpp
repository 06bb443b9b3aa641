// `recoil run SCENE.json`: options and reporting; parsing is in
// cli/scene_parser.cpp and the frame loop in cli/scene_runner.cpp.
#include "cli/commands.h"
#include "cli/run_options.h"
#include "cli/scene_parser.h"

namespace recoil::cli {
namespace {

struct RunCommandOptions {
  std::string scene;
  RunOptions run;
};

}  // namespace

void add_run_command(CLI::App& app, const GlobalOptions& global, Action& action) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scene file and render its frames");
  cmd->add_option("SCENE", options->scene, "Scene file (JSON; every key in docs/scene-format.md)")->required();
  add_run_options(*cmd, options->run);
  cmd->footer(
      "Writes DIR/frame_0001.png ..., DIR/stats.jsonl (one JSON object per frame), DIR/scene.json\n"
      "(the fully resolved scene) and DIR/run.json (timings, solver totals, exit status).\n"
      "Frame k shows simulated time (k - 1) / fps. Options given here override the scene's values.\n\n"
      "Examples:\n"
      "  recoil run assets/scenes/bunny-drop.json\n"
      "  recoil run assets/scenes/jelly-stack.json --frames 1-60:2 --resolution 640x360 -o preview/\n"
      "  recoil run scene.json --no-render --stats stats.jsonl       # physics only\n"
      "  recoil run scene.json --resume                               # finish an interrupted run\n"
      "  recoil run scene.json --video out.mp4                        # needs ffmpeg\n");
  cmd->callback([options, &global, &action] {
    action = [options, &global] {
      return execute_run(load_scene(options->scene), options->run, global, "recoil run " + options->scene);
    };
  });
}

}  // namespace recoil::cli
