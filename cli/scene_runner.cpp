#include "cli/scene_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

#include "cli/frame_names.h"
#include "cli/frame_spec.h"
#include "cli/file_io.h"
#include "cli/format_number.h"
#include "cli/frame_stats.h"
#include "cli/interrupt.h"
#include "cli/output_dir.h"
#include "cli/progress.h"
#include "cli/rest_watch.h"
#include "cli/run_report.h"
#include "cli/scene_view.h"
#include "cli/scene_writer.h"
#include "cli/video_encoder.h"
#include "cli/work_limits.h"
#include "core/atomic_write.h"
#include "core/error.h"
#include "render/frame_writer.h"
#include "render/png.h"
#include "render/png_probe.h"
#include "render/refused_setting.h"
#include "render/renderer.h"
#include "sim/geometry/winding_solid.h"
#include "sim/world.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Inverted elements are tolerated while they recover: the run fails once a
// body stays inverted this long (simulated seconds): beyond recovery.
constexpr double kInversionGrace = 0.1;

std::string describe_failure(const sim::StepReport& r, int frame, const std::string& what, const SceneDesc& scene) {
  std::ostringstream s;
  s << scene.label() << ": simulation failed " << (frame > 0 ? "at frame " + std::to_string(frame) : "while settling")
    << " (step " << r.step << ", t = " << r.time << " s): body '" << r.body
    << "': " << what;
  return s.str();
}

// What led up to a blow-up, when contact solves failed on the way: how many
// and how badly, and the remedy that usually holds (a fast impact crosses
// more than the contact margin in one step); empty when every solve converged.
std::string after_unconverged_solves(const RunReport& report, const SceneDesc& scene) {
  const SolveQuality q = report.solve_quality(scene.world.contact.margin);
  if (q.not_converged == 0) return {};
  return " after " + std::to_string(q.not_converged) + " of " + std::to_string(q.steps) +
         " steps ended with a contact solve that did not converge (worst KKT residual " +
         format_number("%.3g", q.worst_kkt) +
         " m/s); a smaller time step (--dt, or simulation.dt in a scene file; now " +
         format_number("%g", scene.world.dt) + " s) gives a fast impact more steps";
}

// How far a deformable body's own weight alone strains it, resting on its
// base: density * |g| * height / E, its height along gravity at rest. Told
// when its elements invert and it is past a tenth, where a material stops
// being stiff enough to keep its shape, with what holds it; empty otherwise.
std::string self_weight_strain(const sim::World& world, const std::string& body, const Eigen::Vector3d& gravity) {
  for (int i = 0; i < world.num_deformable_bodies(); ++i) {
    const sim::DeformableBody& b = world.deformable_body(i);
    if (b.name != body || gravity.norm() == 0.0) continue;
    const Eigen::VectorXd along = b.rest.nodes * (gravity / gravity.norm());
    const double height = along.maxCoeff() - along.minCoeff();
    const double strain = b.material.density * gravity.norm() * height / b.material.youngs_modulus;
    if (strain < 0.1) return {};
    return "; its own weight alone strains it by about " + format_number("%.2g", 100.0 * strain) + " % (density " +
           format_number("%g", b.material.density) + " kg/m^3 x g x height " + format_number("%.3g", height) +
           " m / E " + format_number("%g", b.material.youngs_modulus) +
           " Pa): a stiffer material, or a smaller body, keeps its shape";
  }
  return {};
}

}  // namespace

namespace {

std::string describe_overlap(const sim::InitialOverlap& overlap, const SceneDesc& scene) {
  auto where = [&](const std::string& name) {
    const SceneBody* body = scene.find(name);
    return "'" + name + "'" + (body ? " (" + body->pointer + ")" : "");
  };
  std::ostringstream s;
  s.precision(3);
  s << scene.label() << ": body " << where(overlap.body) << " starts inside " << where(overlap.inside)
    << ": a vertex of it lies " << overlap.depth * 1e3 << " mm deep, more than the "
    << scene.world.contact.margin * 1e3 << " mm contact margin; move them apart";
  return s.str();
}

// "3 bodies, 2 400 000 triangles": what the build has to go through.
std::string describe_bodies(const SceneDesc& scene) {
  long long triangles = 0;
  for (const sim::DeformableBodyDesc& b : scene.world.bodies) triangles += b.mesh.num_triangles();
  for (const sim::RigidBodyDesc& b : scene.world.rigid_bodies) triangles += b.mesh.num_triangles();
  const size_t bodies = scene.world.bodies.size() + scene.world.rigid_bodies.size();
  return std::to_string(bodies) + (bodies == 1 ? " body, " : " bodies, ") + std::to_string(triangles) + " triangles";
}

}  // namespace

std::string describe_warnings(const SolveQuality& q) {
  std::ostringstream s;
  s.precision(2);
  if (q.not_converged > 0)
    s << q.not_converged << " of " << q.steps << " solves did not converge, the first "
      << (q.first_unconverged_frame > 0 ? "at frame " + std::to_string(q.first_unconverged_frame) : "while settling")
      << " (worst KKT residual " << std::scientific << q.worst_kkt << std::defaultfloat << " m/s)";
  if (q.penetrated_margin())
    s << (q.not_converged > 0 ? "; " : "") << "largest penetration " << std::fixed << q.max_penetration * 1e3
      << " mm, beyond the " << q.margin * 1e3 << " mm contact margin";
  return s.str();
}

std::string describe_run_warnings(const RunResult& result) {
  std::string text = describe_warnings(result.quality);
  if (result.still_moving())
    text += std::string(text.empty() ? "" : "; ") + "still moving after settling " +
            format_number("%g", result.settle_limit) + " s (a longer settle lets it come to rest)";
  if (result.frames_below_ground > 0)
    text += std::string(text.empty() ? "" : "; ") + "the camera is below the ground in " +
            std::to_string(result.frames_below_ground) +
            (result.frames_below_ground == 1 ? " frame" : " frames") +
            ", whose underside hides the scene (raise the camera, or --no-ground)";
  if (!result.look_warnings.empty()) {
    text += std::string(text.empty() ? "" : "; ") + result.look_warnings.front();
    if (result.look_warnings.size() > 1) text += " (and " + std::to_string(result.look_warnings.size() - 1) + " more in run.json)";
  }
  for (const auto& [name, mass] : result.cell_layers)
    text += std::string(text.empty() ? "" : "; ") + "'" + name +
            "' is open and encloses nothing (a sheet, or parts thinner than 1/" +
            std::to_string(sim::kWeighingResolution) +
            " of its longest side): its solid is the lattice cells its surface crosses, " +
            format_number("%.3g", mass) + " kg";
  if (result.open_meshes.empty()) return text;
  text += std::string(text.empty() ? "" : "; ") + (result.open_meshes.size() == 1 ? "open mesh: " : "open meshes: ");
  // A pile of a thousand copies names three of them and counts the rest.
  constexpr size_t kNamed = 3;
  const size_t named = result.open_meshes.size() <= kNamed + 1 ? result.open_meshes.size() : kNamed;
  for (size_t i = 0; i < named; ++i) text += (i == 0 ? "'" : ", '") + result.open_meshes[i] + "'";
  if (named < result.open_meshes.size()) text += " and " + std::to_string(result.open_meshes.size() - named) + " more";
  return text + " (not watertight; inside by winding number)";
}

long frame_step(int frame, double fps, double dt) {
  const double steps = (frame - 1) / (fps * dt);
  return static_cast<long>(std::ceil(steps * (1.0 - 1e-12)));
}

// The video's frame rate: the scene's over the stride of an evenly spaced
// selection (every 4th frame of 30 fps plays at 7.5), so it plays in real
// time; the scene's for a selection spaced unevenly, which no rate fits.
double video_fps(const std::vector<int>& selected, double fps) {
  if (selected.size() < 2) return fps;
  const int stride = selected[1] - selected[0];
  for (size_t i = 2; i < selected.size(); ++i)
    if (selected[i] - selected[i - 1] != stride) return fps;
  return fps / stride;
}

// Whether the run.json in `dir` says a render run finished there: only then
// does the scene.json beside it describe the frames (a run without frames,
// or a stopped one, writes its scene.json over the one that drew them).
bool frames_are_the_saved_scenes(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir / "run.json", ec)) return false;
  std::vector<std::uint8_t> bytes;
  try {
    bytes = read_file_bytes(dir / "run.json");
  } catch (const Error&) {
    return false;  // unreadable: nothing is known of the frames
  }
  const nlohmann::json run = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
  if (!run.is_object() || !run.contains("exit") || !run["exit"].is_object()) return false;
  return run.value("render", false) && run["exit"].value("code", -1) == 0;
}

// Where the scene DIR/scene.json describes, written by the last run there
// (frames_are_the_saved_scenes says whether it drew the frames), differs
// from `resolved`: a JSON pointer ("/bodies/0/material"),
// or "" when they are the same scene. A folder without one holds no run's
// frames (a run writes it before its first frame), and is "" too.
std::string difference_from_saved_scene(const fs::path& saved, const nlohmann::json& resolved) {
  std::error_code ec;
  if (!fs::exists(saved, ec)) return "";
  const std::vector<std::uint8_t> bytes = read_file_bytes(saved);
  const nlohmann::json before = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
  if (before.is_discarded()) return "scene.json beside them is not JSON";
  const nlohmann::json patch = nlohmann::json::diff(before, resolved);
  return patch.empty() ? "" : "scene.json differs at " + patch[0].value("path", std::string("/"));
}

RunResult run_scene(const RunJob& job, const GlobalOptions& global) {
  const auto start = Clock::now();
  const SceneDesc& scene = job.scene;
  // First: a scene of a billion frames must be refused before its frame list is made.
  check_work_limits(scene, job.frames.empty() ? scene.frame_count() : job.frames.back(), job.render,
                    memory_limit_bytes(global.max_memory_gib));
  const double fps = scene.render.fps, dt = scene.world.dt;
  const std::vector<int> selected = job.frames.empty() ? all_frames(scene.frame_count()) : job.frames;
  const int last_frame = selected.back();
  if (last_frame > scene.frame_count())
    throw bad_input(scene.label() + ": --frames: frame " + std::to_string(last_frame) + " is past the last, " +
                    std::to_string(scene.frame_count()) + " (simulation.duration " +
                    format_number("%g", scene.duration) + " s at render.fps " + format_number("%g", fps) +
                    "); lengthen the duration to draw it (drop: --seconds; turntable: --turn-frames)");
  // Frame names keep their width whatever subset is rendered.
  const int name_count = scene.frame_count();
  if (!job.video.empty()) {
    require_video(job.video, scene.render.background == "transparent");
    if (!job.render) throw bad_input("--video needs rendered frames: leave out --no-render");
  }
  // A statistics path naming a folder is a mistake in the command: found before anything is built or written.
  const fs::path stats_path = job.stats_path.empty() ? job.output_dir / "stats.jsonl" : job.stats_path;
  std::error_code ec;
  if (fs::is_directory(stats_path, ec))
    throw bad_input((job.stats_path.empty() ? "" : "--stats ") + stats_path.string() +
                    " is a folder; the statistics need the path of a file to write");

  RunReport report(job, scene);
  Progress progress(global, job.label, static_cast<int>(selected.size()));
  // Tetrahedralizing, simplifying and embedding a mesh of millions of triangles takes seconds.
  progress.stage("building " + describe_bodies(scene));
  auto build_start = Clock::now();
  std::unique_ptr<sim::World> world;
  world = std::make_unique<sim::World>(scene.world);  // its errors name the scene file and field
  report.timings.build = ms_since(build_start);
  if (const std::optional<sim::InitialOverlap> overlap = world->initial_overlap())
    throw bad_input(describe_overlap(*overlap, scene));

  render::RenderSettings settings;
  std::unique_ptr<render::Renderer> renderer;
  std::unique_ptr<render::FrameWriter> writer;
  std::unique_ptr<VideoEncoder> video;
  std::unique_ptr<SceneView> view;
  if (job.render) {
    settings = to_render_settings(scene.render);
    try {
      renderer = std::make_unique<render::Renderer>(settings);
      report.set_gl(render::gl_backend_name(renderer->backend()), renderer->gl_renderer());
    } catch (const render::RefusedSetting& e) {
      // A resolution or an msaa count the renderer or its driver cannot draw,
      // from the scene file or from the option of the same name.
      throw Error(e.kind(), scene.label() + ": /render/" + e.field() + " (--" + e.field() + "): " + e.what());
    }
    const render::FrameWriterSize size = render::default_frame_writer_size();
    writer = std::make_unique<render::FrameWriter>(to_png_options(scene.render), size.threads, size.capacity);
  }

  RunResult result;
  // Outputs only once the world, the renderer and the video's file exist: a
  // refused scene or video path writes nothing.
  if (job.render && !job.video.empty())
    video = std::make_unique<VideoEncoder>(job.video, settings.width, settings.height, video_fps(selected, fps),
                                          settings.transparent_background);
  ensure_output_dir(job.output_dir);
  remove_stale_temporaries(job.output_dir);
  const nlohmann::json resolved = resolved_scene(scene);
  // Frames on disk are kept (--resume) only when the run that drew them had
  // this scene, and those this run does not draw are removed when a
  // finished render run of another scene drew them.
  const std::string another_scene = difference_from_saved_scene(job.output_dir / "scene.json", resolved);
  if (job.resume) result.resume_mismatch = another_scene;
  const bool frames_of_another_scene = !another_scene.empty() && frames_are_the_saved_scenes(job.output_dir);
  write_text_atomically(job.output_dir / "scene.json", resolved.dump(2) + "\n");
  if (stats_path.has_parent_path()) ensure_output_dir(stats_path.parent_path());
  errno = 0;
  std::ofstream stats_out(stats_path, std::ios::binary | std::ios::trunc);
  if (!stats_out) throw output_error("cannot write " + stats_path.string() + ": " + errno_message(errno));

  const InterruptScope interrupts;
  const auto run_start = Clock::now();
  // Only a moving body's solid comes from its winding number; a static or kinematic one is its surface.
  for (const SceneBody& body : scene.bodies) {
    if (body.open_mesh && (body.kind == sim::BodyKind::deformable || body.kind == sim::BodyKind::rigid))
      result.open_meshes.push_back(body.name);
  }
  for (int i = 0; i < world->num_deformable_bodies(); ++i)
    if (const sim::DeformableBody& b = world->deformable_body(i); b.encloses_nothing)
      result.cell_layers.emplace_back(b.name, b.mass.sum());
  for (int i = 0; i < world->num_rigid_bodies(); ++i)
    if (const sim::RigidBody& b = world->rigid_body(i); b.encloses_nothing) result.cell_layers.emplace_back(b.name, b.mass);
  // A look nobody sees (every body of the file painted by a colour) warns of nothing.
  for (const auto& [file, warning] : scene.look_warnings)
    if (std::any_of(scene.bodies.begin(), scene.bodies.end(),
                    [&](const SceneBody& b) { return b.mesh_file == file && !b.color_given; }))
      result.look_warnings.push_back(file.string() + ": " + warning);
  result.settle_limit = scene.settle;
  size_t next = 0;  // index into selected
  long inverted_steps = 0;
  const long grace_steps = std::max(1L, static_cast<long>(std::ceil(kInversionGrace / dt)));
  // One step, with its failure checks; false once the run has failed. `frame`
  // is the frame being stepped towards (0 while settling), for the message.
  auto advance = [&](FrameAccumulator& acc, int frame) {
    const sim::StepReport r = world->step();
    acc.add(r);
    report.add_step(r, frame);
    if (r.status == sim::StepStatus::inverted) ++inverted_steps;
    else if (r.status == sim::StepStatus::ok) inverted_steps = 0;
    if (r.status == sim::StepStatus::nan || r.status == sim::StepStatus::energy_blowup ||
        r.status == sim::StepStatus::runaway) {
      result.failed = true;
      const std::string what = r.status == sim::StepStatus::nan ? "NaN in positions or velocities"
                               : r.status == sim::StepStatus::runaway
                                   ? std::to_string(r.contacts) + " contact candidates, more than " +
                                         std::to_string(sim::kMaxCandidatesPerVertex) +
                                         " per surface vertex (the bodies crossed or folded through themselves; a "
                                         "smaller time step (--dt, or simulation.dt) or a stiffer material holds them)"
                                   : "energy blew up (diverged)" + after_unconverged_solves(report, scene);
      result.message = describe_failure(r, frame, what, scene);
    } else if (r.status == sim::StepStatus::inverted && inverted_steps > grace_steps) {
      result.failed = true;
      std::ostringstream what;
      what << r.inverted_tets << " inverted elements for longer than " << kInversionGrace << " s (beyond recovery)"
           << self_weight_strain(*world, r.body, scene.world.gravity);
      result.message = describe_failure(r, frame, what.str(), scene);
    }
    if (!result.failed && progress.due()) {
      std::ostringstream life;
      life << std::fixed << std::setprecision(3) << "t = " << world->time() << " s";
      if (frame == 0) life << std::defaultfloat << " (settling, at most " << scene.settle << " s)";
      life << std::fixed << ", step " << r.step << ", " << std::setprecision(0) << ms_since(run_start) / 1000.0 << " s";
      progress.working(life.str());
    }
    return !result.failed;
  };

  // Settling: simulated, not drawn, until every dynamic body rests or the time
  // is up; frame 1's statistics count its steps.
  FrameAccumulator settling;
  if (scene.settle > 0.0) {
    const long settle_steps = std::lround(scene.settle / dt);
    RestWatch rest(dt);
    // What settles is the scene as set up: kinematic bodies start their motion with frame 1.
    world->hold_kinematic(true);
    while (world->counters().steps < settle_steps && !pending_interrupt() && advance(settling, 0))
      if (rest.update(world->stats())) {
        result.settled = true;
        break;
      }
    world->hold_kinematic(false);
    result.settle_time = world->time();
  }
  const long first_step = world->counters().steps;
  const double first_time = world->time();  // frame 1's simulated time
  // The view frames what the first frame shows: the settled scene.
  if (job.render)
    view = std::make_unique<SceneView>(scene, world->surfaces(), static_cast<double>(settings.width) / settings.height);

  render::Image image;
  double encoded_before = 0.0;
  for (int k = 1; k <= last_frame && !result.failed && !pending_interrupt(); ++k) {
    FrameAccumulator acc = k == 1 ? settling : FrameAccumulator{};
    const long target = first_step + frame_step(k, fps, dt);
    std::vector<sim::BodyStats> before;  // the bodies a step before the frame's state, for its stats
    while (world->counters().steps < target && !pending_interrupt()) {
      if (world->counters().steps + 1 == target) before = world->stats();
      if (!advance(acc, k)) break;
    }
    if (result.failed || pending_interrupt()) break;
    if (view) view->track(world->body_bounds());
    if (next >= selected.size() || selected[next] != k) continue;
    ++next;
    FrameTimes times;
    if (job.render) {
      const fs::path path = job.output_dir / frame_file_name(k, name_count);
      // Only a whole frame of this size is kept; a cut or foreign file is drawn again.
      if (job.resume && result.resume_mismatch.empty() && render::is_whole_png(path, settings.width, settings.height)) {
        ++result.frames_skipped;
        if (video) video->add(render::read_png(path));
      } else {
        const auto render_start = Clock::now();
        const render::RenderScene& drawn = view->update(world->surfaces());
        // An orbit spaces the scene's own frames round the turn.
        const render::Camera camera = view->camera(k, scene.frame_count());
        if (settings.ground && drawn.ground && camera.eye.y() < drawn.ground_height) ++result.frames_below_ground;
        renderer->render(drawn, camera, image);
        times.render = ms_since(render_start);
        if (video) video->add(image);
        writer->submit(path, image);
        ++result.frames_written;
      }
      times.encode = writer->encode_ms() - encoded_before;
      encoded_before = writer->encode_ms();
    }
    report.add_frame(times);
    const std::vector<sim::BodyStats> bodies =
        bodies_at(first_time + (k - 1) / fps, before, world->stats(), world->time(), dt);
    stats_out << frame_stats_json(k, (k - 1) / fps, world->time(), acc, bodies, scene, times).dump() << "\n";
    errno = 0;
    stats_out.flush();
    if (!stats_out) throw output_error("cannot write " + stats_path.string() + ": " + errno_message(errno));
    progress.update(static_cast<int>(next));
  }
  progress.finish();
  if (writer) writer->finish();
  // A signal while the last frames were written still stops the run: its exit code says so.
  if (!result.failed && (result.interrupted_by = pending_interrupt()) != 0)
    result.message = "interrupted by " + signal_name(result.interrupted_by) + " after " + std::to_string(next) +
                     " of " + std::to_string(selected.size()) + " frames; run the same command with --resume to finish";
  if (video && !result.failed && !result.interrupted_by) video->finish();
  // A finished run leaves the folder one scene's frames: a longer earlier
  // run's tail goes, and all that another scene's finished render run drew.
  // A run without frames leaves them (its scene may differ only in how
  // frames are drawn).
  if (job.render && !result.failed && !result.interrupted_by)
    result.removed_frames =
        remove_foreign_frames(job.output_dir, name_count, frames_of_another_scene ? &selected : nullptr);
  report.timings.encode = writer ? writer->encode_ms() : 0.0;
  result.steps = world->counters().steps;
  result.quality = report.solve_quality(scene.world.contact.margin);
  if (job.strict && !result.failed && !result.interrupted_by && result.quality.not_converged > 0) {
    result.failed = true;
    result.message = scene.label() + ": --strict: " + describe_warnings(result.quality);
  }
  report.finish(*world, result, ms_since(start));
  write_text_atomically(job.output_dir / "run.json", report.json().dump(2) + "\n");
  if (result.interrupted_by) throw Interrupted(result.interrupted_by, result.message);
  if (result.failed) throw Error(ErrorKind::sim_failed, result.message);
  return result;
}

}  // namespace recoil::cli
