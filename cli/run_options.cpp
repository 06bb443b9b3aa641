#include "cli/number_range.h"
#include "cli/run_options.h"

#include <iostream>
#include <thread>

#include "cli/file_io.h"
#include "cli/frame_spec.h"
#include "cli/output_dir.h"
#include "cli/scene_limits.h"
#include "cli/scene_runner.h"
#include "cli/scene_writer.h"
#include "core/error.h"

namespace recoil::cli {
namespace {

bool given(const RunOptions& options, const char* name) {
  return options.command && options.command->count(name) > 0;
}

// The overrides change the scene itself, so that what is drawn and the
// scene.json written beside the frames say the same thing.
void apply_render_overrides(const RunOptions& o, SceneDesc& scene) {
  if (given(o, "--resolution")) scene.render.resolution = o.render.resolution;
  if (given(o, "--fps")) scene.render.fps = o.render.fps;
  if (given(o, "--msaa")) scene.render.msaa = o.render.msaa;
  if (given(o, "--no-shadows")) scene.render.no_shadows = true;
  if (given(o, "--no-ground")) scene.render.no_ground = true;
  if (given(o, "--background")) scene.render.background = o.render.background;
  if (given(o, "--wireframe")) scene.render.wireframe = true;
  if (given(o, "--ao")) scene.render.ambient_occlusion = true;
  if (given(o, "--no-ao")) scene.render.ambient_occlusion = false;
  if (given(o, "--png-level")) scene.render.png_level = o.render.png_level;
  if (given(o, "--gl")) scene.render.gl = o.render.gl;
  if (given(o, "--color")) {
    const render::Rgb color = parse_color(o.render.color, "--color");
    for (SceneBody& body : scene.bodies)
      if (!body.is_plane()) body.color = color, body.color_given = true;
  }
  CameraDesc& camera = scene.camera;
  const char* mode = camera.mode == CameraMode::orbit ? "orbits" : "follows a body";
  if (given(o, "--camera-position")) {
    if (camera.mode != CameraMode::fixed)
      throw bad_input("--camera-position: the camera of " + scene.label() + " " + mode + "; a position needs a fixed camera");
    camera.position = parse_point(o.render.camera_position, "--camera-position");
    camera.has_position = true;
    camera.distance = 0.0;  // a position leaves no distance to keep
  }
  if (given(o, "--camera-target")) {
    if (camera.mode == CameraMode::follow)
      throw bad_input("--camera-target: the camera of " + scene.label() + " follows a body, which is its target");
    camera.target = parse_point(o.render.camera_target, "--camera-target");
    camera.has_target = true;
  }
  if ((given(o, "--camera-position") || given(o, "--camera-target")) && camera.has_position && camera.has_target &&
      (camera.position - camera.target).norm() < 1e-9)
    throw bad_input(std::string(given(o, "--camera-position") ? "--camera-position" : "--camera-target") +
                    ": the camera's position and target must differ");
  if (given(o, "--azimuth")) {
    if (camera.mode == CameraMode::fixed && camera.has_position)
      throw bad_input("--azimuth: " + scene.label() + " places its camera at a position, which sets its direction");
    camera.azimuth = o.render.azimuth;
  }
  if (given(o, "--fov")) camera.fov = o.render.fov;
  if (given(o, "--camera-distance")) {
    // A camera standing at a given position has no distance to change.
    if (o.render.camera_distance > 0.0 && given(o, "--camera-position"))
      throw bad_input("--camera-distance: not with --camera-position, which places the camera; give one of them");
    if (o.render.camera_distance > 0.0 && scene.camera.mode == CameraMode::fixed && scene.camera.has_position)
      throw bad_input("--camera-distance: " + scene.label() +
                      " places its camera at /render/camera/position; remove that to frame the scene from a distance");
    scene.camera.distance = o.render.camera_distance;  // 0: fit the scene
  }
  to_render_settings(scene.render);  // validates the combination (fps, resolution)
}

}  // namespace

void add_run_options(CLI::App& command, RunOptions& options) {
  options.command = &command;
  command.add_option("-o,--output", options.output, "Output folder (default: output/<scene name>/)");
  command.add_option("--frames", options.frames, "Frames to write: 1-100, 1-100:5, 1,3,7-9 (default: all)")
      ->check(CLI::Validator(
          [](const std::string& spec) {
            try {
              parse_frame_spec(spec);
              return std::string();
            } catch (const Error& e) {
              const std::string message = e.what();  // "--frames: why"; CLI11 names the option itself
              return message.substr(message.find(": ") + 2);
            }
          },
          "SPEC"));
  command.add_option("--dt", options.dt,
                     "Time step in seconds (default: the scene's simulation.dt; 0.004 for drop and turntable); "
                     "a smaller one gives a fast impact more steps")
      ->check(NumberIn(kTimeStepRange.lo, kTimeStepRange.hi));
  command.add_option("--solver", options.solver, "Contact solver (default: the scene's)")
      ->check(CLI::IsMember({"cr", "pgs", "cr-plain"}));
  command.add_flag("--no-render", options.no_render, "Simulate and write statistics only, no frames");
  command.add_option("--stats", options.stats, "Write the per-frame statistics here (default: DIR/stats.jsonl)");
  command.add_option("--video", options.video, "Also encode the frames to this video: .mp4, .mov, .mkv, .webm or .gif (needs ffmpeg; over --background transparent .webm or .gif, which keep it); every Nth frame (--frames 1-120:N) plays at fps/N, in real time; frames spaced unevenly (1,3,7-9) have no such rate and play at fps");
  command.add_flag("--resume", options.resume, "Keep frames already whole on disk, draw the rest (the simulation still runs)");
  command.add_flag("--strict", options.strict,
                   "Fail (exit 3) when a contact solve did not converge; the frames and run.json are still written");
  command.add_option("--threads", options.threads, "Threads for collision queries (default: all cores)")
      ->check(WholeNumberIn(1, 1024));
  add_render_options(command, options.render);
}

int execute_run(SceneDesc scene, const RunOptions& options, const GlobalOptions& global,
                const std::string& command_name) {
  RunJob job;
  if (options.dt > 0.0) scene.world.dt = options.dt;
  if (!options.solver.empty()) {
    scene.world.contact.solver.method = options.solver == "pgs"        ? sim::SolverMethod::pgs
                                        : options.solver == "cr-plain" ? sim::SolverMethod::cr_plain
                                                                       : sim::SolverMethod::cr;
  }
  const unsigned cores = std::thread::hardware_concurrency();
  scene.world.contact.num_threads = options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, cores));
  apply_render_overrides(options, scene);
  if (!options.save_scene.empty()) write_text_atomically(options.save_scene, resolved_scene(scene).dump(2) + "\n");
  if (!options.frames.empty()) job.frames = parse_frame_spec(options.frames);
  job.output_dir = options.output.empty() ? default_output_dir(scene.name) : std::filesystem::path(options.output);
  job.stats_path = options.stats;
  job.video = options.video;
  job.render = !options.no_render;
  job.resume = options.resume;
  job.strict = options.strict;
  job.label = command_name;
  job.command = global.command_line();
  job.scene = std::move(scene);
  const RunResult result = run_scene(job, global);
  // The summary line: always when it carries a warning, which -q never hides.
  const std::string warnings = describe_run_warnings(result);
  if (global.log_json) {
    const nlohmann::json line = {{"event", "summary"},       {"scene", job.scene.name},
                                 {"steps", result.steps},     {"frames_written", result.frames_written},
                                 {"frames_skipped", result.frames_skipped},
                                 {"resume_mismatch", result.resume_mismatch},
                                 {"frames_removed", result.removed_frames.count}, {"output", job.output_dir.string()},
                                 {"warnings", warnings}};
    std::cerr << line.dump() << "\n";
  } else if (!global.quiet || !warnings.empty()) {
    std::cerr << "recoil: " << job.scene.name << ": " << result.steps << " steps";
    if (job.render) {
      std::cerr << ", wrote " << result.frames_written << (result.frames_written == 1 ? " frame" : " frames");
      if (result.frames_skipped > 0) std::cerr << " (" << result.frames_skipped << " already on disk)";
      if (!result.resume_mismatch.empty())
        std::cerr << " (--resume drew every frame again: " << result.resume_mismatch << ")";
    }
    std::cerr << " to " << job.output_dir.string();
    if (job.render && !job.video.empty()) std::cerr << " and " << job.video.string();
    if (const RemovedFrames& gone = result.removed_frames; gone.count > 0)
      std::cerr << ", removed " << gone.count << " frames of another run (" << gone.first
                << (gone.count > 1 ? " to " + gone.last : "") << ")";
    if (!warnings.empty()) std::cerr << "; warning: " << warnings;
    std::cerr << "\n";
  }
  return 0;
}

}  // namespace recoil::cli
