// Fuzzes the surface import (assimp plus recoil's triangulation and welding).
// assimp picks a format by extension, so the first byte chooses one of a few
// text formats and the rest is the file.
#include <array>

#include "fuzz/fuzz_input.h"
#include "sim/geometry/mesh_import.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static constexpr std::array<const char*, 4> kNames = {"input.obj", "input.off", "input.ply", "input.stl"};
  const auto path = recoil::fuzz::write_input(kNames[data[0] % kNames.size()], data + 1, size - 1);
  recoil::fuzz::expect_only_bad_input([&] { recoil::sim::import_surface(path); });
  return 0;
}
