#include "render/screen_rect.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/gl.h"

namespace recoil::render {

ScreenRect screen_rect(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Matrix4f& view_projection,
                       int width, int height, int pad) {
  const ScreenRect whole{0, 0, width, height};
  Eigen::Vector2d ndc_lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), ndc_hi = -ndc_lo;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector4d p(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z(),
                            1.0);
    const Eigen::Vector4d clip = view_projection.cast<double>() * p;
    if (!(clip.w() > 1e-9)) return whole;
    const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
    ndc_lo = ndc_lo.cwiseMin(ndc);
    ndc_hi = ndc_hi.cwiseMax(ndc);
  }
  auto pixel = [](double ndc, int size) {
    return std::clamp((0.5 * std::clamp(ndc, -2.0, 2.0) + 0.5) * size, 0.0, static_cast<double>(size));
  };
  return {std::max(static_cast<int>(std::floor(pixel(ndc_lo.x(), width))) - pad, 0),
          std::max(static_cast<int>(std::floor(pixel(ndc_lo.y(), height))) - pad, 0),
          std::min(static_cast<int>(std::ceil(pixel(ndc_hi.x(), width))) + pad, width),
          std::min(static_cast<int>(std::ceil(pixel(ndc_hi.y(), height))) + pad, height)};
}

void scissor_to(const ScreenRect& rect) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x0, rect.y0, std::max(rect.width(), 0), std::max(rect.height(), 0));
}

}  // namespace recoil::render
