// `recoil_bench rigid`: the rigid friction benchmarks beside the per-step
// costs MuJoCo 2.2.2 and Bullet 3.24 were measured at on a 2-core machine
// like this one (same set-up: dt 2 ms, 0.2 m cubes of density 700, bodies
// starting exactly touching). S1: a cube on a 16 degree slope, mu 0.35,
// 10 s (displacement, mm); S4: four cubes stacked, mu 0.5, 10 s (top drift, mm).
// Reports only; nothing is asserted.
#include <iostream>

#include "sim/world.h"
#include "tests/bench/bench.h"
#include "tests/scenes/contact_scenes.h"

namespace recoil::bench {
namespace {

struct RigidRun {
  double moved_mm = 0.0;    // largest displacement of the watched body's centre, mm
  double us_per_step = 0.0;
  long unconverged = 0;
  int steps = 0;
  sim::Profile stage_ms;  // summed over the steps
  long iterations = 0, contacts = 0;
};

// Runs 10 s and watches rigid body `watched` (its index among the bodies' stats).
RigidRun run_rigid(const sim::WorldDesc& desc, int watched) {
  sim::World world(desc);
  const Eigen::Vector3d start = world.stats()[static_cast<size_t>(watched)].center_of_mass;
  RigidRun out;
  out.steps = static_cast<int>(10.0 / desc.dt + 0.5);
  double total_ms = 0.0;
  for (int i = 0; i < out.steps; ++i) {
    const sim::StepReport r = world.step();
    total_ms += r.profile.total;
    out.stage_ms.assemble += r.profile.assemble;
    out.stage_ms.collide += r.profile.collide;
    out.stage_ms.solve += r.profile.solve;
    out.stage_ms.integrate += r.profile.integrate;
    out.stage_ms.health += r.profile.health;
    out.iterations += r.solver_iterations;
    out.contacts += r.contacts;
    out.unconverged += !r.solver_converged;
    const Eigen::Vector3d c = world.stats()[static_cast<size_t>(watched)].center_of_mass;
    out.moved_mm = std::max(out.moved_mm, (c - start).norm() * 1e3);
  }
  out.us_per_step = total_ms * 1e3 / out.steps;
  return out;
}

void rigid_bench() {
  const RigidRun s1 = run_rigid(sim::scenes::cube_on_holding_slope(), 0);
  const RigidRun s4 = run_rigid(sim::scenes::touching_cube_stack(4), 3);
  // The peers' figures: S1 displacement, S4 top drift (mm), and their us per step.
  struct Peer {
    const char* name;
    double s1_mm, s4_mm, s1_us, s4_us;
  };
  const Peer peers[] = {{"MuJoCo, elliptic cone, impratio 10", 0.870, 0.000, 6.1, 26.8},
                        {"MuJoCo, default (pyramidal cone)", 21.493, 0.000, 5.3, 31.5},
                        {"Bullet, box ground, sleeping off", 0.004, 5.301, 2.3, 8.5}};
  BenchTable table("rigid friction benchmarks, 10 s at dt 2 ms (recoil measured now; peers as published)",
                   {"engine", "S1 moved (mm)", "S4 top drift (mm)", "us/step S1", "us/step S4",
                    "recoil / peer S1", "recoil / peer S4"});
  table.note(
      "dt 2 ms, 0.2 m cubes of density 700, every body starting exactly touching its support, 10 s. S1: a cube on a "
      "16 degree slope, mu 0.35 (its largest displacement); S4: four cubes stacked, mu 0.5 (the top cube's largest "
      "displacement). recoil is measured in this run; the peers' figures are MuJoCo 2.2.2's and Bullet 3.24's, "
      "measured on a 2-core machine of the same kind, so the ratios compare similar, not the same, hardware.");
  table.add_row({"recoil (cr)", scientific(s1.moved_mm, 2), scientific(s4.moved_mm, 2), fixed(s1.us_per_step, 0),
                 fixed(s4.us_per_step, 0), "1", "1"});
  for (const Peer& p : peers)
    table.add_row({p.name, fixed(p.s1_mm, 3), fixed(p.s4_mm, 3), fixed(p.s1_us, 1), fixed(p.s4_us, 1),
                   fixed(s1.us_per_step / p.s1_us, 0) + "x", fixed(s4.us_per_step / p.s4_us, 0) + "x"});
  table.print();
  BenchTable stages("recoil's step by stage, us/step", {"scene", "assemble", "collide", "solve", "integrate", "health",
                                                        "total", "contact rows/step", "solver iterations/step"});
  stages.note(
      "The collision stage includes the searches the solver makes each time it converges, for contacts its "
      "solution brings (Algorithm 1's outer loop). A body standing still gives the search the same input step after "
      "step, and the detector answers such a search from its memo of the last two (search_memo.h) instead of "
      "running it: S4's stack stands still from its first steps, so its searches cost a comparison of positions.");
  for (const auto& [name, run] : {std::pair<const char*, const RigidRun&>{"S1", s1}, {"S4", s4}}) {
    const double to_us = 1e3 / run.steps;
    stages.add_row({name, fixed(run.stage_ms.assemble * to_us, 1), fixed(run.stage_ms.collide * to_us, 1),
                    fixed(run.stage_ms.solve * to_us, 1), fixed(run.stage_ms.integrate * to_us, 1),
                    fixed(run.stage_ms.health * to_us, 1), fixed(run.us_per_step, 1),
                    fixed(static_cast<double>(run.contacts) / run.steps, 1),
                    fixed(static_cast<double>(run.iterations) / run.steps, 1)});
  }
  stages.print();
  std::cout << "recoil unconverged steps: S1 " << s1.unconverged << " of " << s1.steps << ", S4 " << s4.unconverged
            << " of " << s4.steps << "\n";
}

const Register registered_rigid("rigid", rigid_bench);

}  // namespace
}  // namespace recoil::bench
