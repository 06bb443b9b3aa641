// Validation check: a pile of rigid meshes, as `recoil drop` builds it, lands
// at the default time step without the bodies sinking into each other.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli/drop_scene.h"
#include "cli/scene_parser.h"
#include "tests/test_support.h"
#include "tests/validation/measured.h"

namespace recoil::sim::validation {
namespace {

// `recoil drop bunny.obj --count 8 --material rigid` at its default dt
// (4 ms): landing bunnies switch on many more normal rows of one rigid pair
// than the pair has relative DoFs, rows whose right-hand sides disagree
// (docs/decisions/023-dependent-rows-exchange.md). The pile check: the run
// goes on, and no frame is deeper than the contact margin.
TEST(RigidPile, EightBunniesLandAtTheDefaultStep) {
  cli::DropSettings settings;
  settings.meshes = {test::source_path("assets/meshes/bunny.obj").string()};
  settings.material = "rigid";
  settings.count = 8;
  const cli::SceneDesc scene =
      cli::parse_scene(cli::build_drop_scene(settings), "drop", test::source_path("."));
  World world(scene.world);
  double penetration = 0.0;
  int unconverged = 0, stepped = 0;
  for (int i = 0; i < 300; ++i) {
    const StepReport r = world.step();
    ASSERT_EQ(r.status, StepStatus::ok) << "step " << r.step << " body " << r.body;
    ++stepped;
    unconverged += !r.solver_converged;
    penetration = std::max(penetration, r.max_penetration);
  }
  Measured() << "rigid bunny pile (8, `recoil drop --material rigid`, dt " << scene.world.dt * 1e3 << " ms): "
             << unconverged << " of " << stepped << " steps unconverged, max penetration " << penetration * 1e3
             << " mm (margin " << scene.world.contact.margin * 1e3 << " mm)";
  EXPECT_LT(penetration, scene.world.contact.margin);
}

}  // namespace
}  // namespace recoil::sim::validation
