// Fuzzes the surface import (assimp plus recoil's triangulation and welding).
// assimp picks a format by extension, so the first byte chooses one of a few
// text formats and the rest is the file.
#include <sanitizer/common_interface_defs.h>

#include <array>
#include <csignal>

#include "fuzz/fuzz_input.h"
#include "sim/geometry/isolated_reader.h"
#include "sim/geometry/mesh_import.h"

namespace {

// assimp reads in a child process, and its crash there is the file's fault,
// answered by the parent as bad input; without this the child would run the
// crash reporting it inherits (the sanitizer's death callback, libFuzzer's
// signal handlers) and write the input as a finding.
void leave_crashes_to_the_parent() {
  __sanitizer_set_death_callback(nullptr);
  for (const int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGILL, SIGFPE}) std::signal(sig, SIG_DFL);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  recoil::sim::set_reader_child_setup(leave_crashes_to_the_parent);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static constexpr std::array<const char*, 4> kNames = {"input.obj", "input.off", "input.ply", "input.stl"};
  const auto path = recoil::fuzz::write_input(kNames[data[0] % kNames.size()], data + 1, size - 1);
  recoil::fuzz::expect_only_bad_input([&] { recoil::sim::import_surface(path); });
  return 0;
}
