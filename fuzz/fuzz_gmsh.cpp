// Fuzzes the Gmsh .msh reader (ASCII 2.x, 4.0, 4.1) over file contents.
#include <string>

#include "fuzz/fuzz_input.h"
#include "sim/geometry/tet_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  recoil::fuzz::expect_only_bad_input([&] { recoil::sim::parse_gmsh(text, "fuzz.msh"); });
  return 0;
}
