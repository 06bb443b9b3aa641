#pragma once
// Whether a file on disk is a whole PNG frame, without decoding it: what
// `run --resume` keeps, so a frame cut short by a crash or a full disk is
// rendered again rather than kept.
#include <filesystem>

namespace recoil::render {

// True when `path` starts with the PNG signature and an IHDR of exactly
// width x height, and its chunks follow each other to an IEND that ends the
// file. False for anything else, a missing or unreadable file included.
bool is_whole_png(const std::filesystem::path& path, int width, int height);

}  // namespace recoil::render
