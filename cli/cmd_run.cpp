// `recoil run SCENE.json`: options and reporting; parsing is in
// cli/scene_parser.cpp and the frame loop in cli/scene_runner.cpp.
#include <cctype>
#include <filesystem>
#include <fstream>

#include "cli/commands.h"
#include "cli/run_options.h"
#include "cli/scene_parser.h"
#include "cli/utf8_arguments.h"
#include "core/error.h"

namespace recoil::cli {
namespace {

struct RunCommandOptions {
  std::string scene;
  RunOptions run;
};

// A folder or a mesh given where a scene file belongs: say what to run instead.
void refuse_non_scene(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    const fs::path saved = fs::path(path) / "scene.json";
    throw bad_input(path + ": a folder, not a scene file; " +
                    (fs::is_regular_file(saved, ec) ? "`recoil run " + saved.string() + "` reruns the scene saved there"
                                                    : std::string("`recoil run` takes a scene file (JSON)")));
  }
  if (!fs::is_regular_file(path, ec)) return;  // missing, a pipe: the parser says what is wrong
  std::ifstream in(path, std::ios::binary);
  std::string head(3, '\0');
  in.read(head.data(), 3);
  if (head != "\xEF\xBB\xBF") in.seekg(0);  // a UTF-8 byte-order mark, which JSON readers skip
  in.clear();
  char first = 0;
  while (in.get(first) && std::isspace(static_cast<unsigned char>(first))) {
  }
  if (in && first != '{')
    throw bad_input(path + ": not a scene file (a scene is a JSON object); for a mesh, `recoil drop " + path +
                    "` builds a scene of it and `recoil turntable " + path + "` renders it");
}

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
      require_utf8_arguments(global);
      refuse_non_scene(options->scene);
      return execute_run(load_scene(options->scene), options->run, global, "run");
    };
  });
}

}  // namespace recoil::cli
