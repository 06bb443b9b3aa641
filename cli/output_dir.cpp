#include "cli/output_dir.h"

#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;

fs::path default_output_dir(const std::string& name) { return fs::path("output") / name; }

void ensure_output_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw output_error("cannot create output folder " + dir.string() + (ec ? ": " + ec.message() : ""));
}

}  // namespace recoil::cli
