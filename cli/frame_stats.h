#pragma once
// One line of stats.jsonl: the step reports of a frame
// summed (solver work, contacts) or maximised (penetration, residual), and
// the dynamic bodies' state at the frame time, in scene order.
#include <nlohmann/json.hpp>
#include <vector>

#include "cli/scene_desc.h"
#include "sim/world.h"

namespace recoil::cli {

// Sums over the steps between two frames.
struct FrameAccumulator {
  int steps = 0;
  long contacts = 0, active = 0, sticking = 0, sliding = 0;
  long iterations = 0, restarts = 0;
  double residual = 0.0;         // largest over the steps
  double max_penetration = 0.0;  // m, largest over the steps
  double step_ms = 0.0, collision_ms = 0.0, solve_ms = 0.0;

  void add(const sim::StepReport& report);
};

// Wall-clock milliseconds spent on a frame's pixels (0 when not rendered).
struct FrameTimes {
  double render = 0.0;
  double encode = 0.0;  // encoding finished on the worker threads since the previous frame
};

// The bodies' state at simulated time `time`, which lies within a step of
// the last one taken: every quantity linear between `before` (World::stats()
// one step earlier) and `after` (now, at `after_time`; `dt` apart). A frame
// falls between steps when 1 / fps is no multiple of dt, and the frame's
// stats report it at its own time. `before` empty: `after` as it is.
std::vector<sim::BodyStats> bodies_at(double time, const std::vector<sim::BodyStats>& before,
                                      const std::vector<sim::BodyStats>& after, double after_time, double dt);

// The stats.jsonl object of frame `frame` at `time` (= (frame - 1) / fps);
// `stats` from World::stats(), reordered to the scene order of `scene`.
nlohmann::json frame_stats_json(int frame, double time, double sim_time, const FrameAccumulator& steps,
                                const std::vector<sim::BodyStats>& stats, const SceneDesc& scene,
                                const FrameTimes& times);

}  // namespace recoil::cli
