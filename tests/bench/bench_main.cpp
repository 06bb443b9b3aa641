#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

#include "tests/bench/bench.h"

namespace recoil::bench {

static std::map<std::string, BenchFunction>& registry() {
  static std::map<std::string, BenchFunction> functions;
  return functions;
}

Register::Register(const std::string& name, BenchFunction function) { registry()[name] = std::move(function); }

double best_ms(int repeats, const std::function<void()>& fn) {
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    fn();
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    best = std::min(best, elapsed.count());
  }
  return best;
}

void write_off(const sim::TriMesh& mesh, const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "OFF\n" << mesh.num_vertices() << " " << mesh.num_triangles() << " 0\n";
  out.precision(9);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    out << mesh.vertices(v, 0) << " " << mesh.vertices(v, 1) << " " << mesh.vertices(v, 2) << "\n";
  for (int f = 0; f < mesh.num_triangles(); ++f)
    out << "3 " << mesh.triangles(f, 0) << " " << mesh.triangles(f, 1) << " " << mesh.triangles(f, 2) << "\n";
}

BenchTable::BenchTable(std::string title, std::vector<std::string> columns)
    : m_title(std::move(title)), m_columns(std::move(columns)) {}

void BenchTable::add_row(std::vector<std::string> cells) { m_rows.push_back(std::move(cells)); }

void BenchTable::print() const {
  std::vector<size_t> width(m_columns.size());
  for (size_t c = 0; c < m_columns.size(); ++c) width[c] = m_columns[c].size();
  for (const auto& row : m_rows)
    for (size_t c = 0; c < row.size() && c < width.size(); ++c) width[c] = std::max(width[c], row[c].size());
  auto print_row = [&](const std::vector<std::string>& cells) {
    std::cout << "|";
    for (size_t c = 0; c < width.size(); ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      std::cout << " " << cell << std::string(width[c] - cell.size(), ' ') << " |";
    }
    std::cout << "\n";
  };
  std::cout << "\n## " << m_title << "\n\n";
  if (!m_note.empty()) std::cout << m_note << "\n\n";
  print_row(m_columns);
  std::cout << "|";
  for (size_t w : width) std::cout << std::string(w + 2, '-') << "|";
  std::cout << "\n";
  for (const auto& row : m_rows) print_row(row);
  std::cout << std::flush;
}

namespace {
std::string format_double(const char* format, double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof(text), format, digits, value);
  return text;
}
}  // namespace

std::string fixed(double value, int digits) { return format_double("%.*f", value, digits); }
std::string scientific(double value, int digits) { return format_double("%.*e", value, digits); }

}  // namespace recoil::bench

int main(int argc, char** argv) {
  using namespace recoil::bench;
  for (const auto& [name, fn] : registry()) {
    bool wanted = argc < 2;
    for (int i = 1; i < argc; ++i) wanted |= name.find(argv[i]) != std::string::npos;
    if (wanted) fn();
  }
  return 0;
}
