#pragma once
// A tiny benchmark registry: each bench file registers named functions that
// print their own table through BenchTable. `make bench` runs them all;
// `recoil_bench NAME...` runs the ones whose name contains a filter.
// Benchmarks report, they never assert: speed is not a test.
#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sim/geometry/tri_mesh.h"

namespace recoil::bench {

using BenchFunction = std::function<void()>;

// Registers at static-initialisation time: `static Register r("render", fn);`
struct Register {
  Register(const std::string& name, BenchFunction function);
};

// Wall-clock milliseconds of the fastest of `repeats` calls to `fn`.
double best_ms(int repeats, const std::function<void()>& fn);

// Prints a Markdown table: a title, what it measures (optional), a header
// row, then rows; `make bench` gathers them into docs/performance.md.
class BenchTable {
 public:
  BenchTable(std::string title, std::vector<std::string> columns);
  // A paragraph printed under the title: the set-up and how to read the table.
  void note(std::string text) { m_note = std::move(text); }
  void add_row(std::vector<std::string> cells);
  void print() const;

 private:
  std::string m_title;
  std::string m_note;
  std::vector<std::string> m_columns;
  std::vector<std::vector<std::string>> m_rows;
};

// Writes `mesh` as an OFF file, for the benches that run recoil on a file.
void write_off(const sim::TriMesh& mesh, const std::filesystem::path& path);

// Formats a number with `digits` after the point.
std::string fixed(double value, int digits = 1);
std::string scientific(double value, int digits = 1);

}  // namespace recoil::bench
