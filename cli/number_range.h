#pragma once
// An option's numeric range, checked with the words the scene file's checks
// use ("must be in [1, 170], got 0"; CLI11's own Range says "Value abc not in
// range 1.000000 to 170.000000", even of a word that is no number).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

#include "cli/format_number.h"

namespace recoil::cli {

class NumberIn : public CLI::Validator {
 public:
  NumberIn(double least, double most) {
    const std::string range = "[" + format_number("%.10g", least) + ", " + format_number("%.10g", most) + "]";
    description("in " + range);
    func_ = [least, most, range](std::string& text) -> std::string {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || std::isnan(value))
        return "must be a number in " + range + ", got '" + text + "'";
      if (value < least || value > most) return "must be in " + range + ", got " + text;
      return std::string();
    };
  }
};

}  // namespace recoil::cli
