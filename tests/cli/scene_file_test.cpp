// Scene file v1: parsing into a SceneDesc, the resolved
// document, and the bad-scene corpus under tests/cli/bad/ (exit 2, message
// naming the file and the JSON pointer).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "cli/frame_spec.h"
#include "cli/json_cursor.h"
#include "cli/scene_bodies.h"
#include "cli/scene_parser.h"
#include "cli/scene_runner.h"
#include "cli/scene_writer.h"
#include "core/error.h"
#include "sim/world.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

TEST(SceneFile, DemoSceneParsesIntoWorldRenderAndCamera) {
  const cli::SceneDesc scene = cli::load_scene(source_path("assets/scenes/bunny-drop.json"));
  EXPECT_EQ(scene.name, "bunny-drop");
  ASSERT_EQ(scene.bodies.size(), 3u);
  EXPECT_TRUE(scene.bodies[0].is_plane());
  EXPECT_EQ(scene.bodies[1].kind, sim::BodyKind::deformable);
  EXPECT_EQ(scene.bodies[2].kind, sim::BodyKind::rigid);
  ASSERT_EQ(scene.world.planes.size(), 1u);
  ASSERT_EQ(scene.world.bodies.size(), 1u);
  ASSERT_EQ(scene.world.rigid_bodies.size(), 1u);
  const sim::DeformableBodyDesc& bunny = scene.world.bodies[0];
  EXPECT_GT(bunny.mesh.num_triangles(), 3000);  // assets/meshes/bunny.obj, found relative to the scene file
  EXPECT_EQ(bunny.resolution, 10);
  EXPECT_DOUBLE_EQ(bunny.material.youngs_modulus, 2e5);
  EXPECT_DOUBLE_EQ(bunny.static_friction, 0.6);
  EXPECT_DOUBLE_EQ(bunny.kinetic_friction, 0.5);
  EXPECT_EQ(bunny.transform.scale, Eigen::Vector3d::Constant(0.3));
  EXPECT_EQ(bunny.transform.rotation, Eigen::Vector3d(0, 30, 0));
  EXPECT_NEAR(scene.bodies[1].color[0], 0xd9 / 255.0, 1e-6);
  EXPECT_DOUBLE_EQ(scene.world.rigid_bodies[0].density, 500.0);
  EXPECT_EQ(scene.world.rigid_bodies[0].kind, sim::BodyKind::rigid);
  EXPECT_EQ(scene.render.resolution, "1280x720");
  EXPECT_EQ(scene.frame_count(), 91);  // 3 s at 30 fps, both ends included
  EXPECT_TRUE(scene.camera.has_position);
  // The resolved document: absolute mesh path, defaults filled in.
  const nlohmann::json r = cli::resolved_scene(scene);
  EXPECT_TRUE(fs::path(r["bodies"][1]["mesh"].get<std::string>()).is_absolute());
  EXPECT_TRUE(fs::exists(r["bodies"][1]["mesh"].get<std::string>()));
  EXPECT_EQ(r["bodies"][1]["material"]["model"], "corotated");
  EXPECT_EQ(r["bodies"][2]["transform"]["scale"], 1.0);
  EXPECT_EQ(r["bodies"][2]["velocity"], nlohmann::json::array({0.0, 0.0, 0.0}));
}

TEST(SceneFile, ResolvedSceneParsesToTheSameDescription) {
  // Every shipped scene: written out, read back and written again, the same document.
  for (const auto& entry : fs::directory_iterator(source_path("assets/scenes"))) {
    if (entry.path().extension() != ".json") continue;
    const nlohmann::json written = cli::resolved_scene(cli::load_scene(entry.path()));
    EXPECT_EQ(cli::resolved_scene(cli::parse_scene(written, "resolved.json", "/")), written) << entry.path();
  }
  // A mirroring uniform scale stays a vector (a scalar scale is positive), and a float opacity is written short.
  const nlohmann::json mirrored = nlohmann::json::parse(R"({"recoil": 1, "name": "m", "bodies": [
    {"type": "rigid", "primitive": {"box": [0.1, 0.2, 0.3]}, "opacity": 0.3,
     "transform": {"scale": [-1, -1, -1]}}]})");
  const nlohmann::json written = cli::resolved_scene(cli::parse_scene(mirrored, "m.json", "/"));
  EXPECT_EQ(written["bodies"][0]["transform"]["scale"], nlohmann::json::array({-1.0, -1.0, -1.0}));
  EXPECT_EQ(written["bodies"][0]["opacity"].dump(), "0.3");
  EXPECT_EQ(cli::resolved_scene(cli::parse_scene(written, "resolved.json", "/")), written);
  const cli::SceneDesc a = cli::load_scene(source_path("assets/scenes/rollers.json"));
  const cli::SceneDesc b = cli::parse_scene(cli::resolved_scene(a), "resolved.json", "/");
  ASSERT_EQ(b.world.rigid_bodies.size(), 2u);
  EXPECT_EQ(b.world.rigid_bodies[0].kind, sim::BodyKind::kinematic);
  EXPECT_EQ(b.world.rigid_bodies[0].angular_velocity, Eigen::Vector3d(0, 0, -4));
  EXPECT_FLOAT_EQ(b.bodies[1].opacity, 0.5f);
  EXPECT_EQ(b.world.bodies[0].material.model, sim::MaterialModel::neo_hookean);
}

TEST(SceneFile, ScalarAndVectorScaleFrictionFormsAndPrimitives) {
  const fs::path dir = scratch_dir("scene_forms");
  write_file(dir / "s.json", R"({"recoil": 1, "bodies": [
    {"type": "static", "primitive": {"torus": {"major": 0.3, "minor": 0.1}}, "transform": {"scale": [1, 2, 3]}, "friction": 0.4},
    {"type": "rigid", "primitive": {"capsule": {"radius": 0.1, "height": 0.2}}, "friction": {"static": 0.7, "kinetic": 0.2}},
    {"type": "kinematic", "primitive": {"sphere": 0.2}, "motion": {"velocity": [1, 0, 0]}},
    {"type": "deformable", "primitive": {"cylinder": {"radius": 0.1, "height": 0.3}}, "pinned": {"min": [-1, -1, -1], "max": [1, 0, 1]}}
  ]})");
  const cli::SceneDesc scene = cli::load_scene(dir / "s.json");
  EXPECT_EQ(scene.name, "s");  // the file stem when the scene has no name
  ASSERT_EQ(scene.world.rigid_bodies.size(), 3u);
  EXPECT_EQ(scene.world.rigid_bodies[0].kind, sim::BodyKind::fixed);
  EXPECT_EQ(scene.world.rigid_bodies[0].transform.scale, Eigen::Vector3d(1, 2, 3));
  EXPECT_DOUBLE_EQ(scene.world.rigid_bodies[0].friction.kinetic_coefficient, 0.4);
  EXPECT_DOUBLE_EQ(scene.world.rigid_bodies[1].friction.static_coefficient, 0.7);
  EXPECT_DOUBLE_EQ(scene.world.rigid_bodies[1].friction.kinetic_coefficient, 0.2);
  EXPECT_EQ(scene.world.rigid_bodies[2].velocity, Eigen::Vector3d(1, 0, 0));
  ASSERT_TRUE(scene.world.bodies[0].pinned.has_value());
  EXPECT_EQ(scene.bodies[3].name, "deformable3");  // default names are unique
  // Default colours come from the palette, one per mesh body.
  EXPECT_NE(scene.bodies[0].color, scene.bodies[1].color);
}

TEST(SceneFile, NearMissSuggestions) {
  EXPECT_EQ(cli::near_miss("youngs_modulos", {"model", "youngs_modulus", "density"}), "youngs_modulus");
  EXPECT_EQ(cli::near_miss("frction", {"friction", "transform"}), "friction");
  EXPECT_EQ(cli::near_miss("banana", {"friction", "transform"}), "");
}

TEST(SceneFile, WorldErrorsNameTheSceneFileAndPointer) {
  // World's own lists order bodies by kind; its errors name the scene's /bodies/j.
  const fs::path dir = scratch_dir("scene_world_error");
  write_file(dir / "w.json", R"({"recoil": 1, "bodies": [
    {"type": "plane"}, {"type": "rigid", "primitive": {"sphere": 0.1}},
    {"type": "deformable", "primitive": {"sphere": 0.1}}, {"type": "deformable", "primitive": {"sphere": 0.1}}]})");
  const std::string file = (dir / "w.json").string();
  cli::SceneDesc scene = cli::load_scene(dir / "w.json");
  scene.world.bodies[1].material.poisson_ratio = 0.7;  // past what the parser lets through
  scene.world.rigid_bodies[0].density = -1.0;
  scene.world.planes[0].normal.setZero();
  scene.world.dt = 0.0;
  const auto error_of = [](const sim::WorldDesc& desc) {
    try {
      sim::World world(desc);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of(scene.world), file + ": /simulation/dt: must be > 0");
  scene.world.dt = 0.01;
  EXPECT_EQ(error_of(scene.world).rfind(file + ": /bodies/3/material/poisson_ratio: ", 0), 0u) << error_of(scene.world);
  scene.world.bodies[1].material.poisson_ratio = 0.3;
  EXPECT_EQ(error_of(scene.world), file + ": /bodies/1/density: must be > 0");
  scene.world.rigid_bodies[0].density = 1000.0;
  EXPECT_EQ(error_of(scene.world), file + ": /bodies/0: point must be finite and normal non-zero");
}

TEST(FrameSpec, RangesStepsAndLists) {
  EXPECT_EQ(cli::parse_frame_spec("1-5"), (std::vector<int>{1, 2, 3, 4, 5}));
  EXPECT_EQ(cli::parse_frame_spec("1-10:4"), (std::vector<int>{1, 5, 9}));
  EXPECT_EQ(cli::parse_frame_spec("7-9,1,3,3"), (std::vector<int>{1, 3, 7, 8, 9}));
  for (const char* bad : {"", "0", "5-1", "a-b", "1,,2", "1-", "3:2", "1-10:0", "1,"})
    EXPECT_THROW(cli::parse_frame_spec(bad), Error) << bad;
  try {
    cli::parse_frame_spec("1-10:0");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the step (:N) is at least 1"), std::string::npos) << e.what();
  }
}

struct BadScene {
  const char* file;
  std::vector<std::string> expected;  // substrings of the one error line
};

TEST(SceneFile, BadSceneCorpusGivesExit2NamingFileAndPointer) {
  const std::vector<BadScene> corpus = {
      {"syntax.json", {"syntax.json:6:", "syntax error"}},
      {"wrong-type.json", {"/simulation/dt: expected a number, got a string \"fast\""}},
      {"unknown-key.json", {"/bodies/1/material/youngs_modulos: unknown key", "did you mean \"youngs_modulus\"?"}},
      {"out-of-range.json", {"/bodies/1/material/poisson_ratio: must be in [0, 0.5), got 0.7"}},
      {"missing-mesh.json", {"/bodies/1/mesh: file not found", "no-such-mesh.obj"}},
      {"empty-mesh.json", {"/bodies/1/mesh:", "empty.obj"}},
      {"vector-length.json", {"/simulation/gravity: expected 3 numbers"}},
      {"unknown-type.json", {"/bodies/1/type: unknown body type", "did you mean \"deformable\"?"}},
      {"duplicate-name.json", {"/bodies/1/name: duplicate body name \"ground\""}},
      {"not-allowed.json", {"/bodies/1/", "not allowed for a rigid body"}},
      {"follow-unknown.json", {"/render/camera/body: no body named \"ghost\""}},
      {"version.json", {"/recoil: unsupported scene format version 2"}},
      {"bad-color.json", {"/bodies/1/color: expected a colour"}},
      {"missing-bodies.json", {"/bodies: is required"}},
      {"friction-order.json", {"/bodies/1/friction/kinetic: must be <= the static coefficient"}},
      {"friction-type.json", {"/bodies/1/friction: expected a number or an object {\"static\", \"kinetic\"}, got a string \"high\""}},
      {"tets-resolution.json", {"/bodies/1/tets/resolution: must be in [1, 256], got 0"}},
      {"negative-scale.json", {"/bodies/1/transform/scale: must be in [1e-09, 1e+09], got -1"}},
      {"tiny-scale.json", {"/bodies/1: is 1e-09 m across once scaled by its transform; at least 1e-06 m"}},
      {"top-level-typo.json", {"/simulaton: unknown key", "did you mean \"simulation\"?"}},
      {"fps-zero.json", {"/render/fps: must be in [0.001, 1000], got 0"}},
      {"up-axis.json", {"/bodies/1/up: unknown up axis \"+W\"", "+X, -X, +Y, -Y, +Z or -Z"}},
      {"up-primitive.json", {"/bodies/1/up: only for mesh files"}},
      {"duplicate-key.json", {"/bodies/1/material/density: given twice in one object"}},
      {"mesh-folder.json", {"/bodies/1/mesh: a folder, not a file"}},
      {"camera-azimuth-position.json",
       {"/render/camera/azimuth: has no effect on a camera at a given position; give position or azimuth"}},
      {"scale-type.json", {"/bodies/1/transform/scale: expected a number or an array of 3 numbers, got a boolean"}},
      {"kinematic-velocity.json",
       {"/bodies/1/velocity: not allowed for a kinematic body;",
        "a kinematic body moves by its \"motion\": {\"velocity\""}},
  };
  const fs::path out = scratch_dir("bad_scenes");
  for (const BadScene& bad : corpus) {
    const fs::path file = source_path(std::string("tests/cli/bad/") + bad.file);
    ASSERT_TRUE(fs::exists(file)) << file;
    const CommandResult r = run_recoil("run " + shell_quote(file) + " --no-render -o " + shell_quote(out));
    std::cout << bad.file << " -> exit " << r.exit_code << ": " << r.err;
    EXPECT_EQ(r.exit_code, 2) << bad.file << ": " << r.err;
    EXPECT_EQ(r.err.rfind("recoil: error: " + file.string(), 0), 0u) << "names the file first: " << r.err;
    for (const std::string& part : bad.expected) EXPECT_NE(r.err.find(part), std::string::npos) << bad.file << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  }
}

}  // namespace recoil::test
