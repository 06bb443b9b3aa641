#include "cli/output_dir.h"

#include <signal.h>

#include <cerrno>
#include <cstdlib>

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

int remove_stale_temporaries(const fs::path& dir) {
  // NAME.tmp-PID-N is stale once process PID is gone; another run still
  // writing into the same folder keeps its own.
  const auto is_stale_temporary = [](const std::string& name) {
    const bool ours = (name.rfind("frame_", 0) == 0 && name.find(".png.tmp-") != std::string::npos) ||
                      name.rfind("scene.json.tmp-", 0) == 0 || name.rfind("run.json.tmp-", 0) == 0;
    if (!ours) return false;
    const long pid = std::strtol(name.c_str() + name.find(".tmp-") + 5, nullptr, 10);
    return pid <= 0 || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH);
  };
  std::error_code ec;
  int removed = 0;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!is_stale_temporary(it->path().filename().string())) continue;
    std::error_code remove_ec;
    fs::remove(it->path(), remove_ec);
    if (remove_ec) throw output_error("cannot remove stale " + it->path().string() + ": " + remove_ec.message());
    ++removed;
  }
  if (ec) throw output_error("cannot list output folder " + dir.string() + ": " + ec.message());
  return removed;
}

}  // namespace recoil::cli
