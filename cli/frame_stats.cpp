#include "cli/frame_stats.h"

#include <algorithm>

#include "cli/json_cursor.h"

namespace recoil::cli {
namespace {

nlohmann::json body_json(const sim::BodyStats& s) {
  const Eigen::Vector3d velocity = s.mass > 0 ? Eigen::Vector3d(s.momentum / s.mass) : Eigen::Vector3d::Zero();
  return {{"name", s.name},
          {"com", json_vec3(s.center_of_mass)},
          {"velocity", json_vec3(velocity)},
          {"kinetic_energy", s.kinetic_energy},
          {"elastic_energy", s.elastic_energy},
          {"min_volume_ratio", s.min_volume_ratio}};
}

}  // namespace

void FrameAccumulator::add(const sim::StepReport& r) {
  ++steps;
  contacts += r.contacts;
  active += r.active;
  sticking += r.sticking;
  sliding += r.sliding;
  iterations += r.solver_iterations;
  restarts += r.solver_restarts;
  residual = std::max(residual, r.solver_residual);
  max_penetration = std::max(max_penetration, r.max_penetration);
  step_ms += r.profile.total;
  collision_ms += r.profile.collide;
  solve_ms += r.profile.solve;
}

std::vector<sim::BodyStats> bodies_at(double time, const std::vector<sim::BodyStats>& before,
                                      const std::vector<sim::BodyStats>& after, double after_time, double dt) {
  std::vector<sim::BodyStats> out = after;
  if (before.size() != after.size() || !(dt > 0.0)) return out;
  const double share = (time - (after_time - dt)) / dt;  // 0 at `before`, 1 at `after`
  const auto blend = [share](const auto& a, const auto& b) { return a + share * (b - a); };
  for (size_t i = 0; i < out.size(); ++i) {
    out[i].center_of_mass = blend(before[i].center_of_mass, after[i].center_of_mass);
    out[i].momentum = blend(before[i].momentum, after[i].momentum);
    out[i].kinetic_energy = blend(before[i].kinetic_energy, after[i].kinetic_energy);
    out[i].elastic_energy = blend(before[i].elastic_energy, after[i].elastic_energy);
    out[i].min_volume_ratio = blend(before[i].min_volume_ratio, after[i].min_volume_ratio);
  }
  return out;
}

nlohmann::json frame_stats_json(int frame, double time, double sim_time, const FrameAccumulator& a,
                                const std::vector<sim::BodyStats>& stats, const SceneDesc& scene,
                                const FrameTimes& times) {
  nlohmann::json bodies = nlohmann::json::array();
  // Scene order: the world lists deformable bodies before rigid ones.
  for (const SceneBody& body : scene.bodies) {
    if (body.kind != sim::BodyKind::rigid && body.kind != sim::BodyKind::deformable) continue;
    const auto it = std::find_if(stats.begin(), stats.end(), [&](const sim::BodyStats& s) { return s.name == body.name; });
    if (it != stats.end()) bodies.push_back(body_json(*it));
  }
  return {{"frame", frame},
          {"time", time},
          {"sim_time", sim_time},
          {"steps", a.steps},
          {"contacts", a.contacts},
          {"active", a.active},
          {"sticking", a.sticking},
          {"sliding", a.sliding},
          {"solver", {{"iterations", a.iterations}, {"restarts", a.restarts}, {"residual", a.residual}, {"ms", a.solve_ms}}},
          {"max_penetration", a.max_penetration},
          {"bodies", bodies},
          {"ms",
           {{"step", a.step_ms},
            {"collision", a.collision_ms},
            {"solve", a.solve_ms},
            {"render", times.render},
            {"encode", times.encode}}}};
}

}  // namespace recoil::cli
