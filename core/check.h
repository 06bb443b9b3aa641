#pragma once
// RECOIL_CHECK(cond, ...): an invariant of the code itself. On failure it prints
// the file, line, the condition and any streamed values, then aborts: a bug is
// never turned into an exception that bad input could also raise.
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace recoil::detail {
[[noreturn]] inline void check_failed(const char* file, int line, const char* cond, const std::string& what) {
  std::cerr << "recoil: internal error: " << file << ":" << line << ": check failed: " << cond;
  if (!what.empty()) std::cerr << " (" << what << ")";
  std::cerr << std::endl;
  std::abort();
}
}  // namespace recoil::detail

#define RECOIL_CHECK(cond, ...)                                                        \
  do {                                                                                 \
    if (!(cond)) {                                                                     \
      std::ostringstream recoil_check_stream_;                                         \
      recoil_check_stream_ << "" __VA_OPT__(<< __VA_ARGS__);                                 \
      ::recoil::detail::check_failed(__FILE__, __LINE__, #cond, recoil_check_stream_.str()); \
    }                                                                                  \
  } while (0)
