#pragma once
// RgbaImage: 8-bit RGBA pixels, row-major, top row first (the order image
// files store). Colour values are sRGB-encoded, alpha is straight (not
// premultiplied). The renderer's frames and a mesh's textures are both this.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace recoil {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes

  RgbaImage() = default;
  RgbaImage(int w, int h) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0) {}

  std::uint8_t* pixel(int x, int y) { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<size_t>(y) * width + x) * 4;
  }
  bool empty() const { return width == 0 || height == 0; }
};

}  // namespace recoil
