#pragma once
// Helpers shared by every test executable: where the sources and assets are,
// a fresh scratch folder per test, and running the recoil binary as a user would.
#include <filesystem>
#include <string>

namespace recoil::test {

// A path inside the source tree, e.g. source_path("assets/meshes/bunny.obj").
std::filesystem::path source_path(const std::string& relative);

// An empty folder unique to `name` under the build tree's test scratch area.
std::filesystem::path scratch_dir(const std::string& name);

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// A file's whole content, byte for byte ("" when it cannot be read).
std::string file_bytes(const std::filesystem::path& path);

// Writes `bytes` to `path`, replacing it.
void write_file(const std::filesystem::path& path, const std::string& bytes);

// `path` in single quotes, for the command lines of run_recoil.
std::string shell_quote(const std::filesystem::path& path);

// Runs `recoil ARGS` (ARGS is passed to /bin/sh unchanged, so quote paths)
// with stdin closed and captures both streams; `environment` ("PATH=/x")
// is set for recoil alone.
CommandResult run_recoil(const std::string& args, const std::string& environment = "");

}  // namespace recoil::test
