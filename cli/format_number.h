#pragma once
// One number through a printf pattern ("%.4f"), for tables and reports.
#include <cstdio>
#include <string>

namespace recoil::cli {

inline std::string format_number(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

}  // namespace recoil::cli
