// Contact solvers on spring lattices resting on the ground (one frictional
// contact per bottom node, mu 0.5, drifting sideways so both friction modes
// occur): iterations, time and the common KKT residual of cr, cr_plain and
// pgs at the same tolerances, cold and warm started. The scene benchmark
// with real bodies lives with the World.
#include <cstdio>
#include <random>
#include <string>

#include "sim/solver/problem_builders.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1e", value);
  return text;
}

void bench_solver() {
  using namespace recoil::sim;
  BenchTable table("Contact solvers, lattice on the ground, h = 1/60 s, node masses 1..100 kg, tol 1e-6 m/s",
                   {"lattice", "DoF", "contacts", "method", "iters", "restarts", "ms", "kkt m/s", "warm iters",
                    "warm ms", "converged"});
  for (int side : {4, 8, 12}) {
    std::mt19937 rng(static_cast<unsigned>(side));
    const OwnedProblem owned = lattice_on_ground(side, side, side / 2, 1.0, 100.0, 1e5, 1.0 / 60.0, 0.5, 0.2, rng);
    for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain, SolverMethod::pgs}) {
      ContactSolverSettings settings;
      settings.method = method;
      settings.max_iterations = 20000;
      ContactSolverStats cold, warm;
      std::vector<ContactState> solved;
      Eigen::VectorXd dv;
      const double cold_ms = best_ms(3, [&] {
        ContactProblem copy = owned.problem;
        cold = solve_contacts(copy, settings, dv);
        solved = copy.states;
      });
      const double warm_ms = best_ms(3, [&] {
        ContactProblem copy = owned.problem;
        copy.states = solved;
        warm = solve_contacts(copy, settings, dv);
      });
      table.add_row({std::to_string(side) + "x" + std::to_string(side) + "x" + std::to_string(side / 2),
                     std::to_string(owned.problem.b.size()), std::to_string(owned.problem.rows.size()), to_string(method),
                     std::to_string(cold.iterations), std::to_string(cold.restarts), fixed(cold_ms, 2),
                     scientific(cold.kkt), std::to_string(warm.iterations), fixed(warm_ms, 2),
                     cold.converged && warm.converged ? "yes" : "no"});
    }
  }
  table.print();
}

const Register registered("solver", bench_solver);

}  // namespace
}  // namespace recoil::bench
