#pragma once
// PNG read/write through libpng (the only includer of png.h).
#include <filesystem>

#include "render/image.h"

namespace recoil::render {

struct PngOptions {
  int level = 1;             // zlib level 0-9; 1 is fast and nearly as small for renders
  bool fast_filter = true;   // SUB filter only: about 2x faster than adaptive, ~7 % larger
  // Write the alpha channel (RGBA). False writes RGB, a quarter fewer bytes
  // to filter and deflate, for images the caller knows are opaque: every
  // frame of a run then has the same colour type.
  bool alpha = true;
};

// Encodes `image` as an 8-bit PNG into memory, RGBA or RGB (options.alpha).
std::vector<std::uint8_t> encode_png(const Image& image, const PngOptions& options = {});

// Writes atomically and durably (core/atomic_write.h): a reader never sees a
// half-written frame. Throws recoil::Error(output_failed) naming the path and
// the system's reason when the disk refuses.
void write_png(const std::filesystem::path& path, const Image& image, const PngOptions& options = {});

// Reads any PNG (grey, palette, 16-bit, with or without alpha) as RGBA8.
// Throws recoil::Error(bad_input) naming the file when it is not a PNG.
Image read_png(const std::filesystem::path& path);

}  // namespace recoil::render
