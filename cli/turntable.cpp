#include "cli/turntable.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "cli/frame_names.h"
#include "cli/interrupt.h"
#include "cli/render_bridge.h"
#include "render/frame_writer.h"

namespace recoil::cli {

TurntableTimings render_turntable(sim::TriMesh mesh, const TurntableJob& job,
                                  const std::function<void(int)>& on_frame) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const sim::Aabb box = sim::bounding_box(mesh);
  const Eigen::Vector3d lift(-box.center().x(), -box.min.y(), -box.center().z());
  sim::transform_in_place(mesh, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Ones(), lift);
  const sim::Aabb placed = sim::bounding_box(mesh);
  const double radius = std::max(0.5 * placed.extent().norm(), 1e-6);

  render::RenderScene scene;
  scene.meshes.push_back(to_render_mesh(mesh, job.color));
  scene.ground = true;
  scene.ground_height = 0.0f;

  render::Renderer renderer(job.settings);
  const double aspect = static_cast<double>(job.settings.width) / job.settings.height;
  const render::FrameWriterSize size = render::default_frame_writer_size();
  render::FrameWriter writer(job.png, size.threads, size.capacity);
  TurntableTimings timings;
  render::Image image;
  for (int frame = 0; frame < job.frames && !pending_interrupt(); ++frame) {
    const double azimuth = render::orbit_azimuth_deg(frame, job.frames);
    render::Camera camera = render::frame_bounding_sphere(placed.center(), radius, azimuth, job.elevation_deg, 40.0, aspect);
    if (job.camera_distance > 0)
      camera.eye = camera.target + job.camera_distance * (camera.eye - camera.target).normalized();
    const auto render_start = clock::now();
    renderer.render(scene, camera, image);
    timings.render_ms += std::chrono::duration<double, std::milli>(clock::now() - render_start).count();
    writer.submit(job.output_dir / frame_file_name(frame + 1, job.frames), image);
    if (on_frame) on_frame(frame + 1);
  }
  writer.finish();
  timings.encode_ms = writer.encode_ms();
  timings.total_ms = std::chrono::duration<double, std::milli>(clock::now() - start).count();
  return timings;
}

}  // namespace recoil::cli
