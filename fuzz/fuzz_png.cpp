// Fuzzes the PNG reader (libpng, normalised to RGBA8).
#include "fuzz/fuzz_input.h"
#include "render/png.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = recoil::fuzz::write_input("input.png", data, size);
  recoil::fuzz::expect_only_bad_input([&] { recoil::render::read_png(path); });
  return 0;
}
