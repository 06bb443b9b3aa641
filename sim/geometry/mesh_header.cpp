// PLY: "ply", "format ascii|binary_* 1.0", then "element NAME COUNT" each
// followed by its "property TYPE NAME" / "property list COUNT_TYPE ITEM_TYPE NAME"
// lines, up to "end_header". OFF: "[ST][C][N][4][n]OFF", then "vertices faces edges".
#include "sim/geometry/mesh_header.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace recoil::sim {
namespace {

// The leading digits of `token`, as assimp reads them ("12x" is 12); too many digits read as the largest count.
bool parse_count(const std::string& token, std::uint64_t& value) {
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec == std::errc::result_out_of_range) value = UINT64_MAX;
  return ptr != token.data();
}

// assimp matches the PLY magic regardless of case ("Ply").
std::string lower_case(std::string word) {
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word;
}

// Bytes of one binary PLY value of `type` (unknown names count as 1).
std::uint64_t ply_type_bytes(const std::string& type) {
  for (const char* t : {"short", "ushort", "int16", "uint16"})
    if (type == t) return 2;
  for (const char* t : {"int", "uint", "float", "int32", "uint32", "float32"})
    if (type == t) return 4;
  for (const char* t : {"double", "float64", "int64", "uint64"})
    if (type == t) return 8;
  return 1;
}

[[noreturn]] void refuse_counts(const std::string& name, const std::string& declared, std::uintmax_t file_size) {
  throw bad_input(name + ": declares " + declared + ", more than its " + std::to_string(file_size) +
                  " bytes can hold");
}

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_bytes = 0;  // of one element: 2 per ASCII value ("0 "), the type's size in binary
};

void check_ply(const std::string& head, std::uintmax_t file_size, const std::string& name) {
  std::istringstream lines(head);
  std::string line;
  std::getline(lines, line);  // "ply"
  bool ascii = true;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (!ended && std::getline(lines, line)) {
    std::istringstream words(line);
    std::string keyword, a, b;
    words >> keyword >> a >> b;  // b: a list's count type
    // Only "end_header" at the start of a line, then the line's end, a space, tab, CR, form
    // feed or NUL (assimp 5.2's blanks): it hangs on near misses ("end_hEader", "end_header\v").
    ended = line.rfind("end_header", 0) == 0 &&
            (line.size() == 10 || std::string_view(" \t\r\f", 5).find(line[10]) != std::string_view::npos);
    if (keyword == "format") {
      ascii = a == "ascii";
    } else if (keyword == "element") {
      // The largest number on the line: assimp finds the count even where the name is missing.
      PlyElement e{a, 0, 0};
      std::istringstream rest(line);
      for (std::string word; rest >> word;)
        if (std::uint64_t n = 0; parse_count(word, n)) e.count = std::max(e.count, n);
      elements.push_back(e);
    } else if (keyword == "property" && !elements.empty()) {
      elements.back().min_bytes += ascii ? 2 : ply_type_bytes(a == "list" ? b : a);  // a list may be empty
    }
  }
  // Without one, assimp 5.2 searches for it forever.
  if (!ended)
    throw bad_input(name + ": PLY header without end_header in its first " + std::to_string(head.size()) + " bytes");
  long double needed = 0;
  for (const PlyElement& e : elements) {
    needed += static_cast<long double>(e.count) * static_cast<long double>(e.min_bytes > 0 ? e.min_bytes : 1);
    if (needed > static_cast<long double>(file_size))
      refuse_counts(name, std::to_string(e.count) + " " + e.name + " elements", file_size);
  }
}

// Mirrors assimp's reading of an OFF header character by character: optional
// prefix letters [ST][C][N][4][n] (a leading '4' is read as one even before
// digits), then "OFF" (optional in a file named .off), an optional dimension
// after 'n', then the vertex and face counts; '#' starts a comment line.
void check_off(const std::string& head, bool named_off, std::uintmax_t file_size, const std::string& name) {
  size_t p = 0;
  const auto skip_blank_and_comments = [&] {
    while (p < head.size()) {
      if (std::isspace(static_cast<unsigned char>(head[p]))) {
        ++p;
      } else if (head[p] == '#') {
        p = std::min(head.find('\n', p), head.size());
      } else {
        break;
      }
    }
  };
  const auto take = [&](const char* prefix) {
    const size_t n = std::char_traits<char>::length(prefix);
    if (head.compare(p, n, prefix) != 0) return false;
    p += n;
    return true;
  };
  skip_blank_and_comments();
  take("ST");
  take("C");
  take("N");
  take("4");
  const bool has_dimension = take("n");
  if (!take("OFF") && !named_off) return;
  const auto next_count = [&](std::uint64_t& value) {
    skip_blank_and_comments();
    const size_t word_end = std::min(head.find_first_of(" \t\r\n#", p), head.size());
    const std::string word = head.substr(p, word_end - p);
    p = word_end;
    return parse_count(word, value);
  };
  skip_blank_and_comments();
  if (head.compare(p, 6, "BINARY") == 0) return;  // binary OFF files store the counts as integers
  std::uint64_t dimension = 0, vertices = 0, faces = 0;
  if (has_dimension && !next_count(dimension)) return;
  if (!next_count(vertices) || !next_count(faces)) return;
  // At least "0 0 0\n" per vertex and "0\n" per face.
  const long double needed = 6.0L * static_cast<long double>(vertices) + 2.0L * static_cast<long double>(faces);
  if (needed > static_cast<long double>(file_size))
    refuse_counts(name, std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces", file_size);
}

}  // namespace

void check_declared_mesh_counts(const std::string& head, std::uintmax_t file_size, const std::filesystem::path& path) {
  const std::string name = path.string();
  // assimp finds the PLY magic after leading blank lines too.
  const size_t text = std::min(head.find_first_not_of(" \t\r\n"), head.size());
  if (lower_case(head.substr(text, 3)) == "ply") {
    check_ply(head.substr(text), file_size, name);
    return;
  }
  // assimp picks its OFF reader by the file's extension, or by the magic for other names.
  check_off(head, lower_case(path.extension().string()) == ".off", file_size, name);
}

}  // namespace recoil::sim
