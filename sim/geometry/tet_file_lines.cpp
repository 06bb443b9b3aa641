#include "sim/geometry/tet_file_lines.h"

#include <charconv>
#include <cmath>

namespace recoil::sim::detail {

LineReader::LineReader(const std::string& text, std::string name, char comment)
    : m_text(text), m_name(std::move(name)), m_comment(comment) {}

bool LineReader::next(std::vector<std::string_view>& tokens) {
  tokens.clear();
  while (m_pos < m_text.size()) {
    size_t end = m_text.find('\n', m_pos);
    if (end == std::string::npos) end = m_text.size();
    std::string_view line(m_text.data() + m_pos, end - m_pos);
    m_pos = end + 1;
    ++m_line;
    if (m_comment) {
      const size_t c = line.find(m_comment);
      if (c != std::string_view::npos) line = line.substr(0, c);
    }
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
      if (j > i) tokens.push_back(line.substr(i, j - i));
      i = j;
    }
    if (!tokens.empty()) return true;
  }
  return false;
}

std::vector<std::string_view> LineReader::expect(const char* what) {
  std::vector<std::string_view> tokens;
  if (!next(tokens)) {
    ++m_line;
    fail(std::string("unexpected end of file, expected ") + what);
  }
  return tokens;
}

void LineReader::fail(const std::string& what) const {
  throw bad_input(m_name + ":" + std::to_string(m_line) + ": " + what);
}

double LineReader::to_double(std::string_view token, const char* what) const {
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || ptr != token.data() + token.size() || !std::isfinite(value))
    fail(std::string("bad number '") + std::string(token.substr(0, 32)) + "' for " + what);
  return value;
}

long long LineReader::to_int(std::string_view token, const char* what) const {
  long long value = 0;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || ptr != token.data() + token.size())
    fail(std::string("bad integer '") + std::string(token.substr(0, 32)) + "' for " + what);
  return value;
}

long long LineReader::to_count(std::string_view token, const char* what, long long limit) const {
  const long long value = to_int(token, what);
  if (value < 0 || value > limit)
    fail(std::string(what) + " " + std::to_string(value) + " is out of range (0.." + std::to_string(limit) + ")");
  return value;
}

long long LineReader::declared_count(std::string_view token, const char* what, long long min_bytes) const {
  const long long value = to_int(token, what);
  if (value < 0) fail(std::string("negative count ") + std::to_string(value) + " of " + what);
  const long long size = static_cast<long long>(m_text.size());
  if (value > size / min_bytes)
    fail("declares " + std::to_string(value) + " " + what + ", more than the file's " + std::to_string(size) +
         " bytes can hold (at least " + std::to_string(min_bytes) + " bytes each)");
  return value;
}

}  // namespace recoil::sim::detail
