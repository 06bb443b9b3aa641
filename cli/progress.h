#pragma once
// Progress for long work: a one-line bar with count, rate and ETA on a
// terminal (redrawn in place on stderr), nothing when stderr is not a TTY or
// with --quiet, and JSON lines with --log-json (each finished item, and
// signs of life within a long one).
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
  // Work inside the current item (the steps before a frame): redraws the bar
  // with `detail` at most 10 times a second, so a slow item still shows life;
  // with --log-json, one {"event": "working"} line a second at most.
  void working(const std::string& detail);
  // A stage before the first item (building the bodies): drawn at once on a
  // terminal, one {"event": "stage"} line with --log-json.
  void stage(const std::string& what);
  // Whether working() would draw now (callers skip composing `detail` otherwise).
  bool due() const;
  // Clears the bar (a terminal keeps no half-drawn line).
  void finish();

 private:
  void draw(const std::string& detail);

  std::string m_label;
  int m_total;
  int m_done = 0;
  bool m_bar;
  bool m_json;
  bool m_finished = false;
  std::chrono::steady_clock::time_point m_start;
  std::chrono::steady_clock::time_point m_last_draw;
  // The rate and ETA count from the first finished item on: a first item
  // that costs nothing (frame 1, the initial state, is only drawn) would
  // otherwise promise a rate the rest never reaches.
  int m_first_done = -1;
  std::chrono::steady_clock::time_point m_first_time;
};

// "3.2/s" at one item a second or more, "4.1 s/frame" below (`unit` names the item).
std::string format_rate(double per_second, const std::string& unit);

}  // namespace recoil::cli
