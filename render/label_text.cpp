#include "render/label_text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <memory>
#include <mutex>

#include "core/error.h"

namespace recoil::render {
namespace {

// One FreeType library and face for the process, loaded on first use.
struct Font {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  Font() {
    if (FT_Init_FreeType(&library) != 0) throw Error(ErrorKind::internal, "cannot start FreeType");
    if (FT_New_Face(library, RECOIL_LABEL_FONT, 0, &face) != 0)
      throw bad_input(std::string(RECOIL_LABEL_FONT) + ": cannot load the label font (install fonts-dejavu-core)");
  }
  ~Font() {
    FT_Done_Face(face);
    FT_Done_FreeType(library);
  }
};

Font& font() {
  static Font instance;
  return instance;
}

// Advance of `c` in pixels (26.6 fixed point rounded).
int advance_of(FT_Face face, char c) {
  if (FT_Load_Char(face, static_cast<unsigned char>(c), FT_LOAD_DEFAULT) != 0) return 0;
  return static_cast<int>((face->glyph->advance.x + 32) >> 6);
}

void blend_glyph(Image& image, const FT_Bitmap& bitmap, int x0, int y0, int right, std::array<std::uint8_t, 3> rgb) {
  for (unsigned row = 0; row < bitmap.rows; ++row) {
    const int y = y0 + static_cast<int>(row);
    if (y < 0 || y >= image.height) continue;
    for (unsigned col = 0; col < bitmap.width; ++col) {
      const int x = x0 + static_cast<int>(col);
      if (x < 0 || x >= image.width || x > right) continue;
      const int coverage = bitmap.buffer[row * static_cast<unsigned>(bitmap.pitch) + col];
      std::uint8_t* p = image.pixel(x, y);
      for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>((rgb[k] * coverage + p[k] * (255 - coverage) + 127) / 255);
      p[3] = static_cast<std::uint8_t>(std::max<int>(p[3], coverage));
    }
  }
}

}  // namespace

void draw_label(Image& image, const std::string& text, int left, int right, int baseline, int pixel_height,
                std::array<std::uint8_t, 3> rgb) {
  static std::mutex lock;  // one FT_Face serves every caller
  const std::lock_guard<std::mutex> guard(lock);
  FT_Face face = font().face;
  FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixel_height));
  std::string shown;
  for (const char c : text) shown += static_cast<unsigned char>(c) < 0x80 && c >= ' ' ? c : '?';
  // Cut to what fits, leaving room for the ellipsis.
  int width = 0;
  for (const char c : shown) width += advance_of(face, c);
  if (left + width > right) {
    const int ellipsis = 3 * advance_of(face, '.');
    std::string cut;
    int used = 0;
    for (const char c : shown) {
      const int a = advance_of(face, c);
      if (left + used + a + ellipsis > right) break;
      cut += c;
      used += a;
    }
    shown = cut + "...";
  }
  int pen = left;
  for (const char c : shown) {
    if (FT_Load_Char(face, static_cast<unsigned char>(c), FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot g = face->glyph;
    blend_glyph(image, g->bitmap, pen + g->bitmap_left, baseline - g->bitmap_top, right, rgb);
    pen += static_cast<int>((g->advance.x + 32) >> 6);
  }
}

}  // namespace recoil::render
