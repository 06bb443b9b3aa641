#include "render/diff_heatmap.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "render/image_metrics.h"

namespace recoil::render {
namespace {

std::uint8_t to_byte(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

}  // namespace

Image difference_heatmap(const Image& actual, const Image& reference, double threshold) {
  if (actual.width != reference.width || actual.height != reference.height)
    throw bad_input("image size mismatch: actual is " + std::to_string(actual.width) + "x" +
                    std::to_string(actual.height) + ", reference is " + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height));
  const std::vector<double> diff = pixel_differences(actual, reference);
  const std::vector<double> luma = composited_luma(reference);
  Image heat(actual.width, actual.height);
  for (size_t i = 0; i < diff.size(); ++i) {
    const double d = diff[i];
    double r, g, b;
    if (d <= threshold) {
      const double context = 0.25 * luma[i];
      const double tint = threshold > 0.0 ? 0.5 * d / threshold : 0.0;
      r = context + tint;
      g = context;
      b = context;
    } else {
      // s in (0,1]: 0 just above the threshold, 1 at the largest difference.
      const double s = threshold < 1.0 ? (d - threshold) / (1.0 - threshold) : 1.0;
      r = 1.0;
      g = std::min(1.0, 2.0 * s);
      b = std::max(0.0, 2.0 * s - 1.0);
    }
    std::uint8_t* p = heat.rgba.data() + 4 * i;
    p[0] = to_byte(r);
    p[1] = to_byte(g);
    p[2] = to_byte(b);
    p[3] = 255;
  }
  return heat;
}

}  // namespace recoil::render
