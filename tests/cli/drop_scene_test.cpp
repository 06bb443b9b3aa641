// build_drop_scene: where `recoil drop` puts its bodies.
#include <gtest/gtest.h>

#include <limits>

#include "cli/drop_scene.h"
#include "cli/scene_parser.h"
#include "sim/world.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace {

// The lowest point of every drawn surface of `document`'s world, m.
double lowest_point(const nlohmann::json& document) {
  const cli::SceneDesc scene = cli::parse_scene(document, "drop", source_path("."));
  const sim::World world(scene.world);
  double lowest = std::numeric_limits<double>::infinity();
  for (const sim::BodySurface& s : world.surfaces()) lowest = std::min(lowest, s.positions.col(1).minCoeff());
  return lowest;
}

// --height is where the lowest point of the lowest body starts, for one body
// and for a pile of bodies turned every which way (whose bounding spheres
// had put it 0.23 m higher for the bunny).
TEST(DropScene, TheLowestPointStartsAtTheDropHeight) {
  for (const int count : {1, 4}) {
    cli::DropSettings settings;
    settings.meshes = {source_path("assets/meshes/bunny.obj").string()};
    settings.material = "rigid";
    settings.count = count;
    settings.height = 0.3;
    EXPECT_NEAR(lowest_point(cli::build_drop_scene(settings)), 0.3, 1e-9) << count << " bodies";
  }
}

}  // namespace
}  // namespace recoil::test
