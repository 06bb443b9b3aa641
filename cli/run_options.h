#pragma once
// The options `run`, `drop` and `turntable` share: output folder, frame
// selection, time step, solver, statistics, video, resume, threads, and the
// render options. Options given on the command line override the scene's
// values; the overrides are recorded in the resolved scene (DIR/scene.json).
#include <CLI/CLI.hpp>
#include <string>

#include "cli/commands.h"
#include "cli/render_options.h"
#include "cli/scene_desc.h"

namespace recoil::cli {

struct RunOptions {
  std::string output;
  std::string frames;      // --frames SPEC
  double dt = 0.0;         // s (0: the scene's simulation.dt)
  std::string solver;      // cr | pgs | cr-plain (empty: the scene's)
  bool no_render = false;
  std::string stats;
  std::string video;
  bool resume = false;
  bool strict = false;     // an unconverged solve is exit 3
  int threads = 0;         // 0: the machine's cores
  RenderOptions render;    // render options; only those given override the scene
  CLI::App* command = nullptr;  // to ask which render options were given
  std::string save_scene;  // drop, turntable: also write the resolved scene here before running
};

void add_run_options(CLI::App& command, RunOptions& options);

// Applies the options to `scene` and runs it (default output folder:
// output/<scene name>/); `command_name` labels the progress bar. Returns the
// exit code.
int execute_run(SceneDesc scene, const RunOptions& options, const GlobalOptions& global,
                const std::string& command_name);

}  // namespace recoil::cli
