// Cost of one implicit FEM step (assembly of A and b, PCG solve) for a
// clamped soft cube at about 1k, 8k and 64k tetrahedra.
#include <string>

#include "tests/bench/bench.h"
#include "tests/sim/fem/fem_scenes.h"

namespace recoil::bench {
namespace {

void bench_fem() {
  using namespace recoil::sim;
  BenchTable table("FEM step, clamped cube sagging under gravity, dt 4 ms, PCG tol 1e-8 (mean of 3 steps)",
                   {"model", "tets", "nodes", "assemble ms", "solve ms", "CG iters", "step ms"});
  for (MaterialModel model : {MaterialModel::corotated, MaterialModel::neo_hookean}) {
    for (int n : {6, 11, 22}) {  // 6 n^3 tets: 1296, 7986, 63888
      WorldDesc desc;
      desc.dt = 0.004;
      desc.bodies.push_back(test_scenes::box_body({1.0, 1.0, 1.0}, n, test_scenes::soft_material(model)));
      desc.bodies.back().pinned = PinBox{Eigen::Vector3d(-1, 0.5 - 1e-9, -1), Eigen::Vector3d(1, 1, 1)};
      World world(desc);
      const int steps = 3;
      Profile sum;
      int iterations = 0;
      for (int i = 0; i < steps; ++i) {
        const StepReport r = world.step();
        sum.assemble += r.profile.assemble;
        sum.solve += r.profile.solve;
        sum.total += r.profile.total;
        iterations += r.solver_iterations;
      }
      table.add_row({model == MaterialModel::corotated ? "corotated" : "neo-hookean",
                     std::to_string(world.stats()[0].num_tets), std::to_string(world.stats()[0].num_nodes),
                     fixed(sum.assemble / steps, 2), fixed(sum.solve / steps, 2), std::to_string(iterations / steps),
                     fixed(sum.total / steps, 2)});
    }
  }
  table.print();
}

const Register registered_fem("fem", bench_fem);

}  // namespace
}  // namespace recoil::bench
