// `recoil drop` on meshes of increasing size, same material, tet resolution
// and duration: ms per simulated step and peak memory against the bunny's,
// and the candidates offered while the body still falls freely. Each drop
// runs in its own process (the CLI), which reports its own peak memory.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "sim/geometry/mesh_import.h"
#include "sim/geometry/primitives.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

namespace fs = std::filesystem;

// The first 0.3 s: the fall from drop's 0.3 m gap and the first impact,
// when the contact patch is widest and the solve hardest.
constexpr double kLandingSeconds = 0.3;

struct DropRun {
  bool ok = false;
  double ms_per_step = 0.0, build_ms = 0.0, peak_mib = 0.0;
  double landing_ms_per_step = 0.0;  // over the frames of the first kLandingSeconds only
  long steps = 0;
  int free_fall_contacts = 0;  // summed over the frames before the collision surface nears the ground
  double collision_below = 0.0;  // m: how far the collision surface reaches below the drawn mesh
  long collision_triangles = 0;  // of the collision surface contact sees
};

// `recoil info --json` of a scene file.
nlohmann::json scene_info(const fs::path& scene) {
  const std::string command = std::string(RECOIL_BINARY) + " info --json '" + scene.string() + "' 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string text;
  if (pipe) {
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
    ::pclose(pipe);
  }
  return nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
}

DropRun run_drop(const fs::path& mesh, const fs::path& out) {
  DropRun r;
  const pid_t child = fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, 2);
    // No --seconds: the whole drop a user gets by default (3 s: the fall,
    // the landing, the bounce and the settling), not the landing alone.
    execl(RECOIL_BINARY, RECOIL_BINARY, "drop", mesh.c_str(), "--no-render", "-q", "-o", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return r;
  const nlohmann::json run = nlohmann::json::parse(std::ifstream(out / "run.json"));
  // The run's own peak: the child's ru_maxrss would count this bench's memory, which it forked from.
  r.peak_mib = run.value("peak_memory_mib", 0.0);
  r.steps = run["steps"].get<long>();
  r.ms_per_step = run["timings_ms"]["step"].get<double>() / static_cast<double>(std::max(r.steps, 1L));
  r.build_ms = run["timings_ms"]["build"].get<double>();
  const nlohmann::json info = scene_info(out / "scene.json");
  if (info.is_discarded()) return r;
  r.collision_below = info["bodies"][1].value("collision_below", 0.0);
  r.collision_triangles = info["bodies"][1].value("collision_triangles", 0L);
  std::ifstream stats(out / "stats.jsonl");
  std::string line;
  double start_height = 0.0, landing_ms = 0.0;
  long landing_steps = 0;
  bool falling = true;
  while (std::getline(stats, line)) {
    // Frames until the collision surface has fallen within 1 cm of the
    // ground (drop leaves a 0.3 m gap under the drawn mesh): the ground's
    // own candidates start there.
    const nlohmann::json frame = nlohmann::json::parse(line);
    if (frame["time"].get<double>() <= kLandingSeconds + 1e-9) {
      landing_ms += frame["ms"]["step"].get<double>();
      landing_steps += frame["steps"].get<long>();
    }
    const double height = frame["bodies"][0]["com"][1].get<double>();
    if (frame["frame"].get<int>() == 1) start_height = height;
    if (start_height - height > 0.29 - r.collision_below) falling = false;
    if (falling) r.free_fall_contacts += frame["contacts"].get<int>();
  }
  r.landing_ms_per_step = landing_ms / static_cast<double>(std::max(landing_steps, 1L));
  r.ok = true;
  return r;
}

void drop_bench() {
  const fs::path dir = fs::temp_directory_path() / ("recoil_drop_bench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::vector<std::pair<std::string, fs::path>> meshes = {
      {"bunny (assets)", fs::path(RECOIL_SOURCE_DIR) / "assets/meshes/bunny.obj"},
      {"duck.dae (assimp-testmodels)", "/usr/share/assimp/models/Collada/duck.dae"},
      {"human.zae (assimp-testmodels)", "/usr/share/assimp/models/Collada/human.zae"},
      // 86 open CAD shells, many a few millimetres apart once scaled to 0.3 m.
      {"2CylinderEngine.glb (assimp-testmodels)",
       "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"}};
  // The same 0.3 m sphere from 1 280 to 1.3 M triangles: the coarse one is
  // the shape's own cost, below any simplification.
  for (int level : {3, 6, 7, 8}) {
    const fs::path path = dir / ("sphere" + std::to_string(level) + ".off");
    write_off(sim::make_sphere(0.15, level), path);
    meshes.emplace_back("sphere, subdivision " + std::to_string(level), path);
  }
  const fs::path torus = dir / "torus.off";  // 0.3 m across, 1024 x 1000 quads: 2 048 000 triangles
  write_off(sim::make_torus(0.11, 0.04, 1024, 1000), torus);
  meshes.emplace_back("torus, 1024 x 1000", torus);
  BenchTable table("drop, 3 s, soft, resolution 8 (each in its own process)",
                   {"mesh", "triangles", "collision triangles", "ms/step", "x bunny", "landing ms/step", "x bunny",
                    "build ms", "peak MiB", "collision below mm", "free-fall candidates"});
  table.note(
      "`recoil drop MESH --no-render` (the default 3 s: fall, landing, bounce, settling), one process per mesh, its "
      "peak memory the run's own (`run.json`), default `soft` material, tet resolution 8. \"Landing\" is the same "
      "run's first 0.3 s alone: the fall and the first impact, when the contact patch spreads and the solve is "
      "hardest. \"Collision below\" is how far the collision surface reaches "
      "below the drawn mesh (`recoil info`), what the body rests above the ground; \"free-fall candidates\" sums "
      "the contact candidates of the frames before the collision surface comes within 1 cm of the ground. The "
      "step cost is set by the collision surface, which the lattice sizes (docs/decisions/003-collision-surfaces.md), "
      "not by the drawn mesh's triangle count: the spheres from 82 k to 1.3 M triangles share one collision budget. "
      "The engine's landing is its 86 shells squashed into each other: self-contact searches over its collision "
      "surface (column \"collision triangles\").");
  double bunny_ms = 0.0, bunny_landing_ms = 0.0;
  for (const auto& [name, path] : meshes) {
    if (!fs::exists(path)) continue;
    const DropRun r = run_drop(path, dir / fs::path(path).stem());
    if (!r.ok) {
      table.add_row({name, "", "failed"});
      continue;
    }
    if (bunny_ms == 0.0) {
      bunny_ms = r.ms_per_step;
      bunny_landing_ms = r.landing_ms_per_step;
    }
    table.add_row({name, std::to_string(sim::import_surface(path).num_triangles()), std::to_string(r.collision_triangles),
                   fixed(r.ms_per_step, 2), fixed(r.ms_per_step / bunny_ms, 2),
                   fixed(r.landing_ms_per_step, 2), fixed(r.landing_ms_per_step / bunny_landing_ms, 2), fixed(r.build_ms, 0),
                   fixed(r.peak_mib, 0), fixed(1e3 * r.collision_below, 1), std::to_string(r.free_fall_contacts)});
  }
  table.print();
  std::error_code ec;
  fs::remove_all(dir, ec);
}

Register drop_registration("drop", drop_bench);

}  // namespace
}  // namespace recoil::bench
