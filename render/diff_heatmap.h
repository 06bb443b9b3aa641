#pragma once
// Heat map of the per-pixel difference between two images (`compare
// --diff`): what a reviewer looks at to see where a frame changed.
#include <cstddef>  // render/image.h uses size_t without including it

#include "render/image.h"

namespace recoil::render {

// An opaque image the size of the inputs. Passing pixels (difference <=
// threshold) show the reference's luma dimmed to a quarter, tinted red in
// proportion to difference/threshold, so the scene stays recognisable and
// small drifts are faintly visible. Failing pixels jump to full brightness on
// a red -> yellow -> white ramp over (threshold, 1], so even a single failing
// pixel stands out. Throws recoil::Error(bad_input) when the sizes differ.
Image difference_heatmap(const Image& actual, const Image& reference, double threshold);

}  // namespace recoil::render
