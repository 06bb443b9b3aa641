// PNG encoding cost per frame at the zlib level and filter choices.
#include <random>

#include "render/png.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

// A frame with smooth gradients and a little noise, like a shaded render.
render::Image synthetic_frame(int width, int height) {
  render::Image image(width, height);
  std::mt19937 rng(7);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(40 + x * 150 / width + (rng() % 3));
      p[1] = static_cast<std::uint8_t>(50 + y * 120 / height);
      p[2] = static_cast<std::uint8_t>(60 + ((x / 64 + y / 64) % 2) * 40);
      p[3] = 255;
    }
  return image;
}

void bench_png() {
  const render::Image frame = synthetic_frame(1920, 1080);
  BenchTable table("PNG encode, 1920x1080 RGBA", {"level", "filter", "ms/frame", "KiB"});
  for (int level : {1, 6}) {
    for (bool fast : {true, false}) {
      size_t bytes = 0;
      const double ms = best_ms(3, [&] { bytes = render::encode_png(frame, {level, fast}).size(); });
      table.add_row({std::to_string(level), fast ? "sub" : "adaptive", fixed(ms), std::to_string(bytes / 1024)});
    }
  }
  table.print();
}

const Register registered_png("png", bench_png);

}  // namespace
}  // namespace recoil::bench
