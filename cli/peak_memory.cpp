#include "cli/peak_memory.h"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

namespace recoil::cli {

namespace {

// KiB of a "Name:   123456 kB" line of /proc/self/status.
std::optional<double> status_kib(const std::string& name) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(name, 0) != 0) continue;
    std::istringstream fields(line.substr(name.size()));
    double kib = 0.0;
    if (!(fields >> kib)) break;
    return kib;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> peak_memory_mib() {
  std::optional<double> kib = status_kib("VmHWM:");
  if (!kib) return std::nullopt;
  rusage children{};
  if (::getrusage(RUSAGE_CHILDREN, &children) == 0) *kib = std::max(*kib, static_cast<double>(children.ru_maxrss));
  return *kib / 1024.0;
}

std::optional<double> resident_memory_mib() {
  const std::optional<double> kib = status_kib("VmRSS:");
  if (!kib) return std::nullopt;
  return *kib / 1024.0;
}

}  // namespace recoil::cli
