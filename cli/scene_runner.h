#pragma once
// The frame loop of `recoil run` (and `drop`): the simulation clock (steps of
// dt) against the frame clock (frame k at (k - 1) / fps), rendering the
// selected frames through the renderer and FrameWriter, stats.jsonl, run.json
// and the optional video. Apart from its command-line parsing so tests and
// benchmarks drive exactly what the commands do.
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/output_dir.h"
#include "cli/run_report.h"
#include "cli/scene_desc.h"
#include "core/error.h"

namespace recoil::cli {

struct RunJob {
  SceneDesc scene;                        // overrides from the command line already applied
  std::vector<int> frames;                // selected frames, ascending; empty: every frame of the scene
  std::filesystem::path output_dir;
  std::filesystem::path stats_path;       // empty: output_dir / stats.jsonl
  std::filesystem::path video;            // empty: no video
  bool render = true;
  bool resume = false;                    // keep frames already on disk
  bool strict = false;                    // a solve that did not converge fails the run (exit 3)
  std::string command;                    // the command line, for run.json
  std::string label = "run";              // the command, for the progress bar
};

// "12 of 750 solves did not converge (worst KKT residual 3.1e-04 m/s); ..."
// naming every warning, or empty when there is none.
std::string describe_warnings(const SolveQuality& quality);

struct RunResult {
  int frames_written = 0;
  int frames_skipped = 0;   // --resume: already on disk
  // --resume found frames of another scene (why, scene_runner.cpp): all drawn again; empty otherwise.
  std::string resume_mismatch;
  RemovedFrames removed_frames;  // another run's frames, deleted from the folder (output_dir.h)
  long steps = 0;
  bool failed = false;
  int interrupted_by = 0;   // SIGINT or SIGTERM that stopped the run early; 0: none
  std::string message;      // what failed, or what interrupted the run
  SolveQuality quality;
  std::vector<std::string> open_meshes;  // bodies from mesh files that are not watertight, scene order
  // Bodies of open meshes that enclose no lattice cell, with their mass (kg):
  // simulated as the layer of cells their surface crosses.
  std::vector<std::pair<std::string, double>> cell_layers;
  std::vector<std::string> look_warnings;  // "FILE: ..." for the looks drawn without something (a texture)
  int frames_below_ground = 0;  // drawn from under the ground, whose underside hides everything above it
  double settle_limit = 0.0;  // s: the scene's settle
  double settle_time = 0.0;   // s: simulated before frame 1
  bool settled = false;       // every dynamic body came to rest within settle_limit
  // Settling was asked for and ran to its end with a body still moving.
  bool still_moving() const { return settle_limit > 0.0 && !settled && !failed && !interrupted_by; }
};

// Every warning of a run, for the summary line and run.json: the solve's
// (describe_warnings), a body still moving after settling, and the open meshes
// ("open mesh: 'cup' (inside by winding number)"); empty when there is none.
std::string describe_run_warnings(const RunResult& result);

// Writes scene.json first, then frames, stats and run.json into job.output_dir
// (created). A failed simulation (or, with job.strict, an unconverged solve)
// throws Error(sim_failed) after the frames so far are on disk and run.json
// records it; the message names the scene file, the frame and the body.
// SIGINT or SIGTERM stops the loop between steps and frames: the frames so far
// are written whole, run.json says "interrupted", then Interrupted is thrown.
RunResult run_scene(const RunJob& job, const GlobalOptions& global);

// Steps at which frame k (1-based) is taken: the first step at or after its
// time (k - 1) / fps (to rounding), so that the step before and this one
// hold the frame's time between them (its statistics interpolate there).
long frame_step(int frame, double fps, double dt);

}  // namespace recoil::cli
