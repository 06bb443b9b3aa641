#pragma once
// Progress for long work: a one-line bar with count, rate and ETA on a
// terminal (redrawn in place on stderr), nothing when stderr is not a TTY or
// with --quiet, and one JSON object per update with --log-json.
#include <chrono>
#include <string>

#include "cli/commands.h"

namespace recoil::cli {

class Progress {
 public:
  Progress(const GlobalOptions& global, std::string label, int total);
  ~Progress();

  // `done` items of `total` are finished.
  void update(int done);
  // Clears the bar (a terminal keeps no half-drawn line).
  void finish();

 private:
  std::string m_label;
  int m_total;
  bool m_bar;
  bool m_json;
  bool m_finished = false;
  std::chrono::steady_clock::time_point m_start;
  std::chrono::steady_clock::time_point m_last_draw;
};

}  // namespace recoil::cli
