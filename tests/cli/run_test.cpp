// `recoil run` and `recoil drop` end to end: every
// shipped scene runs, stats.jsonl keys and types, determinism, --resume,
// exit 3 on a diverging scene with the earlier frames kept, and drop piles
// that reproduce and save a scene `run` accepts; the memory cap, counted
// from a mesh's tetrahedra and triangles.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "render/png.h"
#include "tests/cli/box_mesh_file.h"
#include "tests/cli/json_lines.h"
#include "tests/cli/sphere_stl_file.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::vector<json> read_stats(const fs::path& path) { return json_lines(file_bytes(path)); }

// Stats with the wall-clock fields removed (they differ between runs).
json without_timings(json line) {
  line.erase("ms");
  line["solver"].erase("ms");
  return line;
}

int count_pngs(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ".png";
  return n;
}

}  // namespace

TEST(RunCommand, EveryShippedSceneRuns) {
  std::vector<fs::path> scenes;
  for (const auto& e : fs::recursive_directory_iterator(source_path("assets/scenes")))
    if (e.path().extension() == ".json") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 14u);
  for (const fs::path& scene : scenes) {
    const fs::path dir = scratch_dir("every_scene_" + scene.stem().string() + scene.parent_path().filename().string());
    const CommandResult r = run_recoil("run " + shell_quote(scene) + " --frames 1-2 --no-render -q -o " + shell_quote(dir));
    EXPECT_EQ(r.exit_code, 0) << scene << ": " << r.err;
    const std::vector<json> stats = read_stats(dir / "stats.jsonl");
    ASSERT_EQ(stats.size(), 2u) << scene;
    EXPECT_EQ(stats[1]["frame"], 2);
    EXPECT_TRUE(fs::exists(dir / "scene.json"));
    const json run = json::parse(file_bytes(dir / "run.json"));
    EXPECT_EQ(run["exit"]["code"], 0);
    std::cout << scene.filename().string() << ": " << run["steps"] << " steps, " << run["timings_ms"]["total"] << " ms\n";
  }
}

TEST(RunCommand, RendersTheSelectedFramesAndWritesSpecStats) {
  const fs::path dir = scratch_dir("run_render");
  const fs::path scene = source_path("assets/scenes/bunny-drop.json");
  const CommandResult r = run_recoil("run " + shell_quote(scene) + " --frames 1,3 --resolution 64x48 -o " + shell_quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_pngs(dir), 2);
  ASSERT_TRUE(fs::exists(dir / "frame_0003.png"));
  const render::Image image = render::read_png(dir / "frame_0003.png");
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  const std::vector<json> stats = read_stats(dir / "stats.jsonl");
  ASSERT_EQ(stats.size(), 2u);
  const json& s = stats[1];
  EXPECT_EQ(s["frame"], 3);
  EXPECT_NEAR(s["time"].get<double>(), 2.0 / 30.0, 1e-12);  // frame k at (k - 1) / fps
  EXPECT_GE(s["sim_time"].get<double>(), 2.0 / 30.0);
  EXPECT_LT(s["sim_time"].get<double>(), 2.0 / 30.0 + 0.004);
  // Frame 3 sums the steps between frames 2 and 3 only: frame k is taken at
  // the first step at or after its time, ceil((k - 1) / (fps dt)), so 17 - 9 of them.
  EXPECT_EQ(s["steps"], 8);
  EXPECT_EQ(stats[0]["steps"], 0);  // frame 1 is the initial state
  for (const char* key : {"contacts", "active", "sticking", "sliding"}) EXPECT_TRUE(s[key].is_number_integer()) << key;
  EXPECT_TRUE(s["solver"]["iterations"].is_number_integer());
  EXPECT_TRUE(s["solver"]["restarts"].is_number_integer());
  EXPECT_TRUE(s["solver"]["residual"].is_number());
  EXPECT_TRUE(s["solver"]["ms"].is_number());
  EXPECT_TRUE(s["max_penetration"].is_number());
  for (const char* key : {"step", "collision", "solve", "render", "encode"}) EXPECT_TRUE(s["ms"][key].is_number()) << key;
  EXPECT_GT(s["ms"]["render"].get<double>(), 0.0);
  // Dynamic bodies in scene order: the deformable bunny, then the rigid crate.
  ASSERT_EQ(s["bodies"].size(), 2u);
  const json& bunny = s["bodies"][0];
  EXPECT_EQ(bunny["name"], "bunny");
  EXPECT_EQ(s["bodies"][1]["name"], "crate");
  EXPECT_EQ(bunny["com"].size(), 3u);
  EXPECT_EQ(bunny["velocity"].size(), 3u);
  for (const char* key : {"kinetic_energy", "elastic_energy", "min_volume_ratio"}) EXPECT_TRUE(bunny[key].is_number()) << key;
  // Falling from rest, both bodies move down at g t at the frame's own time
  // (2/30 s), which lies between two 4 ms steps: the stats are not those of
  // the step the frame shows (17, at 0.068 s).
  std::cout << "bunny velocity at frame 3: " << bunny["velocity"].dump() << "\n";
  for (const json& body : s["bodies"])
    EXPECT_NEAR(body["velocity"][1].get<double>(), -9.81 * 2.0 / 30.0, 1e-9) << body["name"];
  const json run = json::parse(file_bytes(dir / "run.json"));
  for (const char* key : {"version", "build", "timings_ms", "solver_totals", "exit"}) EXPECT_TRUE(run.contains(key)) << key;
  // The summary's worst KKT is in the solver totals too, beside the residual the solves stopped at.
  EXPECT_EQ(run["solver_totals"]["worst_kkt"], run["warnings"]["worst_kkt"]) << run.dump();
  // The commit is the one built, taken at build time rather than when the
  // build folder was configured ("unknown" outside a git checkout).
  const fs::path head = dir / "head.txt";
  const std::string describe = "git -C " + shell_quote(source_path("")) + " describe --always > " + shell_quote(head) + " 2>/dev/null";
  std::string commit = std::system(describe.c_str()) == 0 ? file_bytes(head) : "unknown";
  commit.erase(commit.find_last_not_of("\n") + 1);
  EXPECT_EQ(run["build"]["git"].get<std::string>().rfind(commit, 0), 0u) << run["build"] << " built from " << commit;
  EXPECT_EQ(run["frames"]["written"], 2);
  EXPECT_GT(run["peak_memory_mib"].get<double>(), 1.0);  // the run's own high-water mark, MiB
  const json resolved = json::parse(file_bytes(dir / "scene.json"));
  EXPECT_EQ(resolved["render"]["resolution"], json::array({64, 48}));  // the override is recorded
}

TEST(RunCommand, ColorAndCameraDistanceOverridesGiveASceneRunAccepts) {
  // The overrides change the scene itself: the recorded scene.json must say
  // what was drawn and parse again (--camera-distance 0 means "fit").
  const fs::path dir = scratch_dir("run_overrides"), rerun = scratch_dir("run_overrides_rerun");
  const fs::path scene = source_path("assets/scenes/bunny-drop.json");
  CommandResult r = run_recoil("run " + shell_quote(scene) + " --frames 1 --resolution 64x48 --color '#ff0000' --camera-distance 0 -o " +
                               shell_quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json resolved = json::parse(file_bytes(dir / "scene.json"));
  int colored = 0;
  for (const json& body : resolved["bodies"])
    if (body.contains("color")) {
      EXPECT_EQ(body["color"], "#ff0000") << body["name"];
      ++colored;
    }
  EXPECT_GE(colored, 2);  // the bunny and the crate
  EXPECT_FALSE(resolved["render"].contains("camera") && resolved["render"]["camera"].contains("distance"));
  r = run_recoil("run " + shell_quote(dir / "scene.json") + " --frames 1 --resolution 64x48 -o " + shell_quote(rerun));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(file_bytes(dir / "frame_0001.png"), file_bytes(rerun / "frame_0001.png"));  // drawn the same
}

TEST(RunCommand, ACameraDistanceThatCannotApplyIsRefused) {
  // The demo's camera stands at a given position: a distance from the target cannot move it.
  const fs::path dir = scratch_dir("run_distance_refused");
  const fs::path scene = source_path("assets/scenes/bunny-drop.json");
  CommandResult r = run_recoil("run " + shell_quote(scene) + " --camera-distance 6 --no-render -o " + shell_quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--camera-distance: " + scene.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/render/camera/position"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // Nor may a scene file give both.
  json document = json::parse(file_bytes(scene));
  document["render"]["camera"]["distance"] = 6;
  for (json& body : document["bodies"])
    if (body.contains("mesh")) body["mesh"] = source_path("assets/meshes/bunny.obj").string();
  std::ofstream(dir / "both.json") << document.dump();
  r = run_recoil("run " + shell_quote(dir / "both.json") + " --no-render -o " + shell_quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find((dir / "both.json").string() + ": /render/camera/distance: has no effect"), std::string::npos) << r.err;
}

TEST(RunCommand, SameSceneTwiceGivesIdenticalFramesAndStats) {
  const fs::path a = scratch_dir("run_det_a"), b = scratch_dir("run_det_b");
  const fs::path scene = source_path("assets/scenes/jelly-stack.json");
  for (const fs::path& dir : {a, b}) {
    const CommandResult r = run_recoil("run " + shell_quote(scene) + " --frames 1-3 --resolution 64x48 -o " + shell_quote(dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  for (const char* name : {"frame_0001.png", "frame_0002.png", "frame_0003.png"})
    EXPECT_EQ(file_bytes(a / name), file_bytes(b / name)) << name;
  EXPECT_NE(file_bytes(a / "frame_0001.png"), file_bytes(a / "frame_0003.png"));  // the orbit camera moves
  const std::vector<json> sa = read_stats(a / "stats.jsonl"), sb = read_stats(b / "stats.jsonl");
  ASSERT_EQ(sa.size(), 3u);
  ASSERT_EQ(sb.size(), 3u);
  for (size_t i = 0; i < sa.size(); ++i) EXPECT_EQ(without_timings(sa[i]), without_timings(sb[i])) << "frame " << i + 1;
  EXPECT_EQ(file_bytes(a / "scene.json"), file_bytes(b / "scene.json"));
}

TEST(RunCommand, ResumeSkipsFramesAlreadyOnDisk) {
  const fs::path dir = scratch_dir("run_resume");
  const std::string command = "run " + shell_quote(source_path("assets/scenes/validation/rest.json")) +
                              " --frames 1-3 --resolution 32x32 --msaa 0 -o " + shell_quote(dir);
  ASSERT_EQ(run_recoil(command).exit_code, 0);
  // A whole PNG of the frame size in frame 1 (a marker) survives a resume;
  // the missing frame 2 is rendered again.
  const std::string frame2 = file_bytes(dir / "frame_0002.png");
  render::Image marker;
  marker.width = marker.height = 32;
  marker.rgba.assign(32 * 32 * 4, 200);
  render::write_png(dir / "frame_0001.png", marker);
  const std::string kept = file_bytes(dir / "frame_0001.png");
  fs::remove(dir / "frame_0002.png");
  const CommandResult r = run_recoil(command + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(file_bytes(dir / "frame_0001.png"), kept);
  EXPECT_EQ(file_bytes(dir / "frame_0002.png"), frame2);
  const json run = json::parse(file_bytes(dir / "run.json"));
  EXPECT_EQ(run["frames"]["written"], 1);
  EXPECT_EQ(run["frames"]["skipped"], 2);
  EXPECT_EQ(read_stats(dir / "stats.jsonl").size(), 3u);  // the simulation still ran every frame
}

// Frames on disk belong to the scene in the scene.json beside them: a resume
// with another scene (here, another gravity) draws every frame again and
// says where the scenes differ, instead of mixing two simulations.
TEST(RunCommand, ResumeWithAnotherSceneDrawsEveryFrameAgain) {
  const fs::path dir = scratch_dir("run_resume_other_scene");
  json scene = json::parse(file_bytes(source_path("assets/scenes/validation/rest.json")));
  const fs::path path = dir / "rest.json", out = dir / "out";
  const std::string command = "run " + shell_quote(path) + " --frames 1-3 --resolution 32x32 --msaa 0 -o " + shell_quote(out);
  std::ofstream(path) << scene.dump();
  ASSERT_EQ(run_recoil(command).exit_code, 0);
  scene["simulation"]["gravity"] = json::array({0.0, -1.62, 0.0});
  std::ofstream(path, std::ios::trunc) << scene.dump();
  const CommandResult r = run_recoil(command + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("--resume drew every frame again: scene.json differs at /simulation/gravity"), std::string::npos)
      << r.err;
  const json run = json::parse(file_bytes(out / "run.json"));
  EXPECT_EQ(run["frames"]["written"], 3);
  EXPECT_EQ(run["frames"]["skipped"], 0);
}

// A frame past the scene's duration is refused before anything is made:
// drawing it would simulate beyond the duration that scene.json records.
TEST(RunCommand, FramesPastTheDurationAreRefused) {
  const fs::path dir = scratch_dir("run_frames_past");
  const fs::path scene = source_path("assets/scenes/validation/rest.json");  // 4 s at 30 fps: 121 frames
  const CommandResult r = run_recoil("run " + shell_quote(scene) + " --frames 120-200 --no-render -o " + shell_quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--frames: frame 200 is past the last, 121 (simulation.duration 4 s at render.fps 30)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A --stats path that names a folder is a mistake in the command (exit 2),
// found before anything is written.
TEST(RunCommand, AStatsPathThatIsAFolderIsRefusedUpFront) {
  const fs::path dir = scratch_dir("run_stats_folder");
  fs::create_directories(dir / "stats");
  const CommandResult r = run_recoil("run " + shell_quote(source_path("assets/scenes/validation/rest.json")) +
                                     " --no-render --stats " + shell_quote(dir / "stats") + " -o " +
                                     shell_quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--stats " + (dir / "stats").string() + " is a folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A rerun into a folder that a longer run wrote leaves one run's frames:
// those past its frame count (or of another name width) go, the ones within
// it stay even when not selected, and files that are no frame stay.
TEST(RunCommand, ARerunRemovesTheFramesOfALongerRunAndSaysSo) {
  const fs::path dir = scratch_dir("run_rerun_shorter");
  const fs::path scene = source_path("assets/scenes/validation/rest.json");  // 4 s at 30 fps: 121 frames
  fs::create_directories(dir);
  for (const char* name : {"frame_0009.png", "frame_9999.png", "frame_00003.png", "frame_12.png", "frame_notes.txt",
                           "frame_0005.png.bak"})
    std::ofstream(dir / name) << "earlier";
  const CommandResult r = run_recoil("run " + shell_quote(scene) + " --frames 1-2 --resolution 32x32 --msaa 0 -o " +
                                     shell_quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("removed 2 frames of another run (frame_00003.png to frame_9999.png)"), std::string::npos)
      << r.err;
  for (const char* gone : {"frame_9999.png", "frame_00003.png"}) EXPECT_FALSE(fs::exists(dir / gone)) << gone;
  for (const char* kept : {"frame_0001.png", "frame_0002.png", "frame_0009.png", "frame_12.png", "frame_notes.txt",
                           "frame_0005.png.bak"})
    EXPECT_TRUE(fs::exists(dir / kept)) << kept;
  EXPECT_EQ(json::parse(file_bytes(dir / "run.json"))["frames"]["removed"], 2);
}

// Frames drawn for another scene never stay beside this one's: a rerun of
// the same scene draws a subset among the frames it drew before, but one
// whose scene differs (here only the resolution) removes every frame it
// did not draw. A run without frames removes none.
TEST(RunCommand, ARunOfAnotherSceneLeavesNoneOfTheOldScenesFrames) {
  const fs::path dir = scratch_dir("run_other_scene");
  const std::string scene = shell_quote(source_path("assets/scenes/validation/rest.json"));
  const std::string out = " --msaa 0 -o " + shell_quote(dir);
  ASSERT_EQ(run_recoil("run " + scene + " --frames 1-6 --resolution 32x32 -q" + out).exit_code, 0);
  const CommandResult same = run_recoil("run " + scene + " --frames 1-2 --resolution 32x32" + out);
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(same.err.find("removed"), std::string::npos) << same.err;
  for (int k = 1; k <= 6; ++k) EXPECT_TRUE(fs::exists(dir / ("frame_000" + std::to_string(k) + ".png"))) << k;
  const CommandResult other = run_recoil("run " + scene + " --frames 1-2 --resolution 48x32" + out);
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.err.find("removed 4 frames of another run (frame_0003.png to frame_0006.png)"), std::string::npos)
      << other.err;
  for (int k = 3; k <= 6; ++k) EXPECT_FALSE(fs::exists(dir / ("frame_000" + std::to_string(k) + ".png"))) << k;
  EXPECT_EQ(render::read_png(dir / "frame_0001.png").width, 48);
  const CommandResult none = run_recoil("run " + scene + " --frames 1-2 --no-render --resolution 64x32" + out);
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_EQ(none.err.find("removed"), std::string::npos) << none.err;
  EXPECT_TRUE(fs::exists(dir / "frame_0001.png"));
  // That run wrote its scene.json over the one that drew the frames: what
  // drew them is unknown now, and a render run of their own scene keeps them.
  const CommandResult again = run_recoil("run " + scene + " --frames 1 --resolution 48x32" + out);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.err.find("removed"), std::string::npos) << again.err;
  EXPECT_TRUE(fs::exists(dir / "frame_0002.png"));
}

// The shipped rollers example to its end: the soft ball is drawn through
// the 12 cm gap between the rollers (it used to be squeezed into 2 cm, its
// tets to a seventh of their volume, and the run blew up at frame 12) and
// lies on the ground below them.
TEST(RunCommand, TheRollersExampleDrawsTheBallThroughTheGap) {
  const fs::path dir = scratch_dir("run_rollers_example");
  const CommandResult r =
      run_recoil("run " + shell_quote(source_path("assets/scenes/rollers.json")) + " --no-render -q -o " + shell_quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<json> stats = read_stats(dir / "stats.jsonl");
  ASSERT_FALSE(stats.empty());
  const json& dough = stats.back()["bodies"][0];
  EXPECT_LT(dough["com"][1].get<double>(), 0.1) << dough.dump();   // the rollers' undersides are at 0.2 m
  EXPECT_LT(std::abs(dough["com"][0].get<double>()), 0.05) << dough.dump();  // between them, not round one
}

TEST(RunCommand, DivergingSceneExits3NamingFrameAndBodyAndKeepsEarlierFrames) {
  const fs::path dir = scratch_dir("run_diverge");
  // A column of nearly no stiffness, pinned at its base, with huge steps:
  // its top falls through its bottom and stays inverted.
  const fs::path scene = dir / "collapse.json";
  std::ofstream(scene) << R"({"recoil": 1, "name": "collapse",
    "simulation": {"dt": 0.05, "duration": 2},
    "bodies": [{"name": "column", "type": "deformable", "primitive": {"box": [0.1, 0.6, 0.1]},
                "tets": {"resolution": 4}, "material": {"youngs_modulus": 1, "poisson_ratio": 0.3, "density": 1000},
                "pinned": {"min": [-1, -1, -1], "max": [1, 0.01, 1]}, "self_contact": false, "transform": {"position": [0, 0.3, 0]}}],
    "render": {"fps": 10, "resolution": [32, 32], "msaa": 0}})";
  const fs::path out = dir / "out";
  const CommandResult r = run_recoil("run " + shell_quote(scene) + " -o " + shell_quote(out));
  std::cout << r.err;
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("recoil: error: " + scene.string() + ": simulation failed at frame "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("body 'column'"), std::string::npos) << r.err;
  // Why: 1000 kg/m^3 x 9.81 m/s^2 x 0.6 m over E = 1 Pa.
  EXPECT_NE(r.err.find("its own weight alone strains it by about 5.9e+05 % (density 1000 kg/m^3 x g x height 0.6 m / E 1 Pa)"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(out / "frame_0001.png"));
  const json run = json::parse(file_bytes(out / "run.json"));
  EXPECT_EQ(run["exit"]["code"], 3);
  const int frames = count_pngs(out);
  EXPECT_GE(frames, 1);
  EXPECT_EQ(static_cast<int>(read_stats(out / "stats.jsonl").size()), frames);
  for (const auto& e : fs::directory_iterator(out)) EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

// A solve capped at 2 iterations cannot converge once the box lands: the run
// still succeeds, but its summary says so (even with -q), run.json records it,
// and --strict makes it exit 3 with every output written.
TEST(RunCommand, UnconvergedSolvesAreReportedAndStrictFailsOnThem) {
  const fs::path dir = scratch_dir("run_strict");
  const fs::path scene = dir / "capped.json";
  std::ofstream(scene) << R"({"recoil": 1, "name": "capped",
    "simulation": {"dt": 0.01, "duration": 0.3, "solver": {"max_iterations": 2}},
    "bodies": [{"type": "plane"},
               {"name": "box", "type": "rigid", "primitive": {"box": [0.2, 0.2, 0.2]}, "transform": {"position": [0, 0.11, 0]}}],
    "render": {"fps": 10, "resolution": [32, 32], "msaa": 0}})";
  const CommandResult lenient = run_recoil("run " + shell_quote(scene) + " -q --no-render -o " + shell_quote(dir / "lenient"));
  EXPECT_EQ(lenient.exit_code, 0) << lenient.err;
  EXPECT_NE(lenient.err.find("warning: "), std::string::npos) << lenient.err;
  EXPECT_NE(lenient.err.find(" solves did not converge, the first at frame "), std::string::npos) << lenient.err;
  EXPECT_NE(lenient.err.find(" (worst KKT residual "), std::string::npos) << lenient.err;
  const json run = json::parse(file_bytes(dir / "lenient" / "run.json"));
  EXPECT_GT(run["warnings"]["not_converged_steps"].get<int>(), 0);
  EXPECT_GT(run["warnings"]["worst_kkt"].get<double>(), 0.0);
  // Dropped 1 cm, the box lands at t = 0.045 s: among frame 2's steps (10 fps, dt 10 ms).
  EXPECT_EQ(run["warnings"]["first_unconverged_frame"].get<int>(), 2);
  EXPECT_EQ(run["exit"]["code"], 0);

  const fs::path out = dir / "strict";
  const CommandResult strict = run_recoil("run " + shell_quote(scene) + " -q --strict -o " + shell_quote(out));
  std::cout << strict.err;
  EXPECT_EQ(strict.exit_code, 3) << strict.err;
  EXPECT_NE(strict.err.find("recoil: error: " + scene.string() + ": --strict: "), std::string::npos) << strict.err;
  EXPECT_EQ(count_pngs(out), 4);
  EXPECT_EQ(read_stats(out / "stats.jsonl").size(), 4u);
  EXPECT_EQ(json::parse(file_bytes(out / "run.json"))["exit"]["code"], 3);

  // A scene whose solves all converge has no warning to give.
  const CommandResult clean = run_recoil("run " + shell_quote(source_path("assets/scenes/validation/slide-to-stop.json")) +
                                         " -q --strict --frames 1-3 --no-render -o " + shell_quote(dir / "clean"));
  EXPECT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(clean.err, "");
}

// --collision-triangles reaches the scene (and so a rerun), and `info` tells
// the drawn mesh from what contact sees.
TEST(DropCommand, CollisionBudgetIsRecordedAndReported) {
  const fs::path dir = scratch_dir("drop_collision");
  const fs::path bunny = source_path("assets/meshes/bunny.obj");
  const CommandResult r = run_recoil("drop " + shell_quote(bunny) + " --collision-triangles 800 --frames 1-2 --no-render -q -o " +
                                     shell_quote(dir / "out") + " --save-scene " + shell_quote(dir / "drop.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json scene = json::parse(file_bytes(dir / "drop.json"));
  EXPECT_EQ(scene["bodies"][1]["collision"]["triangles"], 800);
  const CommandResult info = run_recoil("info --json " + shell_quote(dir / "drop.json"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const json body = json::parse(info.out)["bodies"][1];
  EXPECT_EQ(body["surface_triangles"], 3674);
  EXPECT_LE(body["collision_triangles"].get<int>(), 800);
  EXPECT_GT(body["collision_offset"].get<double>(), 0.0);
  // How far it reaches below the drawn mesh: some of the offset, never more.
  EXPECT_GE(body["collision_below"].get<double>(), 0.0);
  EXPECT_LE(body["collision_below"].get<double>(), body["collision_offset"].get<double>() + 1e-12);
  // The text says what the two lengths are.
  const CommandResult text = run_recoil("info " + shell_quote(dir / "drop.json"));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const std::string triangles = std::to_string(body["collision_triangles"].get<int>());
  EXPECT_NE(text.out.find("3674 triangles (collision surface " + triangles + " triangles, up to "),
            std::string::npos) << text.out;
  EXPECT_NE(text.out.find(" mm outside the drawn mesh and "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(" mm below its lowest point)"), std::string::npos) << text.out;
  EXPECT_EQ(run_recoil("drop " + shell_quote(bunny) + " --collision-triangles 800 --collision-edge 0.01").exit_code, 2);
}

TEST(DropCommand, SeededPileReproducesAndSavesASceneRunAccepts) {
  const fs::path a = scratch_dir("drop_a"), b = scratch_dir("drop_b");
  const fs::path bunny = source_path("assets/meshes/bunny.obj");
  for (const fs::path& dir : {a, b}) {
    const CommandResult r = run_recoil("drop " + shell_quote(bunny) + " --count 3 --material jelly --frames 1-2 --no-render -o " +
                                       shell_quote(dir / "out") + " --save-scene " + shell_quote(dir / "pile.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(file_bytes(a / "pile.json"), file_bytes(b / "pile.json"));
  const std::vector<json> sa = read_stats(a / "out" / "stats.jsonl"), sb = read_stats(b / "out" / "stats.jsonl");
  ASSERT_EQ(sa.size(), 2u);
  for (size_t i = 0; i < sa.size(); ++i) EXPECT_EQ(without_timings(sa[i]), without_timings(sb[i]));
  ASSERT_EQ(sa[0]["bodies"].size(), 3u);
  // A loose pile: the bodies start apart, above the ground, at different heights.
  std::vector<double> heights;
  for (const json& body : sa[0]["bodies"]) heights.push_back(body["com"][1].get<double>());
  std::cout << "pile heights " << sa[0]["bodies"][0]["com"] << " " << sa[0]["bodies"][1]["com"] << " " << sa[0]["bodies"][2]["com"] << "\n";
  for (double h : heights) EXPECT_GT(h, 0.1);
  const json saved = json::parse(file_bytes(a / "pile.json"));
  EXPECT_EQ(saved["bodies"].size(), 4u);  // ground + 3
  const fs::path rerun = scratch_dir("drop_rerun");
  const CommandResult r = run_recoil("run " + shell_quote(a / "pile.json") + " --frames 1-2 --no-render -o " + shell_quote(rerun));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<json> sr = read_stats(rerun / "stats.jsonl");
  ASSERT_EQ(sr.size(), 2u);
  EXPECT_EQ(without_timings(sr[1]), without_timings(sa[1]));  // the saved scene is the scene that ran
}

TEST(DropCommand, AMemoryLimitBelowWhatTheProcessHoldsRefusesTheRun) {
  // The bunny's tets and buffers are a few MiB; the process itself (libraries,
  // the imported mesh) is tens: a 10 MiB limit must count both, and the
  // message blames no field of the scene for the process's own share.
  const fs::path dir = scratch_dir("drop_memory_limit");
  const CommandResult r = run_recoil("--max-memory 0.01 drop " + shell_quote(source_path("assets/meshes/bunny.obj")) +
                                     " --no-render --seconds 0.1 -o " + shell_quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("(itself and the meshes read), more than the 0.01 GiB allowed (--max-memory): raise the limit"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("/bodies/"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "run.json"));
}

// A dense scan costs memory by its triangles, whatever the lattice: a
// 250 000-triangle sphere (binary STL) under a cap below what it needs is
// refused naming the mesh, and the estimate the refusal gives is not below
// what the same turntable then uses (run.json's peak).
TEST(TurntableCommand, AMemoryLimitCountsWhatAMeshsTrianglesNeed) {
  const fs::path dir = scratch_dir("turntable_memory_triangles");
  const fs::path stl = write_sphere_stl(dir / "scan.stl", 250);
  const std::string args = "turntable " + shell_quote(stl) + " --turn-frames 2 --resolution 64x48 -o ";
  const CommandResult refused = run_recoil("--max-memory 0.15 " + args + shell_quote(dir / "refused"));
  ASSERT_EQ(refused.exit_code, 2) << refused.err;
  const CommandResult ran = run_recoil("--max-memory 2 " + args + shell_quote(dir / "ran"));
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  // AddressSanitizer's shadow memory and redzones are no part of the
  // estimate; under it recoil's own share alone passes 0.15 GiB, and the
  // refusal blames no field.
#ifndef __SANITIZE_ADDRESS__
  EXPECT_NE(refused.err.find("/bodies/1/mesh: the run needs about "), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("million triangles"), std::string::npos) << refused.err;
  const double estimate_gib = std::stod(refused.err.substr(refused.err.find("needs about ") + 12));
  const double peak_mib = json::parse(file_bytes(dir / "ran/run.json"))["peak_memory_mib"];
  EXPECT_GE(estimate_gib * 1024.0, 0.9 * peak_mib) << "estimated " << estimate_gib << " GiB";
#endif
}

TEST(DropCommand, AVideoThatCannotBeWrittenFailsBeforeTheFirstFrame) {
  const fs::path dir = scratch_dir("drop_video_unwritable");
  // A folder where the partial video would go: even root cannot open it as a file.
  fs::create_directories(dir / "v.gif.partial");
  const CommandResult r = run_recoil("drop " + shell_quote(source_path("assets/meshes/bunny.obj")) +
                                     " --seconds 0.1 --resolution 64x48 --video " + shell_quote(dir / "v.gif") +
                                     " -o " + shell_quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_EQ(r.err, "recoil: error: --video " + (dir / "v.gif").string() + ": cannot write " +
                       (dir / "v.gif.partial").string() + ": Is a directory\n");
  EXPECT_FALSE(fs::exists(dir / "out"));  // nothing written: no folder, no scene.json
  EXPECT_FALSE(fs::exists(dir / "v.gif"));
  EXPECT_FALSE(fs::exists(dir / "v.gif.log"));
}

TEST(RunCommand, VideoWithoutFfmpegOrOfAnUnknownKindFailsAtOnce) {
  const fs::path dir = scratch_dir("run_video");
  const std::string scene = shell_quote(source_path("assets/scenes/bunny-drop.json"));
  const CommandResult r = run_recoil("run " + scene + " --video " + shell_quote(dir / "v.mp4") + " -o " +
                                         shell_quote(dir / "out"),
                                     "PATH=/nonexistent");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("apt-get install ffmpeg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "frame_0001.png"));
  const CommandResult avi = run_recoil("run " + scene + " --video " + shell_quote(dir / "v.avi") + " -o " +
                                       shell_quote(dir / "out"));
  EXPECT_EQ(avi.exit_code, 2);
  EXPECT_NE(avi.err.find("--video: cannot write 'v.avi'"), std::string::npos) << avi.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "frame_0001.png"));
  EXPECT_FALSE(fs::exists(dir / "v.avi"));
}

TEST(InfoCommand, SceneListsBodiesAndTetrahedra) {
  const CommandResult r = run_recoil("info " + shell_quote(source_path("assets/scenes/jelly-stack.json")) + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json info = json::parse(r.out);
  EXPECT_EQ(info["name"], "jelly-stack");
  EXPECT_EQ(info["frames"], 91);
  ASSERT_EQ(info["bodies"].size(), 4u);
  EXPECT_EQ(info["bodies"][0]["type"], "plane");
  EXPECT_EQ(info["bodies"][1]["type"], "deformable");
  EXPECT_GT(info["bodies"][1]["tets"].get<int>(), 50);
  // A 0.2 m jelly cube of density 1000: 8 kg.
  EXPECT_NEAR(info["bodies"][1]["mass"].get<double>(), 8.0, 0.08);
  const CommandResult text = run_recoil("info " + shell_quote(source_path("assets/scenes/jelly-stack.json")));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("jelly-2"), std::string::npos) << text.out;
}

// The colour type byte of a PNG file's header (2: RGB, 6: RGBA).
static int png_colour_type(const fs::path& file) { return static_cast<unsigned char>(file_bytes(file).at(25)); }

TEST(RunCommand, FramesOverATransparentBackgroundKeepTheirAlphaEvenWhereABodyFillsTheFrame) {
  const fs::path dir = scratch_dir("run_alpha");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.15, 0.0, -0.15), Eigen::Vector3d(0.15, 0.3, 0.15));
  // The camera 5 cm in front of a face of the 30 cm box: the face is all it sees.
  for (const char* background : {"transparent", "#1d2127"}) {
    const fs::path scene = dir / "scene.json";
    std::ofstream(scene) << R"({"recoil": 1, "simulation": {"duration": 0},
      "bodies": [{"type": "plane"}, {"type": "static", "mesh": ")" << box.string() << R"("}],
      "render": {"resolution": [32, 32], "background": ")" << background << R"(",
                 "camera": {"mode": "fixed", "position": [0, 0.15, 0.2], "target": [0, 0.15, 0]}}})";
    const fs::path out = dir / (background[0] == '#' ? "opaque" : "transparent");
    const CommandResult r = run_recoil("run " + shell_quote(scene) + " -q -o " + shell_quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const render::Image frame = render::read_png(out / "frame_0001.png");
    for (size_t i = 3; i < frame.rgba.size(); i += 4) ASSERT_EQ(frame.rgba[i], 255) << "the box fills the frame";
    // Every frame of a transparent run has an alpha channel, so a sequence has one colour type.
    EXPECT_EQ(png_colour_type(out / "frame_0001.png"), background[0] == '#' ? 2 : 6) << background;
  }
}

}  // namespace recoil::test
