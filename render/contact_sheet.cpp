#include "render/contact_sheet.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/label_text.h"
#include "render/png.h"
#include "render/srgb.h"

namespace recoil::render {
namespace {

using Rgb8 = std::array<std::uint8_t, 3>;
constexpr Rgb8 kSheet = {32, 32, 32};
constexpr Rgb8 kTile = {48, 48, 48};
constexpr Rgb8 kFailedTile = {96, 24, 24};
constexpr Rgb8 kLabel = {230, 230, 230};
constexpr Rgb8 kFailedLabel = {255, 120, 110};
constexpr int kGap = 8;          // pixels between tiles and around the sheet
constexpr int kLabelHeight = 22; // pixels under each picture for its name
constexpr int kTextHeight = 13;  // pixel size of the label face

void fill(Image& image, int x0, int y0, int w, int h, Rgb8 rgb) {
  for (int y = std::max(0, y0); y < std::min(image.height, y0 + h); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x0 + w); ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2], p[3] = 255;
    }
}

void paste(Image& sheet, const Image& tile, int x0, int y0) {
  for (int y = 0; y < tile.height; ++y)
    std::copy_n(tile.pixel(0, y), static_cast<size_t>(tile.width) * 4, sheet.pixel(x0, y0 + y));
}

}  // namespace

Image fit_thumbnail(const Image& source, int width, int height, const Rgb8& background) {
  Image out(width, height);
  fill(out, 0, 0, width, height, background);
  if (source.empty()) return out;
  const double scale = std::min(static_cast<double>(width) / source.width, static_cast<double>(height) / source.height);
  const int w = std::max(1, static_cast<int>(std::lround(source.width * scale)));
  const int h = std::max(1, static_cast<int>(std::lround(source.height * scale)));
  const int x_off = (width - w) / 2, y_off = (height - h) / 2;
  const std::array<float, 3> under = srgb_to_linear(Rgb{background[0] / 255.0f, background[1] / 255.0f, background[2] / 255.0f});
  for (int ty = 0; ty < h; ++ty) {
    // Source rows and columns [begin, end) that fall into this target pixel.
    const int sy0 = ty * source.height / h, sy1 = std::max(sy0 + 1, (ty + 1) * source.height / h);
    for (int tx = 0; tx < w; ++tx) {
      const int sx0 = tx * source.width / w, sx1 = std::max(sx0 + 1, (tx + 1) * source.width / w);
      double sum[3] = {0, 0, 0};
      for (int sy = sy0; sy < sy1; ++sy)
        for (int sx = sx0; sx < sx1; ++sx) {
          const std::uint8_t* p = source.pixel(sx, sy);
          const double alpha = p[3] / 255.0;
          for (int k = 0; k < 3; ++k) sum[k] += alpha * srgb_to_linear(p[k] / 255.0f) + (1.0 - alpha) * under[k];
        }
      const double n = static_cast<double>((sy1 - sy0) * (sx1 - sx0));
      std::uint8_t* q = out.pixel(x_off + tx, y_off + ty);
      for (int k = 0; k < 3; ++k)
        q[k] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(linear_to_srgb(static_cast<float>(sum[k] / n)), 0.0f, 1.0f)));
      q[3] = 255;
    }
  }
  return out;
}

Image compose_contact_sheet(const std::vector<SheetTile>& tiles, const SheetLayout& layout) {
  const int n = std::max<int>(1, static_cast<int>(tiles.size()));
  const int tile_w = layout.thumb_width, tile_h = layout.thumb_height + kLabelHeight;
  // Columns for a sheet about 16:9 when none are asked for.
  int columns = layout.columns;
  if (columns <= 0)
    columns = std::clamp(static_cast<int>(std::ceil(std::sqrt(n * (16.0 / 9.0) * tile_h / tile_w))), 1, n);
  const int rows = (n + columns - 1) / columns;
  Image sheet(kGap + columns * (tile_w + kGap), kGap + rows * (tile_h + kGap));
  fill(sheet, 0, 0, sheet.width, sheet.height, kSheet);
  for (size_t i = 0; i < tiles.size(); ++i) {
    const SheetTile& tile = tiles[i];
    const int x0 = kGap + static_cast<int>(i % columns) * (tile_w + kGap);
    const int y0 = kGap + static_cast<int>(i / columns) * (tile_h + kGap);
    const bool failed = tile.state == SheetTile::State::failed;
    const Rgb8 ground = failed ? kFailedTile : kTile;
    std::string note = tile.note;
    Image picture;
    if (!tile.image.empty()) {
      try {
        picture = read_png(tile.image);
      } catch (const Error&) {
        note = "unreadable picture";
        picture = Image();
      }
    }
    paste(sheet, fit_thumbnail(picture, layout.thumb_width, layout.thumb_height, ground), x0, y0);
    if (failed) {  // a red frame, visible even at a glance over a big sheet
      fill(sheet, x0, y0, tile_w, 3, kFailedLabel);
      fill(sheet, x0, y0 + layout.thumb_height - 3, tile_w, 3, kFailedLabel);
      fill(sheet, x0, y0, 3, layout.thumb_height, kFailedLabel);
      fill(sheet, x0 + tile_w - 3, y0, 3, layout.thumb_height, kFailedLabel);
    }
    if (picture.empty()) {
      const int middle = y0 + layout.thumb_height / 2;
      draw_label(sheet, note, x0 + 8, x0 + tile_w - 8, middle - 2, kTextHeight, failed ? kFailedLabel : kLabel);
      draw_label(sheet, tile.detail, x0 + 8, x0 + tile_w - 8, middle + kTextHeight + 2, kTextHeight - 2, kLabel);
    }
    draw_label(sheet, tile.label, x0 + 2, x0 + tile_w - 2, y0 + layout.thumb_height + kLabelHeight - 6, kTextHeight,
               failed ? kFailedLabel : kLabel);
  }
  return sheet;
}

}  // namespace recoil::render
