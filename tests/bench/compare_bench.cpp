// Cost of `recoil compare` on a 300-frame 1280x720 sequence, split into its parts: metrics on decoded images, PNG decoding of both
// frames, and the heat map (only with --diff or --report). Per-pair times are
// measured on 20 distinct synthetic pairs and extrapolated to 300, on one
// thread, then the command's pipeline on one thread and on every core.
#include <time.h>

#include <filesystem>
#include <algorithm>
#include <cstdio>
#include <random>
#include <thread>
#include <unistd.h>

#include "cli/compare_pairs.h"
#include "render/diff_heatmap.h"
#include "render/image_metrics.h"
#include "render/png.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {
namespace fs = std::filesystem;

constexpr int width = 1280, height = 720, measured_pairs = 20, sequence = 300;

// A shaded-looking frame: gradients, a checker ground, seeded noise.
render::Image frame(unsigned seed) {
  render::Image image(width, height);
  std::mt19937 rng(seed);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(40 + x * 150 / width + rng() % 4);
      p[1] = static_cast<std::uint8_t>(50 + y * 120 / height + rng() % 4);
      p[2] = static_cast<std::uint8_t>(60 + (((x + int(seed)) / 64 + y / 64) % 2) * 40);
      p[3] = 255;
    }
  return image;
}

// The "actual" of a pair: the reference with noise and a moved bright patch.
render::Image perturbed(const render::Image& reference, unsigned seed) {
  render::Image image = reference;
  std::mt19937 rng(seed * 7 + 1);
  for (size_t i = 0; i < image.rgba.size(); i += 4)
    image.rgba[i] = static_cast<std::uint8_t>(std::min<unsigned>(255u, image.rgba[i] + unsigned(rng() % 3)));
  const int x0 = 100 + int(seed) * 20;
  for (int y = 300; y < 380; ++y)
    for (int x = x0; x < x0 + 80; ++x) image.pixel(x, y)[1] = 250;
  return image;
}

struct Timing {
  double wall_ms = 0.0;  // per pair, best of 2 runs
  double cpu_ms = 0.0;   // per pair, process CPU time (all threads) over both runs / 2
};

double cpu_now_ms() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// CPU time is reported beside wall time because the build machine is shared:
// wall time there includes waiting for a core, CPU time does not.
Timing measure(const std::function<void()>& all_pairs) {
  const double cpu_start = cpu_now_ms();
  const double wall = best_ms(2, all_pairs);
  return {wall / measured_pairs, (cpu_now_ms() - cpu_start) / (2.0 * measured_pairs)};
}

void bench_compare() {
  std::vector<render::Image> references, actuals;
  for (int i = 0; i < measured_pairs; ++i) {
    references.push_back(frame(unsigned(i)));
    actuals.push_back(perturbed(references.back(), unsigned(i)));
  }
  const fs::path dir = fs::temp_directory_path() / ("recoil_compare_bench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (int i = 0; i < measured_pairs; ++i) {
    render::write_png(dir / ("ref_" + std::to_string(i) + ".png"), references[i]);
    render::write_png(dir / ("act_" + std::to_string(i) + ".png"), actuals[i]);
  }

  auto per_pair = [&](const std::function<void(int)>& work) {
    return measure([&] {
      for (int i = 0; i < measured_pairs; ++i) work(i);
    });
  };
  double checksum = 0.0;
  const Timing metrics = per_pair([&](int i) { checksum += render::compare_images(actuals[i], references[i]).ssim; });
  const Timing ssim = per_pair([&](int i) {
    checksum += render::ssim_luma(render::composited_luma(actuals[i]), render::composited_luma(references[i]),
                                  width, height);
  });
  const Timing decode = per_pair([&](int i) {
    checksum += render::read_png(dir / ("act_" + std::to_string(i) + ".png")).width +
                render::read_png(dir / ("ref_" + std::to_string(i) + ".png")).width;
  });
  const Timing decode_and_metrics = per_pair([&](int i) {
    checksum += render::compare_image_files(dir / ("act_" + std::to_string(i) + ".png"),
                                            dir / ("ref_" + std::to_string(i) + ".png"))
                    .metrics.ssim;
  });
  // The command's own pipeline (decode + metrics per pair, pairs spread over
  // threads), on the same 20 pairs, with one thread and with every core.
  cli::PairPlan plan;
  for (int i = 0; i < measured_pairs; ++i) {
    plan.actual.push_back(dir / ("act_" + std::to_string(i) + ".png"));
    plan.reference.push_back(dir / ("ref_" + std::to_string(i) + ".png"));
  }
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  auto pipeline = [&](int threads) {
    cli::CompareSettings settings;
    settings.threads = threads;
    return measure([&] { checksum += cli::compare_pairs(plan, settings).size(); });
  };
  const Timing pipeline_one = pipeline(1);
  const Timing pipeline_all = pipeline(cores);
  const Timing heatmap = per_pair([&](int i) {
    checksum += render::encode_png(render::difference_heatmap(actuals[i], references[i], 0.02)).size();
  });
  fs::remove_all(dir);

  BenchTable table("compare, 1280x720 pairs (measured on " + std::to_string(measured_pairs) +
                       " pairs, extrapolated to " + std::to_string(sequence) + ")",
                   {"stage", "wall ms/pair", "CPU ms/pair (all threads)", "wall s per 300 pairs"});
  auto row = [&](const std::string& name, const Timing& t) {
    table.add_row({name, fixed(t.wall_ms, 2), fixed(t.cpu_ms, 2), fixed(t.wall_ms * sequence / 1000.0, 2)});
  };
  row("metrics only (diff, PSNR, SSIM; images in memory)", metrics);
  row("  of which luma + SSIM", ssim);
  row("PNG decode of both frames", decode);
  row("decode + metrics (plain `recoil compare`)", decode_and_metrics);
  row("heat map + PNG encode (--diff / --report)", heatmap);
  row("decode + metrics + heat map",
      {decode_and_metrics.wall_ms + heatmap.wall_ms, decode_and_metrics.cpu_ms + heatmap.cpu_ms});
  row("compare_pairs pipeline, 1 thread", pipeline_one);
  row("compare_pairs pipeline, " + std::to_string(cores) + " threads", pipeline_all);
  table.print();
  std::printf("(checksum %.3f)\n", checksum);
}

const Register registered_compare("compare", bench_compare);

}  // namespace
}  // namespace recoil::bench
