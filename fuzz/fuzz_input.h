#pragma once
// Helpers shared by the fuzz targets: the readers that take a path get the
// input as a file in a scratch folder of this process, and every reader may
// only ever fail with recoil's bad_input error.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"

namespace recoil::fuzz {

// A folder of this process, removed at exit (one per process, so parallel
// fuzzers never share inputs); the pid is padded so that the path, which the
// readers parse, has the same length in every run.
inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    char name[32];
    std::snprintf(name, sizeof name, "recoil-fuzz-%010d", static_cast<int>(::getpid()));
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::create_directories(dir);
    std::atexit([] { std::error_code ignored; std::filesystem::remove_all(scratch_folder(), ignored); });
    return dir;
  }();
  return folder;
}

// Writes `size` bytes to scratch_folder()/`name` and returns its path.
inline std::filesystem::path write_input(const std::string& name, const uint8_t* data, size_t size) {
  const std::filesystem::path path = scratch_folder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) std::abort();  // a full scratch disk is no finding of the reader
  return path;
}

// Runs `read`; a recoil error of another kind than bad_input is a finding
// (any other exception already is one: libFuzzer reports it as a crash).
template <typename F>
void expect_only_bad_input(F&& read) {
  try {
    read();
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::bad_input) {
      std::fprintf(stderr, "reader failed with error kind %d: %s\n", e.exit_code(), e.what());
      std::abort();
    }
  }
}

}  // namespace recoil::fuzz
