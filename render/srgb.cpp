#include "render/srgb.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace recoil::render {

float srgb_to_linear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

float linear_to_srgb(float linear) {
  linear = std::clamp(linear, 0.0f, 1.0f);
  return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::array<float, 3> srgb_to_linear(const Rgb& encoded) {
  return {srgb_to_linear(encoded[0]), srgb_to_linear(encoded[1]), srgb_to_linear(encoded[2])};
}

void unpremultiply_srgb(Image& image) {
  std::array<float, 256> decode{};
  for (int i = 0; i < 256; ++i) decode[static_cast<size_t>(i)] = srgb_to_linear(static_cast<float>(i) / 255.0f);
  const size_t pixels = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  std::uint8_t* p = image.rgba.data();
  for (size_t i = 0; i < pixels; ++i, p += 4) {
    const std::uint8_t alpha = p[3];
    if (alpha == 0 || alpha == 255) continue;
    const float inverse = 255.0f / static_cast<float>(alpha);
    for (int c = 0; c < 3; ++c) {
      const float straight = linear_to_srgb(decode[p[c]] * inverse);
      p[c] = static_cast<std::uint8_t>(std::lround(straight * 255.0f));
    }
  }
}

}  // namespace recoil::render
