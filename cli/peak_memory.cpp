#include "cli/peak_memory.h"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

namespace recoil::cli {

std::optional<double> peak_memory_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmHWM:", 0) != 0) continue;
    std::istringstream fields(line.substr(6));
    double kib = 0.0;
    if (!(fields >> kib)) break;  // "VmHWM:   123456 kB"
    rusage children{};
    if (::getrusage(RUSAGE_CHILDREN, &children) == 0) kib = std::max(kib, static_cast<double>(children.ru_maxrss));
    return kib / 1024.0;
  }
  return std::nullopt;
}

}  // namespace recoil::cli
