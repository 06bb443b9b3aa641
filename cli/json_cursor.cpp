#include "cli/json_cursor.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

#include "core/error.h"

namespace recoil::cli {
namespace {

std::string escape_pointer_token(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string short_number(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// `text` as a JSON string (control characters escaped, so nothing reaches the
// terminal raw), cut to its first 60 bytes.
std::string quoted_excerpt(const std::string& text) {
  constexpr size_t kShown = 60;
  const nlohmann::json shown = text.size() <= kShown ? text : text.substr(0, kShown);
  return shown.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + (text.size() > kShown ? "..." : "");
}

// Byte `offset` of `text` as 1-based line and column.
std::pair<size_t, size_t> line_and_column(const std::string& text, size_t offset) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

// A SAX reader that only follows where it is in the document, so that what
// the DOM parser cannot place (a number overflowing a double) or lets pass
// (a key given twice) can be given its JSON pointer.
class PointerTracker : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string pointer() const {
    std::string out;
    for (const Level& level : m_levels) {
      if (level.is_array) out += "/" + std::to_string(level.index);
      else if (level.has_key) out += "/" + escape_pointer_token(level.key);
    }
    return out.empty() ? "/" : out;
  }
  size_t error_offset() const { return m_error_offset; }
  // The pointer of the first key given twice in one object; empty when none is.
  const std::string& duplicate() const { return m_duplicate; }

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& name) override {
    Level& level = m_levels.back();
    level.key = name;
    level.has_key = true;
    // A key given twice stops the parse: the parser keeps the last silently.
    if (!level.keys.insert(name).second) {
      m_duplicate = pointer();
      return false;
    }
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) override {
    m_error_offset = position;
    return false;
  }

 private:
  struct Level {
    bool is_array = false;
    size_t index = 0;
    bool has_key = false;
    std::string key;
    std::set<std::string> keys;  // an object's keys so far
  };
  bool open(bool is_array) {
    m_levels.push_back({is_array, 0, false, {}, {}});
    return true;
  }
  bool close() {
    m_levels.pop_back();
    return value();
  }
  // A value (or a whole container) ended: an array moves to its next element.
  bool value() {
    if (!m_levels.empty() && m_levels.back().is_array) ++m_levels.back().index;
    return true;
  }
  std::vector<Level> m_levels;
  size_t m_error_offset = 0;
  std::string m_duplicate;
};

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  try {
    nlohmann::json document = nlohmann::json::parse(text);
    PointerTracker tracker;
    nlohmann::json::sax_parse(text, &tracker);
    if (!tracker.duplicate().empty())
      throw bad_input(file + ": " + tracker.duplicate() + ": given twice in one object; keep one");
    return document;
  } catch (const nlohmann::json::out_of_range&) {
    // Only a number too large for a double is out of range while parsing.
    PointerTracker tracker;
    nlohmann::json::sax_parse(text, &tracker);
    // The SAX position is just past the number, as parse_error's byte is.
    const auto [line, column] = line_and_column(text, tracker.error_offset() > 0 ? tracker.error_offset() - 1 : 0);
    throw bad_input(file + ": " + tracker.pointer() + ": number beyond the range of a double (line " +
                    std::to_string(line) + ", column " + std::to_string(column) + ")");
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character.
    const auto [line, column] = line_and_column(text, e.byte > 0 ? static_cast<size_t>(e.byte - 1) : size_t{0});
    std::string what = e.what();
    // nlohmann prefixes "[json.exception.parse_error.101] parse error at line L, column C: "
    const size_t colon = what.find(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw bad_input(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": syntax error: " + what);
  }
}

std::string near_miss(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::string json_type_name(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::binary: return "binary data";
    case nlohmann::json::value_t::discarded: return "nothing";
    default: return "a number";
  }
}

JsonCursor::JsonCursor(const nlohmann::json& in, std::string file, std::string pointer)
    : m_in(&in), m_file(std::move(file)), m_pointer(std::move(pointer)) {}

void JsonCursor::fail(const std::string& message) const {
  throw bad_input(m_file + ": " + (m_pointer.empty() ? "/" : m_pointer) + ": " + message);
}

void JsonCursor::type_error(const char* expected) const {
  std::string got = json_type_name(*m_in);
  if (m_in->is_string()) got += " " + quoted_excerpt(m_in->get<std::string>());
  else if (m_in->is_number() || m_in->is_boolean()) got += " " + m_in->dump();
  fail(std::string("expected ") + expected + ", got " + got);
}

void JsonCursor::expect_object(const std::vector<std::string>& allowed) const {
  if (!m_in->is_object()) type_error("an object");
  for (const auto& [key, value] : m_in->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    const std::string suggestion = near_miss(key, allowed);
    std::string message = "unknown key " + quoted_excerpt(key);
    if (!suggestion.empty()) message += "; did you mean \"" + suggestion + "\"?";
    else {
      message += "; expected one of";
      for (const std::string& a : allowed) message += " " + a;
    }
    JsonCursor(value, m_file, m_pointer + "/" + escape_pointer_token(key)).fail(message);
  }
}

JsonCursor JsonCursor::child(const std::string& key) const {
  if (!m_in->is_object()) type_error("an object");
  const std::string pointer = m_pointer + "/" + escape_pointer_token(key);
  const auto it = m_in->find(key);
  if (it == m_in->end()) JsonCursor(*m_in, m_file, pointer).fail("is required");
  return JsonCursor(*it, m_file, pointer);
}

JsonCursor JsonCursor::child_or_empty(const std::string& key) const {
  if (has(key)) return child(key);
  static const nlohmann::json empty = nlohmann::json::object();
  return JsonCursor(empty, m_file, m_pointer + "/" + escape_pointer_token(key));
}

std::vector<JsonCursor> JsonCursor::elements(std::optional<size_t> size) const {
  if (!m_in->is_array()) type_error("an array");
  if (size && m_in->size() != *size)
    fail("expected " + std::to_string(*size) + " elements, got " + std::to_string(m_in->size()));
  std::vector<JsonCursor> out;
  for (size_t i = 0; i < m_in->size(); ++i)
    out.emplace_back((*m_in)[i], m_file, m_pointer + "/" + std::to_string(i));
  return out;
}

double JsonCursor::number() const {
  if (!m_in->is_number()) type_error("a number");
  const double x = m_in->get<double>();
  if (!std::isfinite(x)) fail("must be finite");
  return x;
}

int JsonCursor::integer_in(int lo, int hi) const {
  if (!m_in->is_number_integer()) type_error("an integer");
  // Compared as a double, exact for every int, so no 64-bit value wraps.
  const double x = m_in->get<double>();
  if (x < lo || x > hi) fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + m_in->dump());
  return static_cast<int>(x);
}

bool JsonCursor::boolean() const {
  if (!m_in->is_boolean()) type_error("true or false");
  return m_in->get<bool>();
}

std::string JsonCursor::string() const {
  if (!m_in->is_string()) type_error("a string");
  return m_in->get<std::string>();
}

Eigen::Vector3d JsonCursor::vec3_in(const Range& component) const {
  if (!m_in->is_array()) type_error("an array of 3 numbers");
  if (m_in->size() != 3) fail("expected 3 numbers [x, y, z], got " + std::to_string(m_in->size()));
  Eigen::Vector3d v;
  const auto items = elements(3);
  for (int k = 0; k < 3; ++k) v[k] = items[static_cast<size_t>(k)].number_in(component);
  return v;
}

double JsonCursor::number_in(const Range& range) const {
  const double x = number();
  if (!range.contains(x)) fail("must be " + range.describe() + ", got " + short_number(x));
  return x;
}

double JsonCursor::number_in_or(const std::string& key, double fallback, const Range& range) const {
  if (has(key)) return child(key).number_in(range);
  return fallback;
}

int JsonCursor::integer_in_or(const std::string& key, int fallback, int lo, int hi) const {
  if (has(key)) return child(key).integer_in(lo, hi);
  return fallback;
}

bool JsonCursor::boolean_or(const std::string& key, bool fallback) const {
  if (has(key)) return child(key).boolean();
  return fallback;
}

std::string JsonCursor::string_or(const std::string& key, const std::string& fallback) const {
  if (has(key)) return child(key).string();
  return fallback;
}

Eigen::Vector3d JsonCursor::vec3_in_or(const std::string& key, const Eigen::Vector3d& fallback,
                                       const Range& component) const {
  if (has(key)) return child(key).vec3_in(component);
  return fallback;
}

}  // namespace recoil::cli
