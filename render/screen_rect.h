#pragma once
// ScreenRect: the pixels a box in the world can cover once projected, so a
// pass can be scissored to the part of the frame where its geometry is.
#include <Eigen/Core>

namespace recoil::render {

// Pixels [x0, x1) by [y0, y1), rows from the bottom (as glScissor takes them).
struct ScreenRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

// The pixels of a width x height target where the box [lo, hi] (metres) can
// show through `view_projection` (world to clip, 4 by 4), grown by `pad`
// pixels each way and clamped to the target; the whole target when a corner
// is at or behind the eye, where the projection no longer bounds it.
ScreenRect screen_rect(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Matrix4f& view_projection,
                       int width, int height, int pad);

// Turns the scissor test on, limited to `rect`.
void scissor_to(const ScreenRect& rect);

}  // namespace recoil::render
