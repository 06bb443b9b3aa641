#pragma once
// An option's numeric range, checked with the words the scene file's checks
// use ("must be in [1, 170], got 0"; CLI11's own Range says "Value abc not in
// range 1.000000 to 170.000000", even of a word that is no number).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "cli/format_number.h"

namespace recoil::cli {

// `text`, all of it, as a number (as strtod reads one, NaN refused); nothing otherwise.
inline std::optional<double> number_from_text(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || std::isnan(value)) return std::nullopt;
  return value;
}

// `text` as a base-10 integer (all of it, in range of long long); nothing otherwise.
inline std::optional<long long> whole_number_from_text(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE) return std::nullopt;
  return value;
}

class NumberIn : public CLI::Validator {
 public:
  NumberIn(double least, double most) {
    const std::string range = "[" + format_number("%.10g", least) + ", " + format_number("%.10g", most) + "]";
    description("in " + range);
    func_ = [least, most, range](std::string& text) -> std::string {
      const std::optional<double> value = number_from_text(text);
      if (!value) return "must be a number in " + range + ", got '" + text + "'";
      if (*value < least || *value > most) return "must be in " + range + ", got " + text;
      return std::string();
    };
  }
};

// A finite number above `least` (not equal to it), in the same words.
class NumberAbove : public CLI::Validator {
 public:
  explicit NumberAbove(double least) {
    const std::string bound = format_number("%.10g", least);
    description("above " + bound);
    func_ = [least, bound](std::string& text) -> std::string {
      const std::optional<double> value = number_from_text(text);
      if (!value) return "must be a number above " + bound + ", got '" + text + "'";
      if (!(*value > least) || std::isinf(*value)) return "must be a finite number above " + bound + ", got " + text;
      return std::string();
    };
  }
};

// NumberIn for an integer option: "1.5" or "1e3" is refused in the same
// words ("must be a whole number in [1, 1000]"), not by CLI11's conversion.
class WholeNumberIn : public CLI::Validator {
 public:
  WholeNumberIn(long long least, long long most) {
    const std::string range = "[" + std::to_string(least) + ", " + std::to_string(most) + "]";
    description("in " + range);
    func_ = [least, most, range](std::string& text) -> std::string {
      const std::optional<long long> value = whole_number_from_text(text);
      if (!value) return "must be a whole number in " + range + ", got '" + text + "'";
      if (*value < least || *value > most) return "must be in " + range + ", got " + text;
      return std::string();
    };
  }
};

}  // namespace recoil::cli
