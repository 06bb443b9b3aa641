// `recoil turntable MESH`: the camera orbits once around a mesh standing on the
// ground, one PNG per frame. Rendering of frame i+1 overlaps the PNG encoding
// of frame i (render::FrameWriter).
#include <algorithm>
#include <iostream>
#include <thread>

#include "cli/commands.h"
#include "cli/frame_names.h"
#include "cli/output_dir.h"
#include "cli/progress.h"
#include "cli/render_bridge.h"
#include "cli/render_options.h"
#include "core/error.h"
#include "render/camera.h"
#include "render/frame_writer.h"
#include "render/renderer.h"
#include "sim/geometry/mesh_import.h"

namespace recoil::cli {
namespace {

struct TurntableOptions {
  std::string mesh;
  std::string output;
  int frames = 120;
  double elevation = 20.0;  // degrees above the horizon
  RenderOptions render;
};

int run_turntable(const TurntableOptions& options, const GlobalOptions& global) {
  const render::RenderSettings settings = to_render_settings(options.render);
  const render::Rgb color =
      options.render.color.empty() ? palette_color(0) : parse_color(options.render.color, "--color");
  sim::TriMesh mesh = sim::import_surface(options.mesh);

  // Stand the mesh on the ground (y = 0), centred on the vertical axis.
  const sim::Aabb box = sim::bounding_box(mesh);
  const Eigen::Vector3d lift(-box.center().x(), -box.min.y(), -box.center().z());
  sim::transform_in_place(mesh, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Ones(), lift);
  const sim::Aabb placed = sim::bounding_box(mesh);
  const Eigen::Vector3d center = placed.center();
  const double radius = std::max(0.5 * placed.extent().norm(), 1e-6);

  render::RenderScene scene;
  scene.meshes.push_back(to_render_mesh(mesh, color));
  scene.ground = true;
  scene.ground_height = 0.0f;

  const std::filesystem::path dir =
      options.output.empty() ? default_output_dir(std::filesystem::path(options.mesh).stem().string())
                             : std::filesystem::path(options.output);
  ensure_output_dir(dir);

  render::Renderer renderer(settings);
  const double aspect = static_cast<double>(settings.width) / settings.height;
  const int encoders = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1);
  render::FrameWriter writer(to_png_options(options.render), encoders, 2 * encoders + 1);
  Progress progress(global, "turntable", options.frames);
  render::Image image;
  for (int frame = 0; frame < options.frames; ++frame) {
    const double azimuth = render::orbit_azimuth_deg(frame, options.frames);
    render::Camera camera =
        render::frame_bounding_sphere(center, radius, azimuth, options.elevation, 40.0, aspect);
    if (options.render.camera_distance > 0)
      camera.eye = camera.target + options.render.camera_distance * (camera.eye - camera.target).normalized();
    renderer.render(scene, camera, image);
    writer.submit(dir / frame_file_name(frame + 1, options.frames), image);
    progress.update(frame + 1);
  }
  writer.finish();
  progress.finish();
  if (!global.quiet) std::cerr << "recoil: wrote " << options.frames << " frames to " << dir.string() << "\n";
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
  add_render_options(*cmd, options->render);
  cmd->footer(
      "The mesh is stood on a ground plane and the camera circles it once; frames are\n"
      "written as DIR/frame_0001.png, frame_0002.png, ... (PNG encoding overlaps rendering).\n\n"
      "Examples:\n"
      "  recoil turntable assets/meshes/bunny.obj\n"
      "  recoil turntable model.glb --frames 240 --elevation 35 --resolution 1920x1080 -o preview/\n"
      "  recoil turntable part.stl --color '#8fb3d9' --background transparent --msaa 0\n"
      "  ffmpeg -framerate 30 -i output/bunny/frame_%04d.png bunny.mp4   # make a video\n");
  cmd->callback([options, &global, &action] { action = [options, &global] { return run_turntable(*options, global); }; });
}

}  // namespace recoil::cli
