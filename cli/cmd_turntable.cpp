// `recoil turntable MESH`: options and reporting; the frame loop is in
// cli/turntable.cpp.
#include <iostream>

#include "cli/commands.h"
#include "cli/interrupt.h"
#include "cli/output_dir.h"
#include "cli/progress.h"
#include "cli/render_options.h"
#include "cli/turntable.h"
#include "cli/up_axis.h"
#include "core/error.h"
#include "sim/geometry/mesh_import.h"

namespace recoil::cli {
namespace {

struct TurntableOptions {
  std::string mesh;
  std::string output;
  int frames = 120;
  double elevation = 20.0;  // degrees above the horizon
  UpAxis up = UpAxis::pos_y;
  RenderOptions render;
};

int run_turntable(const TurntableOptions& options, const GlobalOptions& global) {
  TurntableJob job;
  job.settings = to_render_settings(options.render);
  job.png = to_png_options(options.render);
  job.color = options.render.color.empty() ? palette_color(0) : parse_color(options.render.color, "--color");
  job.frames = options.frames;
  job.elevation_deg = options.elevation;
  job.camera_distance = options.render.camera_distance;
  job.output_dir = options.output.empty()
                       ? default_output_dir(std::filesystem::path(options.mesh).stem().string())
                       : std::filesystem::path(options.output);
  sim::TriMesh mesh = sim::import_surface(options.mesh);
  apply_up(options.up, mesh);
  ensure_output_dir(job.output_dir);
  const InterruptScope interrupts;
  Progress progress(global, "turntable", options.frames);
  int frames_done = 0;
  render_turntable(std::move(mesh), job, [&](int done) { progress.update(frames_done = done); });
  progress.finish();
  if (const int sig = pending_interrupt())
    throw Interrupted(sig, "interrupted by " + signal_name(sig) + " after " + std::to_string(frames_done) +
                               " of " + std::to_string(options.frames) + " frames; those are whole in " +
                               job.output_dir.string());
  if (!global.quiet) std::cerr << "recoil: wrote " << options.frames << " frames to " << job.output_dir.string() << "\n";
  return 0;
}

}  // namespace

void add_turntable_command(CLI::App& app, const GlobalOptions& global, Action& action) {
  auto options = std::make_shared<TurntableOptions>();
  CLI::App* cmd = app.add_subcommand("turntable", "Orbit the camera once around a mesh and render every frame");
  cmd->add_option("MESH", options->mesh, "Mesh file (anything assimp reads: OBJ, PLY, STL, glTF, ...)")->required();
  cmd->add_option("-o,--output", options->output, "Output folder (default: output/<mesh name>/)");
  cmd->add_option("--frames", options->frames, "Number of frames in one full turn")
      ->check(CLI::Range(1, 1000000))->capture_default_str();
  cmd->add_option("--elevation", options->elevation, "Camera height above the horizon, degrees")
      ->check(CLI::Range(-89.0, 89.0))->capture_default_str();
  add_up_option(*cmd, options->up);
  add_render_options(*cmd, options->render);
  cmd->footer(
      "The mesh is stood on a ground plane, its --up axis (default +Y) turned to world +Y, and\n"
      "the camera circles it once; frames are written as DIR/frame_0001.png, frame_0002.png, ...\n"
      "(PNG encoding overlaps rendering).\n\n"
      "Examples:\n"
      "  recoil turntable assets/meshes/bunny.obj\n"
      "  recoil turntable model.glb --frames 240 --elevation 35 --resolution 1920x1080 -o preview/\n"
      "  recoil turntable part.stl --color '#8fb3d9' --background transparent --msaa 0\n"
      "  recoil turntable bracket.stl --up +Z       # a Z-up CAD export, stood as modelled\n"
      "  ffmpeg -framerate 30 -i output/bunny/frame_%04d.png bunny.mp4   # make a video\n");
  cmd->callback([options, &global, &action] { action = [options, &global] { return run_turntable(*options, global); }; });
}

}  // namespace recoil::cli
