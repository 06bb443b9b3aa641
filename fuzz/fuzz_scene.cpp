// Fuzzes the scene file parser: JSON syntax, then validation into a SceneDesc
// (primitives are built, tetrahedralised bodies meshed). Mesh paths resolve
// against an empty folder, so only absolute paths reach a file.
#include <string>

#include "cli/json_cursor.h"
#include "cli/scene_parser.h"
#include "fuzz/fuzz_input.h"

namespace {

// Known and not yet fixed: parse_json_text lets nlohmann's "number overflow"
// error (id 406, e.g. 1e400) through instead of a bad_input (reproducers in
// fuzz/unfixed/scene/); skipped so that the fuzzer gets past it. Remove when fixed.
constexpr int kKnownNumberOverflow = 406;

nlohmann::json parse_or_skip(const std::string& text, bool& skipped) {
  try {
    return recoil::cli::parse_json_text(text, "fuzz.json");
  } catch (const nlohmann::json::out_of_range& e) {
    if (e.id != kKnownNumberOverflow) throw;
    skipped = true;
    return {};
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  recoil::fuzz::expect_only_bad_input([&] {
    bool skipped = false;
    const nlohmann::json document = parse_or_skip(text, skipped);
    if (!skipped) recoil::cli::parse_scene(document, "fuzz.json", recoil::fuzz::scratch_folder());
  });
  return 0;
}
