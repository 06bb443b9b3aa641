#pragma once
// How many terminal columns a UTF-8 string takes, counted as code points
// (bytes that do not continue a sequence): right for Latin, Greek and
// Cyrillic names; a wide East Asian character counts one column short.
#include <cstddef>
#include <string_view>

namespace recoil {

inline std::size_t text_columns(std::string_view text) {
  std::size_t columns = 0;
  for (char c : text) columns += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return columns;
}

}  // namespace recoil
