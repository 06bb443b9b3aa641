#pragma once
// A contact sheet: a grid of thumbnails, one per batch item, each labelled
// with its name; failed items are marked in red, items without a picture grey.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "render/image.h"

namespace recoil::render {

struct SheetTile {
  enum class State { done, failed, missing };
  std::string label;
  State state = State::missing;
  std::filesystem::path image;  // the PNG to show; empty for none
  std::string note;             // drawn in a tile without a picture ("failed, exit 2", "not run")
  std::string detail;           // a second line under the note (the error message)
};

struct SheetLayout {
  int thumb_width = 256;   // pixels of the picture area of a tile
  int thumb_height = 144;
  int columns = 0;         // 0: about as many as rows, for a roughly 16:9 sheet
};

// The sheet, opaque RGBA. A tile whose PNG cannot be read shows its note and
// the reason instead of failing the sheet.
Image compose_contact_sheet(const std::vector<SheetTile>& tiles, const SheetLayout& layout = {});

// `source` scaled to fit inside width x height (aspect kept, area-averaged in
// linear light, composited over `background`), centred on a canvas of that size.
Image fit_thumbnail(const Image& source, int width, int height, const std::array<std::uint8_t, 3>& background);

}  // namespace recoil::render
