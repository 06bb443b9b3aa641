#pragma once
// DIR/run.json (SPEC.md section 4): version and build, wall-clock time per
// phase, solver totals and the exit status of a run.
#include <nlohmann/json.hpp>

#include "cli/frame_stats.h"
#include "sim/world.h"

namespace recoil::cli {

struct RunJob;
struct RunResult;

class RunReport {
 public:
  struct Timings {  // milliseconds
    double build = 0.0;   // World construction (tetrahedralization included)
    double step = 0.0, assemble = 0.0, collision = 0.0, solve = 0.0, integrate = 0.0, health = 0.0;
    double render = 0.0;  // drawing, on the main thread
    double encode = 0.0;  // PNG encoding, summed over the worker threads
    double total = 0.0;
  };

  RunReport(const RunJob& job, const SceneDesc& scene);
  void add_step(const sim::StepReport& report);
  void add_frame(const FrameTimes& times);
  void finish(const sim::World& world, const RunResult& result, double total_ms);
  nlohmann::json json() const;

  Timings timings;

 private:
  nlohmann::json m_head;
  long m_iterations = 0, m_restarts = 0, m_contacts = 0, m_not_converged = 0;
  double m_max_residual = 0.0, m_max_penetration = 0.0;
  nlohmann::json m_tail;
};

}  // namespace recoil::cli
