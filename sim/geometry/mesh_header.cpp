// PLY: "ply", "format ascii|binary_* 1.0", then "element NAME COUNT" each
// followed by its "property TYPE NAME" / "property list COUNT_TYPE ITEM_TYPE NAME"
// lines, up to "end_header". OFF: "[ST][C][N][4][n]OFF", then "vertices faces edges".
#include "sim/geometry/mesh_header.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/lower_case.h"

namespace recoil::sim {
namespace {

// The leading digits of `token`, as assimp reads them ("12x" is 12); too many digits read as the largest count.
bool parse_count(const std::string& token, std::uint64_t& value) {
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec == std::errc::result_out_of_range) value = UINT64_MAX;
  return ptr != token.data();
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

// The scalar type names of the PLY format, in both its spellings.
bool is_ply_type(const std::string& type) {
  for (const char* t : {"char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8", "int16",
                        "uint16", "int32", "uint32", "float32", "float64"})
    if (type == t) return true;
  return false;
}

[[noreturn]] void refuse_counts(const std::string& name, const std::string& declared, std::uintmax_t file_size) {
  throw bad_input(name + ": declares " + declared + ", more than its " + std::to_string(file_size) +
                  " bytes can hold");
}

// `line` for a message: at most 60 bytes, anything unprintable as '?'.
std::string quoted_line(const std::string& line) {
  std::string out;
  for (const char c : line.substr(0, 60)) out += (c >= ' ' && c <= '~' && c != '"') ? c : '?';
  return out;
}

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_bytes = 0;  // of one element: 2 per ASCII value ("0 "), the type's size in binary
  std::vector<bool> is_list;    // per property, in order
};

// Throws when `line`, one instance of `e`, holds a list count that needs more
// bytes than the file has: a list of n values needs at least 2n ("0 ").
void check_instance_line(const std::string& line, const PlyElement& e, std::uintmax_t file_size,
                         const std::string& name) {
  std::istringstream values(line);
  std::string value;
  for (const bool list : e.is_list) {
    if (!(values >> value)) return;
    if (!list) continue;
    // A negative count of a signed type would become a huge unsigned one.
    std::uint64_t n = 0;
    const bool negative = value.size() > 1 && value[0] == '-';
    if (!parse_count(negative ? value.substr(1) : value, n)) n = 0;
    if (negative && n > 0) n = UINT64_MAX;
    if (static_cast<long double>(n) * 2.0L > static_cast<long double>(file_size))
      refuse_counts(name, "a list of " + (negative ? value : std::to_string(n)) + " values in " + e.name, file_size);
    for (std::uint64_t k = 0; k < n; ++k)
      if (!(values >> value)) return;
  }
}

// assimp reserves a list's values as soon as it reads the count, whatever the
// count's type (a "uchar" count of 99990000 is taken as is), so the lists of
// an ASCII body are checked before it reads them. assimp reads one instance
// per '\n'-ended line, and once the lines run out it reads the last one again.
void check_ascii_list_counts(std::istream& body, const std::vector<PlyElement>& elements, std::uintmax_t file_size,
                             const std::string& name) {
  std::string line, next;
  bool lines_left = true;
  for (const PlyElement& e : elements) {
    const bool has_list = std::find(e.is_list.begin(), e.is_list.end(), true) != e.is_list.end();
    for (std::uint64_t i = 0; i < e.count; ++i) {
      lines_left = lines_left && static_cast<bool>(std::getline(body, next));
      if (lines_left) line.swap(next);
      if (has_list) check_instance_line(line, e, file_size, name);
      if (!lines_left) break;  // every further instance reads the same line
    }
  }
}

// `head` starts at the magic, `head_offset` bytes into the file at `path`.
void check_ply(const std::string& head, size_t head_offset, const std::filesystem::path& path, std::uintmax_t file_size,
               const std::string& name) {
  // A header is lines of text; past a NUL byte or a form feed assimp 5.2 may search for end_header forever.
  const size_t control = std::find_if(head.begin(), head.end(), [](char c) {
                           return static_cast<unsigned char>(c) < ' ' && c != '\n' && c != '\r' && c != '\t';
                         }) - head.begin();
  if (control < head.size() && control < head.find("end_header")) {
    char code[8];
    std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(head[control])));
    throw bad_input(name + ": PLY header holds the control byte " + code + " (a header is lines of text)");
  }
  // assimp ends a header line at '\n', '\r', form feed or NUL.
  constexpr std::string_view kLineEnd("\n\r\f\0", 4);
  size_t next = std::min(head.find_first_of(kLineEnd), head.size());  // past "ply"
  bool ascii = true;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (!ended && next < head.size()) {
    const size_t start = next + 1;
    next = std::min(head.find_first_of(kLineEnd, start), head.size());
    const std::string line = head.substr(start, next - start);
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    const std::string keyword = w.empty() ? "" : w[0];
    const auto refuse_line = [&](const std::string& why) {
      throw bad_input(name + ": PLY header line \"" + quoted_line(line) + "\" " + why);
    };
    if (keyword == "end_header") {
      // Only "end_header" then a line end (not the file's end), a space or a tab:
      // assimp 5.2 hangs on near misses ("end_header\v", "end_header" as the file's last bytes).
      ended = line.rfind("end_header", 0) == 0 &&
              (line.size() == 10 ? next < head.size() : line[10] == ' ' || line[10] == '\t');
      if (!ended) refuse_line("is not a plain end_header");
    } else if (line.find("end_header") != std::string::npos) {
      // assimp takes the header to end at the first "end_header" wherever it stands.
      refuse_line("holds end_header but is not one");
    } else if (keyword == "format") {
      // assimp 5.2 may search forever past a format line it cannot read, so only the three forms pass.
      const bool known = w.size() == 3 && (w[1] == "ascii" || w[1] == "binary_little_endian" ||
                                           w[1] == "binary_big_endian");
      if (!known || w[2].find_first_not_of("0123456789.") != std::string::npos)
        throw bad_input(name + ": PLY format line \"" + quoted_line(line) +
                        "\" is not \"format ascii|binary_little_endian|binary_big_endian VERSION\"");
      ascii = w[1] == "ascii";
    } else if (keyword == "element") {
      std::uint64_t count = 0;
      if (w.size() != 3 || w[2].find_first_not_of("0123456789") != std::string::npos || !parse_count(w[2], count))
        refuse_line("is not \"element NAME COUNT\"");
      elements.push_back(PlyElement{w[1], count, 0, {}});
    } else if (keyword == "property") {
      const bool list = w.size() > 1 && w[1] == "list";
      if (elements.empty()) refuse_line("comes before any element");
      if (list ? w.size() != 5 || !is_ply_type(w[2]) || !is_ply_type(w[3]) : w.size() != 3 || !is_ply_type(w[1]))
        refuse_line("is not \"property TYPE NAME\" or \"property list COUNT_TYPE ITEM_TYPE NAME\"");
      elements.back().min_bytes += ascii ? 2 : ply_type_bytes(list ? w[2] : w[1]);  // a list may be empty
      elements.back().is_list.push_back(list);
    }  // other lines are comments, as in Blender's files, which write them without the keyword
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
  if (!ascii) return;
  // The body's lines end at '\n' only; it starts on the line after end_header's.
  const size_t body_start = std::min(head.find('\n', next), head.size() - 1) + 1;
  std::ifstream body(path, std::ios::binary);
  body.seekg(static_cast<std::streamoff>(head_offset + body_start));
  check_ascii_list_counts(body, elements, file_size, name);
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
  if (!next_count(vertices)) return;
  // At least "0 0 0\n" per vertex and "0\n" per face; assimp allocates the
  // vertices even when what follows is no face count.
  if (6.0L * static_cast<long double>(vertices) > static_cast<long double>(file_size))
    refuse_counts(name, std::to_string(vertices) + " vertices", file_size);
  if (!next_count(faces)) return;
  const long double needed = 6.0L * static_cast<long double>(vertices) + 2.0L * static_cast<long double>(faces);
  if (needed > static_cast<long double>(file_size))
    refuse_counts(name, std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces", file_size);
}

}  // namespace

void check_declared_mesh_counts(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if (ec) return;  // assimp reports what it cannot open
  // Headers fit in the first 64 KiB.
  std::string head(64 * 1024, '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  const std::string extension = lower_case(path.extension().string());
  // assimp finds the PLY magic after leading blanks and line ends (its line ends include form feed and NUL).
  const size_t text = std::min(head.find_first_not_of(std::string_view(" \t\r\n\f\0", 6)), head.size());
  const bool starts_with_magic = lower_case(head.substr(text, 3)) == "ply" &&
                                 (text + 3 == head.size() || std::isspace(static_cast<unsigned char>(head[text + 3])));
  // In a file named .ply, assimp 5.2 also takes the magic from later lines
  // and then may search for end_header forever; a PLY file starts with it.
  if (!starts_with_magic && extension == ".ply" && text < head.size())
    throw bad_input(name + ": not a PLY file: it does not start with the line \"ply\"");
  if (starts_with_magic) {
    check_ply(head.substr(text), text, path, file_size, name);
    return;
  }
  // assimp picks its OFF reader by the file's extension, or by the magic for other names.
  check_off(head, extension == ".off", file_size, name);
}

}  // namespace recoil::sim
