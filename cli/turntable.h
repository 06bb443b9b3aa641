#pragma once
// The turntable frame loop, apart from its command-line parsing so the
// benchmark measures exactly what `recoil turntable` does.
#include <filesystem>
#include <functional>

#include "render/camera.h"
#include "render/png.h"
#include "render/renderer.h"
#include "sim/geometry/tri_mesh.h"

namespace recoil::cli {

struct TurntableJob {
  render::RenderSettings settings;
  render::PngOptions png;
  render::Rgb color;
  int frames = 120;
  double elevation_deg = 20.0;
  double camera_distance = 0.0;  // metres from the target; 0: fit the bounding sphere
  std::filesystem::path output_dir;
};

struct TurntableTimings {
  double render_ms = 0.0;  // summed over frames, on the calling thread
  double encode_ms = 0.0;  // summed over frames, on the encoder threads
  double total_ms = 0.0;   // wall time of the whole loop, encoding drained
};

// Stands `mesh` on the ground (y = 0) centred on the vertical axis, orbits the
// camera once around it and writes frame_0001.png ... into job.output_dir
// (which must exist). `on_frame(done)` is called after each frame is queued.
// Inside an InterruptScope (cli/interrupt.h) a signal ends the loop early,
// with every frame queued so far written whole.
TurntableTimings render_turntable(sim::TriMesh mesh, const TurntableJob& job,
                                  const std::function<void(int)>& on_frame = {});

}  // namespace recoil::cli
