// End-to-end `recoil turntable` on a ~1M-triangle mesh at 1920x1080, MSAA 4,
// shadows: rendering and PNG encoding overlap, so the wall time per frame
// should come close to the larger of the two, not their sum.
#include <filesystem>

#include "cli/turntable.h"
#include "sim/geometry/primitives.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

void bench_turntable() {
  BenchTable table("recoil turntable end to end, 1920x1080, MSAA 4, shadows, PNG level 1",
                   {"mesh", "triangles", "frames", "render ms/frame", "encode ms/frame", "end-to-end ms/frame",
                    "sum / end-to-end"});
  struct Subject {
    const char* name;
    sim::TriMesh mesh;
  };
  const Subject subjects[] = {{"sphere", sim::make_sphere(0.5, 4)}, {"torus", sim::make_torus(0.7, 0.3, 1000, 500)}};
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "recoil_bench_turntable";
  std::filesystem::create_directories(dir);
  for (const Subject& subject : subjects) {
    cli::TurntableJob job;
    job.settings.width = 1920;
    job.settings.height = 1080;
    job.color = {0.85f, 0.63f, 0.40f};
    job.frames = 12;
    job.output_dir = dir;
    const cli::TurntableTimings t = cli::render_turntable(subject.mesh, job);
    const double render = t.render_ms / job.frames, encode = t.encode_ms / job.frames, total = t.total_ms / job.frames;
    table.add_row({subject.name, std::to_string(subject.mesh.num_triangles()), std::to_string(job.frames), fixed(render),
                   fixed(encode), fixed(total), fixed((render + encode) / total, 2)});
  }
  std::filesystem::remove_all(dir);
  table.print();
}

const Register registered_turntable("turntable", bench_turntable);

}  // namespace
}  // namespace recoil::bench
