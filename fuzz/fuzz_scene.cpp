// Fuzzes the scene file parser: JSON syntax, then validation into a SceneDesc
// (primitives are built, tetrahedralised bodies meshed). Mesh paths resolve
// against an empty folder, so only absolute paths reach a file. A scene the
// parser accepts must write out as a resolved scene that parses back to the
// same description (written again, the same document).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/json_cursor.h"
#include "cli/scene_parser.h"
#include "cli/scene_writer.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  recoil::fuzz::expect_only_bad_input([&] {
    const nlohmann::json document = recoil::cli::parse_json_text(text, "fuzz.json");
    const recoil::cli::SceneDesc scene = recoil::cli::parse_scene(document, "fuzz.json", recoil::fuzz::scratch_folder());
    const nlohmann::json written = recoil::cli::resolved_scene(scene);
    // Any failure from here on is a finding, a refusal of the written scene included.
    try {
      const recoil::cli::SceneDesc again =
          recoil::cli::parse_scene(written, "resolved.json", recoil::fuzz::scratch_folder());
      if (recoil::cli::resolved_scene(again) == written) return;
      std::fprintf(stderr, "the resolved scene does not read back alike:\n%s\n", written.dump(2).c_str());
    } catch (const recoil::Error& e) {
      std::fprintf(stderr, "the resolved scene is refused: %s\n%s\n", e.what(), written.dump(2).c_str());
    }
    std::abort();
  });
  return 0;
}
