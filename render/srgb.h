#pragma once
// sRGB transfer functions (IEC 61966-2-1) and the un-premultiply step of a
// transparent-background frame.
#include <array>

#include "render/image.h"
#include "render/render_scene.h"

namespace recoil::render {

float srgb_to_linear(float encoded);
float linear_to_srgb(float linear);
std::array<float, 3> srgb_to_linear(const Rgb& encoded);

// The framebuffer holds premultiplied colour (sRGB-encoded linear * alpha);
// Image wants straight alpha. Rewrites every pixel with 0 < alpha < 255:
// decode, divide by alpha, encode. Opaque and empty pixels are untouched.
void unpremultiply_srgb(Image& image);

}  // namespace recoil::render
