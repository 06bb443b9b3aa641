// Fuzzes the scene file parser: JSON syntax, then validation into a SceneDesc
// (primitives are built, tetrahedralised bodies meshed). Mesh paths resolve
// against an empty folder, so only absolute paths reach a file.
#include <string>

#include "cli/json_cursor.h"
#include "cli/scene_parser.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  recoil::fuzz::expect_only_bad_input([&] {
    const nlohmann::json document = recoil::cli::parse_json_text(text, "fuzz.json");
    recoil::cli::parse_scene(document, "fuzz.json", recoil::fuzz::scratch_folder());
  });
  return 0;
}
