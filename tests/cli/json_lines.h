#pragma once
// The lines of a stats.jsonl file or of a --log-json stderr, each parsed; a
// line that is not JSON is a discarded value (is_discarded()), so that a test
// can say which line broke the format.
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace recoil::test {

inline std::vector<nlohmann::json> json_lines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line, nullptr, false));
  return lines;
}

}  // namespace recoil::test
