#pragma once
// Text drawn into an Image through FreeType (the only includer of its
// headers), in the face the build names (DejaVu Sans by default): the labels
// of contact sheets.
#include <array>
#include <cstdint>
#include <string>

#include "render/image.h"

namespace recoil::render {

// Draws `text` (UTF-8; bytes outside ASCII drawn as '?') with its baseline at
// pixel row `baseline`, starting at column `left`, `pixel_height` pixels tall,
// blended over `image` in `rgb`; glyphs that would pass column `right` are cut
// and the text ends in "..." instead. Throws bad_input naming the font when it
// cannot be loaded.
void draw_label(Image& image, const std::string& text, int left, int right, int baseline, int pixel_height,
                std::array<std::uint8_t, 3> rgb);

}  // namespace recoil::render
