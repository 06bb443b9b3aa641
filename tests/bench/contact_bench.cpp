// `recoil_bench contact`: the contact solvers (cr, cr_plain, pgs) on three
// short scenes: a jelly stack, a pile of eight deformable bunnies, a soft
// block between counter-rotating rollers. Per method: mean solver
// iterations per step, ms per step (whole step and solve stage), the final
// KKT residual and the largest penetration; then the ratios cr/pgs time and
// cr_plain/cr iterations. Reports only; nothing is asserted.
#include <iostream>
#include <string>

#include "sim/world.h"
#include "tests/bench/bench.h"
#include "tests/scenes/contact_scenes.h"

namespace recoil::bench {
namespace {

struct Row {
  double iterations = 0.0, step_ms = 0.0, solve_ms = 0.0, residual = 0.0, penetration = 0.0;
  long not_converged = 0;
};

Row run_scene(sim::WorldDesc desc, sim::SolverMethod method, int steps) {
  desc.contact.solver.method = method;
  sim::World world(desc);
  Row row;
  for (int i = 0; i < steps; ++i) {
    const sim::StepReport r = world.step();
    row.iterations += r.solver_iterations;
    row.step_ms += r.profile.total;
    row.solve_ms += r.profile.solve;
    row.residual = r.solver_residual;
    row.penetration = std::max(row.penetration, r.max_penetration);
  }
  row.not_converged = world.counters().solver_not_converged;
  row.iterations /= steps;
  row.step_ms /= steps;
  row.solve_ms /= steps;
  return row;
}

void bench_contact() {
  const std::string bunny = std::string(RECOIL_SOURCE_DIR) + "/assets/meshes/bunny.obj";
  struct Scene {
    std::string name;
    sim::WorldDesc desc;
    int steps;
  };
  // Each scene starts in contact (stack) or reaches it within the steps run.
  sim::WorldDesc stack = sim::scenes::jelly_stack(3, 0.1, 3, 0.01);
  sim::WorldDesc pile = sim::scenes::bunny_pile(bunny, 8, 0.12, 3, 0.005);
  sim::WorldDesc roll = sim::scenes::rollers(6.0, 3, 0.005);
  const std::vector<Scene> scenes = {{"jelly stack (3)", stack, 10}, {"bunny pile (8)", pile, 10},
                                     {"rollers", roll, 10}};
  BenchTable table("contact solvers per step (tolerance 1e-7)",
                   {"scene", "method", "steps", "iterations/step", "ms/step", "solve ms/step", "final residual",
                    "max penetration mm", "not converged"});
  BenchTable ratios("contact solver ratios", {"scene", "cr/pgs time", "cr_plain/cr iterations"});
  for (const Scene& scene : scenes) {
    Row rows[3];
    const sim::SolverMethod methods[3] = {sim::SolverMethod::cr, sim::SolverMethod::cr_plain, sim::SolverMethod::pgs};
    for (int m = 0; m < 3; ++m) {
      rows[m] = run_scene(scene.desc, methods[m], scene.steps);
      table.add_row({scene.name, sim::to_string(methods[m]), std::to_string(scene.steps), fixed(rows[m].iterations, 1),
                     fixed(rows[m].step_ms, 2), fixed(rows[m].solve_ms, 2), std::to_string(rows[m].residual),
                     fixed(rows[m].penetration * 1e3, 3), std::to_string(rows[m].not_converged)});
    }
    ratios.add_row({scene.name, fixed(rows[0].solve_ms / std::max(rows[2].solve_ms, 1e-9), 2),
                    fixed(rows[1].iterations / std::max(rows[0].iterations, 1e-9), 2)});
  }
  table.print();
  ratios.print();
}

Register reg("contact", bench_contact);

}  // namespace
}  // namespace recoil::bench
