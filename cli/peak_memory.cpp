#include "cli/peak_memory.h"

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
    if (fields >> kib) return kib / 1024.0;  // "VmHWM:   123456 kB"
  }
  return std::nullopt;
}

}  // namespace recoil::cli
