#pragma once
// Input files are read only when they are regular files: open() on a FIFO
// blocks until a writer appears and a device such as /dev/zero never ends, so
// both are refused (as bad_input naming the file) before anything is opened.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "core/error.h"

namespace recoil {

// Throws bad_input "PATH: cannot read WHAT: REASON" unless `path` (after
// symlinks) is a regular file. `what` is e.g. "tet mesh file".
inline void require_regular_file(const std::filesystem::path& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  const char* reason = nullptr;
  switch (status.type()) {
    case fs::file_type::regular: return;
    case fs::file_type::not_found: reason = "no such file"; break;
    case fs::file_type::directory: reason = "is a folder, not a file"; break;
    case fs::file_type::fifo: reason = "is a FIFO (named pipe), not a regular file"; break;
    case fs::file_type::character:
    case fs::file_type::block: reason = "is a device, not a regular file"; break;
    case fs::file_type::socket: reason = "is a socket, not a regular file"; break;
    default: break;
  }
  const std::string why = reason ? reason : ec ? ec.message() : "not a regular file";
  throw bad_input(path.string() + ": cannot read " + what + ": " + why);
}

// The whole content of a regular file (see require_regular_file).
inline std::string read_regular_file(const std::filesystem::path& path, const std::string& what) {
  require_regular_file(path, what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad_input(path.string() + ": cannot open " + what);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw bad_input(path.string() + ": cannot read " + what);
  return std::move(text).str();
}

}  // namespace recoil
