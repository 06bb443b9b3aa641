#include "cli/scene_limits.h"

#include <cmath>

#include "cli/format_number.h"

namespace recoil::cli {

std::string Range::describe() const {
  if (std::isinf(hi)) return (open_lo ? "> " : ">= ") + format_number("%g", lo);
  return std::string("in ") + (open_lo ? "(" : "[") + format_number("%g", lo) + ", " + format_number("%g", hi) +
         (open_hi ? ")" : "]");
}

std::string unsafe_name_reason(const std::string& name) {
  if (name.empty()) return "must not be empty";
  if (name == "." || name == "..") return "must be a folder name, not \"" + name + "\"";
  if (name.size() > static_cast<size_t>(kMaxNameBytes))
    return "must be at most " + std::to_string(kMaxNameBytes) + " bytes, got " + std::to_string(name.size());
  for (const char c : name) {
    if (c == '/') return "must not contain '/'";
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) return "must not contain control characters";
  }
  return "";
}

}  // namespace recoil::cli
