// Contact solvers on spring lattices resting on the ground (one frictional
// contact per bottom node, mu 0.5, drifting sideways so both friction modes
// occur): iterations, time and the common KKT residual of cr, cr_plain and
// pgs at the same tolerances, cold and warm started. The scene benchmark
// with real bodies lives with the World.
#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "tests/fixtures/fem_problem.h"
#include "tests/fixtures/problem_builders.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

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

// The real FEM system: iterations and ms of cr, cr_plain and pgs at the
// same tolerances, with ratios against cr.
struct Variant {
  std::string label;
  recoil::sim::SolverMethod method;
};

void bench_solver_fem() {
  using namespace recoil::sim;
  const std::vector<Variant> variants = {
      {"cr", SolverMethod::cr}, {"cr_plain", SolverMethod::cr_plain}, {"pgs", SolverMethod::pgs}};
  BenchTable table("Contact solvers, FEM cube 0.5 m on the ground (co-rotated, rho 1000, h = 1/60 s, mu 0.5, drift "
                   "0.2 m/s), tol 1e-6 m/s, cold start; ratios against cr",
                   {"problem", "DoF", "contacts", "method", "iters", "restarts", "ms", "kkt m/s", "plain/this iters",
                    "this/cr ms", "converged"});
  for (double E : {1e5, 1e6, 1e7}) {
    for (int resolution : {6, 10}) for (double drift : {0.2, 0.0}) {
      FemBlockParams params;
      params.youngs_modulus = E;
      params.resolution = resolution;
      params.drift = drift;
      const OwnedProblem owned = fem_block_on_ground(params);
      std::vector<ContactSolverStats> stats(variants.size());
      std::vector<double> ms(variants.size(), 0.0);
      for (size_t i = 0; i < variants.size(); ++i) {
        ContactSolverSettings settings;
        settings.method = variants[i].method;
        settings.max_iterations = 50000;
        Eigen::VectorXd dv;
        ms[i] = best_ms(variants[i].method == SolverMethod::pgs ? 1 : 3, [&] {
          ContactProblem copy = owned.problem;
          stats[i] = solve_contacts(copy, settings, dv);
        });
      }
      const size_t plain = variants.size() - 2;
      for (size_t i = 0; i < variants.size(); ++i)
        table.add_row({describe(params), std::to_string(owned.problem.b.size()), std::to_string(owned.problem.rows.size()),
                       variants[i].label, std::to_string(stats[i].iterations), std::to_string(stats[i].restarts),
                       fixed(ms[i], 2), scientific(stats[i].kkt),
                       variants[i].method == SolverMethod::cr
                           ? fixed(static_cast<double>(stats[plain].iterations) / std::max(1, stats[i].iterations), 2)
                           : "",
                       fixed(ms[i] / ms[0], 2), stats[i].converged ? "yes" : "no"});
    }
  }
  table.print();
}

const Register registered_solver("solver", bench_solver);
const Register registered_solver_fem("solver_fem", bench_solver_fem);

}  // namespace
}  // namespace recoil::bench
