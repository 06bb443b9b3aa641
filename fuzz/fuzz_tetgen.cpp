// Fuzzes the TetGen reader: the input is the .node text, a NUL byte, then the
// .ele text (no NUL: an empty .ele).
#include <string>

#include "fuzz/fuzz_input.h"
#include "sim/geometry/tet_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const size_t split = input.find('\0');
  const std::string node = input.substr(0, split);
  const std::string ele = split == std::string::npos ? std::string() : input.substr(split + 1);
  recoil::fuzz::expect_only_bad_input([&] { recoil::sim::parse_tetgen(node, "fuzz.node", ele, "fuzz.ele"); });
  return 0;
}
