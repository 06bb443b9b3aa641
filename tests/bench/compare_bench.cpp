// Cost of `recoil compare` on a 300-frame 1280x720 sequence (SPEC.md section
// 6), split into its parts: metrics on decoded images, PNG decoding of both
// frames, and the heat map (only with --diff or --report). Per-pair times are
// measured on 20 distinct synthetic pairs and extrapolated to 300, on one
// thread, then the command's pipeline on one thread and on every core.
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
    return best_ms(2, [&] {
             for (int i = 0; i < measured_pairs; ++i) work(i);
           }) /
           measured_pairs;
  };
  double checksum = 0.0;
  const double metrics = per_pair([&](int i) { checksum += render::compare_images(actuals[i], references[i]).ssim; });
  const double ssim = per_pair([&](int i) {
    checksum += render::ssim_luma(render::composited_luma(actuals[i]), render::composited_luma(references[i]),
                                  width, height);
  });
  const double decode = per_pair([&](int i) {
    checksum += render::read_png(dir / ("act_" + std::to_string(i) + ".png")).width +
                render::read_png(dir / ("ref_" + std::to_string(i) + ".png")).width;
  });
  const double decode_and_metrics = per_pair([&](int i) {
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
    return best_ms(2, [&] { checksum += cli::compare_pairs(plan, settings).size(); }) / measured_pairs;
  };
  const double pipeline_one = pipeline(1);
  const double pipeline_all = pipeline(cores);
  const double heatmap = per_pair([&](int i) {
    checksum += render::encode_png(render::difference_heatmap(actuals[i], references[i], 0.02)).size();
  });
  fs::remove_all(dir);

  BenchTable table("compare, 1280x720 pairs (measured on " + std::to_string(measured_pairs) +
                       " pairs, extrapolated to " + std::to_string(sequence) + ")",
                   {"stage", "ms/pair", "s per 300 pairs"});
  auto row = [&](const std::string& name, double ms) {
    table.add_row({name, fixed(ms, 2), fixed(ms * sequence / 1000.0, 2)});
  };
  row("metrics only (diff, PSNR, SSIM; images in memory)", metrics);
  row("  of which luma + SSIM", ssim);
  row("PNG decode of both frames", decode);
  row("decode + metrics (plain `recoil compare`)", decode_and_metrics);
  row("heat map + PNG encode (--diff / --report)", heatmap);
  row("decode + metrics + heat map", decode_and_metrics + heatmap);
  row("compare_pairs pipeline, 1 thread", pipeline_one);
  row("compare_pairs pipeline, " + std::to_string(cores) + " threads", pipeline_all);
  table.print();
  std::printf("(checksum %.3f)\n", checksum);
}

Register reg("compare", bench_compare);

}  // namespace
}  // namespace recoil::bench
