#pragma once
// DIR/run.json: version and build, wall-clock time per
// phase, solver totals and the exit status of a run.
#include <nlohmann/json.hpp>

#include "cli/frame_stats.h"
#include "sim/world.h"

namespace recoil::cli {

struct RunJob;
struct RunResult;

// How well the contact solves went over a run: what the end-of-run summary
// warns about and --strict fails on.
struct SolveQuality {
  long steps = 0;
  long not_converged = 0;          // steps whose solve ended above its tolerance (at its cap, or stalled)
  int first_unconverged_frame = -1;  // the frame whose steps held the first of them (0: settling; -1: none)
  double worst_kkt = 0.0;          // largest KKT residual of a returned solution, m/s
  double max_penetration = 0.0;    // m
  double margin = 0.0;             // the scene's contact margin, m
  bool penetrated_margin() const { return max_penetration > margin; }
};

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
  // `frame`: the frame being stepped towards (0 while settling).
  void add_step(const sim::StepReport& report, int frame);
  void add_frame(const FrameTimes& times);
  // The OpenGL backend that drew the frames and its GL_RENDERER string.
  void set_gl(const std::string& backend, const std::string& renderer);
  void finish(const sim::World& world, const RunResult& result, double total_ms);
  // The steps added so far, against the scene's contact margin (m).
  SolveQuality solve_quality(double margin) const;
  nlohmann::json json() const;

  Timings timings;

 private:
  nlohmann::json m_head;
  long m_steps = 0, m_iterations = 0, m_restarts = 0, m_contacts = 0, m_not_converged = 0;
  int m_first_unconverged_frame = -1;
  double m_max_residual = 0.0, m_max_penetration = 0.0, m_worst_kkt = 0.0;
  nlohmann::json m_tail;
};

}  // namespace recoil::cli
