// Offscreen rendering cost per frame (llvmpipe reference
// timings at 1920x1080: 3.7k triangles ~8 ms, 1M ~72 ms without AA
// or shadows; 4x MSAA adds ~20 / ~110 ms). Each row is the best of a few
// frames after a warm-up frame, and includes what every frame of a run pays:
// normals, vertex upload, shadow pass, drawing, resolve and read-back.
#include <time.h>

#include <chrono>
#include <string>
#include <vector>

#include "render/crease_split.h"
#include "render/renderer.h"
#include "render/vertex_normals.h"
#include "tests/bench/bench.h"
#include "tests/render/test_meshes.h"

namespace recoil::bench {
namespace {

// Process CPU time (ms) summed over all threads, llvmpipe's workers included:
// steadier than wall time on a machine shared with other jobs.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

struct Config {
  int msaa;
  bool shadows;
};

void bench_render() {
  struct Subject {
    std::string name;
    render::RenderMesh mesh;
  };
  std::vector<Subject> subjects;
  // 62 x 30 quads = 3,720 triangles, about the Stanford bunny's 3.7k.
  subjects.push_back({"torus 3.7k", render::test::make_torus({0, 0.35f, 0}, 0.7f, 0.3f, 62, 30, {0.85f, 0.63f, 0.40f})});
  // 1000 x 500 quads = 1,000,000 triangles.
  subjects.push_back({"torus 1M", render::test::make_torus({0, 0.35f, 0}, 0.7f, 0.3f, 1000, 500, {0.85f, 0.63f, 0.40f})});
  const std::vector<Config> configs = {{0, false}, {0, true}, {4, false}, {4, true}};

  BenchTable table("Render 1920x1080, llvmpipe (render() incl. normals, upload, read-back)",
                   {"mesh", "triangles", "msaa", "shadows", "ms/frame", "frames/s", "cpu ms/frame"});
  for (const Subject& subject : subjects) {
    render::RenderScene scene;
    scene.meshes.push_back(subject.mesh);
    const render::Camera camera = render::frame_bounding_sphere({0, 0.35, 0}, 1.05, 30, 20, 40, 1920.0 / 1080.0);
    for (const Config& config : configs) {
      render::RenderSettings settings;
      settings.width = 1920;
      settings.height = 1080;
      settings.msaa = config.msaa;
      settings.shadows = config.shadows;
      render::Renderer renderer(settings);
      render::Image image;
      renderer.render(scene, camera, image);  // warm-up: shader JIT, index upload
      constexpr int kFrames = 4;
      const double cpu_start = cpu_ms();
      const double ms = best_ms(kFrames, [&] { renderer.render(scene, camera, image); });
      const double cpu = (cpu_ms() - cpu_start) / kFrames;
      table.add_row({subject.name, std::to_string(subject.mesh.indices.size() / 3), std::to_string(config.msaa),
                     config.shadows ? "yes" : "no", fixed(ms), fixed(1000.0 / ms), fixed(cpu)});
    }
  }
  table.print();

  BenchTable parts("Render parts, CPU side (single thread)", {"part", "triangles", "ms"});
  for (const Subject& subject : subjects) {
    std::vector<float> normals;
    const double ms = best_ms(4, [&] { render::area_weighted_normals(subject.mesh.positions, subject.mesh.indices, normals); });
    parts.add_row({"area-weighted normals (every frame)", std::to_string(subject.mesh.indices.size() / 3), fixed(ms, 2)});
    const double split_ms = best_ms(2, [&] { render::split_creases(subject.mesh.positions, subject.mesh.indices, 40.0); });
    parts.add_row({"crease split + closedness (topology change)", std::to_string(subject.mesh.indices.size() / 3), fixed(split_ms, 2)});
  }
  parts.print();
}

const Register registered_render("render", bench_render);

}  // namespace
}  // namespace recoil::bench
