// `recoil batch` throughput: items per minute for full bunny turntables
// (120 frames at 640x360) with one item at a time against two, on this
// machine's cores. The runs are the real command, one process per batch.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

namespace fs = std::filesystem;

void bench_batch() {
  constexpr int kItems = 4;
  const fs::path dir = fs::temp_directory_path() / "recoil_bench_batch";
  fs::remove_all(dir);
  fs::create_directories(dir);
  nlohmann::json manifest = nlohmann::json::array();
  const std::string bunny = (fs::path(RECOIL_SOURCE_DIR) / "assets/meshes/bunny.obj").string();
  for (int i = 0; i < kItems; ++i)
    manifest.push_back({{"mesh", bunny}, {"name", "bunny-" + std::to_string(i + 1)}, {"resolution", "640x360"}});
  std::ofstream(dir / "manifest.json") << manifest.dump(1);

  BenchTable table("recoil batch: bunny turntables, 120 frames at 640x360, " + std::to_string(kItems) + " items",
                   {"--jobs", "seconds", "items/minute", "x --jobs 1"});
  table.note(
      "One `recoil batch` per `--jobs` setting over the same items. One item already keeps the cores busy "
      "(llvmpipe's rasteriser threads and the PNG encoders), so a second at a time fills only the gaps: an item's "
      "start (import, world build) and its last frames' encoding.");
  double one_job = 0.0;
  for (const int jobs : {1, 2}) {
    const fs::path out = dir / ("jobs" + std::to_string(jobs));
    const std::string command = std::string(RECOIL_BINARY) + " -q batch '" + (dir / "manifest.json").string() +
                                "' --jobs " + std::to_string(jobs) + " -o '" + out.string() + "'";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (status != 0) {
      table.add_row({std::to_string(jobs), "failed: " + command});
      continue;
    }
    const double rate = 60.0 * kItems / seconds;
    if (jobs == 1) one_job = rate;
    table.add_row({std::to_string(jobs), fixed(seconds, 1), fixed(rate, 1), fixed(one_job > 0 ? rate / one_job : 0.0, 2)});
  }
  fs::remove_all(dir);
  table.print();
}

const Register registered_batch("batch", bench_batch);

}  // namespace
}  // namespace recoil::bench
