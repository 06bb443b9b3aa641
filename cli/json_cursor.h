#pragma once
// JsonCursor: one value inside a parsed JSON document together with its JSON
// pointer, for validating scene files (pbrt style: every error names the file
// and the field).
#include <Eigen/Core>
#include <cmath>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/scene_limits.h"

namespace recoil::cli {

// Parses `text` (the contents of `file`); syntax errors throw bad_input as
// "FILE:LINE:COLUMN: syntax error: ...", and a number beyond double range as
// "FILE: /POINTER: ..." naming the field it was given for, as is a key given
// twice in one object (which the parser would otherwise take the last of).
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

// [x, y, z] for scene files and stats.
inline nlohmann::json json_vec3(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

// The closest of `candidates` to `word` when it is a plausible typo, else "".
std::string near_miss(std::string_view word, const std::vector<std::string>& candidates);

class JsonCursor {
 public:
  // `in` must outlive the cursor and every child.
  JsonCursor(const nlohmann::json& in, std::string file, std::string pointer = "");

  const nlohmann::json& value() const { return *m_in; }
  const std::string& pointer() const { return m_pointer; }
  const std::string& file() const { return m_file; }

  // Throws bad_input "FILE: /POINTER: message".
  [[noreturn]] void fail(const std::string& message) const;
  // fail("expected EXPECTED, got" the value's type and an excerpt of it).
  [[noreturn]] void type_error(const char* expected) const;

  // Requires an object whose keys are all in `allowed`; an unknown key fails
  // with a near-miss suggestion ("did you mean ...?").
  void expect_object(const std::vector<std::string>& allowed) const;
  bool is_number() const { return m_in->is_number(); }
  bool is_array() const { return m_in->is_array(); }
  bool has(const std::string& key) const { return m_in->is_object() && m_in->contains(key); }

  // The member `key` (which must exist; fails "is required" otherwise).
  JsonCursor child(const std::string& key) const;
  // The member `key`, or an empty object standing in for it when absent (so
  // that its members' defaults apply).
  JsonCursor child_or_empty(const std::string& key) const;
  // An array's elements (fails unless an array, optionally of `size` elements).
  std::vector<JsonCursor> elements(std::optional<size_t> size = std::nullopt) const;

  // Leaves: type-checked and range-checked.
  // Every number a scene gives has a stated range (cli/scene_limits.h).
  bool boolean() const;
  std::string string() const;
  double number_in(const Range& range) const;
  int integer_in(int lo, int hi) const;
  // Each of the three components in `component`.
  Eigen::Vector3d vec3_in(const Range& component) const;

  // Optional members: the default when absent.
  double number_in_or(const std::string& key, double fallback, const Range& range) const;
  int integer_in_or(const std::string& key, int fallback, int lo, int hi) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  std::string string_or(const std::string& key, const std::string& fallback) const;
  Eigen::Vector3d vec3_in_or(const std::string& key, const Eigen::Vector3d& fallback, const Range& component) const;

 private:
  double number() const;  // finite, not yet range-checked

  const nlohmann::json* m_in;
  std::string m_file;
  std::string m_pointer;
};

// JSON's name for the type of `value` ("a string", "an array", ...), for messages.
std::string json_type_name(const nlohmann::json& value);

}  // namespace recoil::cli
