#pragma once
// Image: what the renderer draws into and reads textures from (core/rgba_image.h).
#include "core/rgba_image.h"

namespace recoil::render {

using Image = RgbaImage;

}  // namespace recoil::render
