#include "cli/run_report.h"

#include <algorithm>

#include "cli/build_info.h"
#include "cli/peak_memory.h"
#include "cli/scene_runner.h"

namespace recoil::cli {

RunReport::RunReport(const RunJob& job, const SceneDesc& scene) {
#ifdef NDEBUG
  const char* build_type = "release";
#else
  const char* build_type = "debug";
#endif
  m_head = {{"version", RECOIL_VERSION},
            {"build", {{"git", build_commit()}, {"type", build_type}, {"compiler", __VERSION__}}},
            {"command", job.command},
            {"scene", scene.name},
            {"scene_file", scene.file.string()},
            {"output", job.output_dir.string()},
            {"solver", solver_name(scene.world.contact.solver.method)},
            {"threads", scene.world.contact.num_threads},
            {"dt", scene.world.dt},
            {"fps", scene.render.fps},
            {"render", job.render},
            {"resume", job.resume}};
}

void RunReport::add_step(const sim::StepReport& r, int frame) {
  timings.step += r.profile.total;
  timings.assemble += r.profile.assemble;
  timings.collision += r.profile.collide;
  timings.solve += r.profile.solve;
  timings.integrate += r.profile.integrate;
  timings.health += r.profile.health;
  m_iterations += r.solver_iterations;
  m_restarts += r.solver_restarts;
  m_contacts += r.contacts;
  ++m_steps;
  if (!r.solver_converged && m_not_converged++ == 0) m_first_unconverged_frame = frame;
  m_worst_kkt = std::max(m_worst_kkt, r.solver_kkt);
  m_max_residual = std::max(m_max_residual, r.solver_residual);
  m_max_penetration = std::max(m_max_penetration, r.max_penetration);
}

SolveQuality RunReport::solve_quality(double margin) const {
  return {m_steps, m_not_converged, m_first_unconverged_frame, m_worst_kkt, m_max_penetration, margin};
}

void RunReport::add_frame(const FrameTimes& times) { timings.render += times.render; }

void RunReport::set_gl(const std::string& backend, const std::string& renderer) {
  m_head["gl"] = {{"backend", backend}, {"renderer", renderer}};
}

void RunReport::finish(const sim::World& world, const RunResult& result, double total_ms) {
  timings.total = total_ms;
  const sim::WorldCounters& c = world.counters();
  const std::optional<double> peak = peak_memory_mib();
  m_tail = {{"frames",
             {{"written", result.frames_written},
              {"skipped", result.frames_skipped},
              {"removed", result.removed_frames.count}}},
            {"steps", result.steps},
            {"simulated_seconds", world.time()},
            {"peak_memory_mib", peak ? nlohmann::json(*peak) : nlohmann::json()},
            {"settle", result.settle_limit > 0.0 ? nlohmann::json{{"limit_s", result.settle_limit},
                                                                 {"time_s", result.settle_time},
                                                                 {"at_rest", result.settled}}
                                                 : nlohmann::json()},
            {"counters",
             {{"steps", c.steps},
              {"solver_not_converged", c.solver_not_converged},
              {"inverted_steps", c.inverted_steps},
              {"nan_steps", c.nan_steps},
              {"energy_blowup_steps", c.energy_blowup_steps}}},
            {"warnings",
             {{"summary", describe_run_warnings(result)},
              {"open_meshes", result.open_meshes},
              {"look", result.look_warnings},
              {"not_converged_steps", result.quality.not_converged},
              {"first_unconverged_frame", result.quality.first_unconverged_frame},
              {"worst_kkt", result.quality.worst_kkt},
              {"max_penetration", result.quality.max_penetration},
              {"margin", result.quality.margin}}},
            {"exit", {{"code", result.interrupted_by ? 128 + result.interrupted_by : result.failed ? 3 : 0},
                      {"status", result.interrupted_by ? "interrupted" : result.failed ? "sim_failed" : "ok"},
                      {"message", result.message}}}};
}

nlohmann::json RunReport::json() const {
  nlohmann::json out = m_head;
  out.update(m_tail);
  out["timings_ms"] = {{"build", timings.build},         {"step", timings.step},   {"assemble", timings.assemble},
                       {"collision", timings.collision}, {"solve", timings.solve}, {"integrate", timings.integrate},
                       {"health", timings.health},       {"render", timings.render}, {"encode", timings.encode},
                       {"total", timings.total}};
  out["solver_totals"] = {{"iterations", m_iterations},
                          {"restarts", m_restarts},
                          {"contacts", m_contacts},
                          {"not_converged_steps", m_not_converged},
                          // The Krylov residual the solver stopped at (its tolerance's measure) and the
                          // KKT residual of the solution it returned (the contact laws' error, the summary's
                          // "worst KKT"), both m/s: one solve can meet the first and miss the second.
                          {"max_residual", m_max_residual},
                          {"worst_kkt", m_worst_kkt},
                          {"max_penetration", m_max_penetration}};
  return out;
}

}  // namespace recoil::cli
