#pragma once
// Line-by-line tokenising shared by the tet file readers: every token knows its
// line so that errors can say "file:line: what".
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace recoil::sim::detail {

class LineReader {
 public:
  // `comment`: a character that starts a comment to end of line, or 0.
  LineReader(const std::string& text, std::string name, char comment);

  // The tokens of the next non-empty line; false at end of text.
  bool next(std::vector<std::string_view>& tokens);
  // Like next() but a missing line is an error saying what was expected.
  std::vector<std::string_view> expect(const char* what);

  int line() const { return m_line; }
  [[noreturn]] void fail(const std::string& what) const;

  double to_double(std::string_view token, const char* what) const;
  long long to_int(std::string_view token, const char* what) const;
  // A count that must fit in [0, limit]: protects allocations from garbage.
  long long to_count(std::string_view token, const char* what, long long limit) const;
  // A count declared by a header, of items that take at least `min_bytes`
  // each: more than the whole text could hold is an error naming the count,
  // checked before anything is allocated for them.
  long long declared_count(std::string_view token, const char* what, long long min_bytes) const;

 private:
  const std::string& m_text;
  std::string m_name;
  char m_comment;
  size_t m_pos = 0;
  int m_line = 0;
};

}  // namespace recoil::sim::detail
