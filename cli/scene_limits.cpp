#include "cli/scene_limits.h"

#include <algorithm>
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

std::string name_from_stem(const std::string& stem) {
  std::string name;
  for (const char c : stem) {
    const auto byte = static_cast<unsigned char>(c);
    name += byte < 0x20 || byte == 0x7f ? '_' : c;
  }
  size_t end = std::min(name.size(), static_cast<size_t>(kMaxNameBytes - kNameSuffixBytes));
  // Back off UTF-8 continuation bytes (10xxxxxx) so that no character is cut in two.
  while (end > 0 && end < name.size() && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) --end;
  name.resize(end);
  if (name.empty() || name == "." || name == "..") return "mesh";
  return name;
}

}  // namespace recoil::cli
