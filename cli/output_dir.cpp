#include "cli/output_dir.h"

#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <vector>

#include "cli/frame_names.h"
#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;

fs::path default_output_dir(const std::string& name) { return fs::path("output") / name; }

void ensure_output_dir(const fs::path& dir) {
  std::error_code ec;
  // A file where the folder should be is a mistake in the command, not a failure a retry may get past.
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw bad_input(dir.string() + " is a file, not a folder: name a folder for the output");
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

namespace recoil::cli {

RemovedFrames remove_foreign_frames(const fs::path& dir, int frame_count, const std::vector<int>* only) {
  // frame_ + digits + .png as some run names its frames, and not a name this run's frames have.
  const auto is_foreign_frame = [frame_count, only](const std::string& name, long& number) {
    const std::string prefix = "frame_", suffix = ".png";
    if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      return false;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    // Four digits at least, as every run names its frames.
    if (digits.size() < 4 || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return false;
    number = std::stol(digits);
    if (number < 1 || number > frame_count || frame_file_name(static_cast<int>(number), frame_count) != name)
      return true;
    return only != nullptr && !std::binary_search(only->begin(), only->end(), static_cast<int>(number));
  };
  std::vector<std::pair<long, fs::path>> foreign;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    long number = 0;
    if (is_foreign_frame(it->path().filename().string(), number)) foreign.emplace_back(number, it->path());
  }
  if (ec) throw output_error("cannot list output folder " + dir.string() + ": " + ec.message());
  std::sort(foreign.begin(), foreign.end());
  RemovedFrames removed;
  for (const auto& [number, path] : foreign) {
    std::error_code remove_ec;
    fs::remove(path, remove_ec);
    if (remove_ec) throw output_error("cannot remove " + path.string() + " (a frame of an earlier run): " + remove_ec.message());
    if (removed.count++ == 0) removed.first = path.filename().string();
    removed.last = path.filename().string();
  }
  return removed;
}

}  // namespace recoil::cli
