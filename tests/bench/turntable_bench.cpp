// End-to-end `recoil turntable` on a sphere and a ~1M-triangle torus at
// 1920x1080, MSAA 4, shadows, one process each: rendering and PNG encoding
// overlap, so the wall time per frame should come close to the larger of the
// two, not their sum. The figures are the run's own (run.json).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "sim/geometry/primitives.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

namespace fs = std::filesystem;

void bench_turntable() {
  BenchTable table("recoil turntable end to end, 1920x1080, MSAA 4, shadows, PNG level 1",
                   {"mesh", "triangles", "frames", "build ms", "render ms/frame", "encode ms/frame",
                    "end-to-end ms/frame", "sum / end-to-end"});
  table.note(
      "`recoil turntable` as a user runs it, one process per mesh, 12 frames of a turn; the figures are the run's "
      "own (`run.json`). \"End to end\" is the run less the world's build, per frame; a sum of render and encode "
      "above it means PNG encoding overlapped the next frame's rendering.");
  struct Subject {
    const char* name;
    sim::TriMesh mesh;
  };
  const Subject subjects[] = {{"sphere", sim::make_sphere(0.5, 4)}, {"torus", sim::make_torus(0.7, 0.3, 1000, 500)}};
  const fs::path dir = fs::temp_directory_path() / "recoil_bench_turntable";
  fs::remove_all(dir);
  fs::create_directories(dir);
  constexpr int kFrames = 12;
  for (const Subject& subject : subjects) {
    const fs::path mesh = dir / (std::string(subject.name) + ".off"), out = dir / subject.name;
    write_off(subject.mesh, mesh);
    const std::string command = std::string(RECOIL_BINARY) + " -q turntable '" + mesh.string() + "' --turn-frames " +
                                std::to_string(kFrames) + " --resolution 1920x1080 -o '" + out.string() + "'";
    if (std::system(command.c_str()) != 0) {
      table.add_row({subject.name, "failed: " + command});
      continue;
    }
    const nlohmann::json t = nlohmann::json::parse(std::ifstream(out / "run.json"))["timings_ms"];
    const double render = t["render"].get<double>() / kFrames, encode = t["encode"].get<double>() / kFrames;
    const double total = (t["total"].get<double>() - t["build"].get<double>()) / kFrames;
    table.add_row({subject.name, std::to_string(subject.mesh.num_triangles()), std::to_string(kFrames),
                   fixed(t["build"].get<double>(), 0), fixed(render), fixed(encode), fixed(total),
                   fixed((render + encode) / total, 2)});
  }
  fs::remove_all(dir);
  table.print();
}

const Register registered_turntable("turntable", bench_turntable);

}  // namespace
}  // namespace recoil::bench
