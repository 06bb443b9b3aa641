#include <gtest/gtest.h>

#include <cstdio>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "render/png.h"
#include "tests/cli/box_mesh_file.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

static std::string bunny() { return shell_quote(source_path("assets/meshes/bunny.obj")); }

TEST(TurntableCommand, WritesEveryFrameAtTheAskedSizeByteIdenticalAcrossRuns) {
  const fs::path a = scratch_dir("turntable_a"), b = scratch_dir("turntable_b");
  for (const fs::path& dir : {a, b}) {
    const CommandResult r =
        run_recoil("turntable " + bunny() + " --turn-frames 4 --resolution 96x64 -o " + shell_quote(dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(a)) files.insert(entry.path().filename().string());
  // Every frame and what `run` writes beside them; no temporary files left.
  EXPECT_EQ(files, (std::set<std::string>{"frame_0001.png", "frame_0002.png", "frame_0003.png", "frame_0004.png",
                                          "run.json", "scene.json", "stats.jsonl"}));
  const render::Image first = render::read_png(a / "frame_0001.png");
  EXPECT_EQ(first.width, 96);
  EXPECT_EQ(first.height, 64);
  for (const char* name : {"frame_0001.png", "frame_0004.png"})
    EXPECT_EQ(file_bytes(a / name), file_bytes(b / name)) << name << " differs between two identical runs";
  // The camera moves: consecutive frames differ.
  EXPECT_NE(file_bytes(a / "frame_0001.png"), file_bytes(a / "frame_0002.png"));
}

TEST(TurntableCommand, EglBackendWritesTheSameFramesAsOsmesa) {
  const fs::path dir = scratch_dir("turntable_gl");
  for (const char* gl : {"osmesa", "egl"}) {
    const CommandResult r = run_recoil("turntable " + bunny() + " --turn-frames 2 --resolution 96x64 --gl " + gl +
                                       " -o " + shell_quote(dir / gl));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json run = nlohmann::json::parse(file_bytes(dir / gl / "run.json"));
    EXPECT_EQ(run["gl"]["backend"], gl);
  }
  for (const char* name : {"frame_0001.png", "frame_0002.png"})
    EXPECT_EQ(file_bytes(dir / "osmesa" / name), file_bytes(dir / "egl" / name)) << name;
  EXPECT_EQ(run_recoil("turntable " + bunny() + " --gl vulkan -o " + shell_quote(dir / "bad")).exit_code, 2);
}

TEST(TurntableCommand, TransparentBackgroundAndColour) {
  const fs::path dir = scratch_dir("turntable_transparent");
  const CommandResult r = run_recoil("turntable " + bunny() +
                                     " --turn-frames 1 --resolution 64x64 --background transparent --color '#ff0000' -o " +
                                     shell_quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const render::Image image = render::read_png(dir / "frame_0001.png");
  // The bunny sits in the middle; it is reddish and opaque there.
  const std::uint8_t* centre = image.pixel(32, 36);
  EXPECT_EQ(centre[3], 255);
  EXPECT_GT(centre[0], centre[1] + 40);
}

TEST(TurntableCommand, BadInputIsExit2AndUnwritableOutputIsExit4) {
  const fs::path dir = scratch_dir("turntable_bad");
  EXPECT_EQ(run_recoil("turntable /nonexistent.obj -o " + shell_quote(dir)).exit_code, 2);
  const CommandResult resolution = run_recoil("turntable " + bunny() + " --resolution 12by9 -o " + shell_quote(dir));
  EXPECT_EQ(resolution.exit_code, 2);
  EXPECT_NE(resolution.err.find("--resolution"), std::string::npos) << resolution.err;
  const CommandResult color = run_recoil("turntable " + bunny() + " --color red -o " + shell_quote(dir));
  EXPECT_EQ(color.exit_code, 2);
  EXPECT_NE(color.err.find("--color"), std::string::npos) << color.err;
  EXPECT_EQ(run_recoil("turntable " + bunny() + " --msaa 3").exit_code, 2);
  // A count the driver cannot draw exactly (llvmpipe has 4 samples only) is
  // refused naming the scene's field and the option; a driver with 2 samples draws it.
  const CommandResult two = run_recoil("turntable " + bunny() + " --msaa 2 --turn-frames 1 --resolution 32x32 -q -o " +
                                       shell_quote(dir / "two"));
  if (two.exit_code != 0) {
    EXPECT_EQ(two.exit_code, 2) << two.err;
    EXPECT_NE(two.err.find(": /render/msaa (--msaa): render msaa 2"), std::string::npos) << two.err;
  }
  std::ofstream(dir / "a_file") << "x";
  const CommandResult blocked =
      run_recoil("turntable " + bunny() + " --turn-frames 1 --resolution 32x32 -o " + shell_quote(dir / "a_file" / "sub"));
  EXPECT_EQ(blocked.exit_code, 4) << blocked.err;
}

// Meshes as exported, whatever their units or names: a box modelled in
// units of 1.5 nm (0.3 m as 2e8) is scaled to 0.3 m like any other,
// and a file name past the 128-byte scene name is cut (at a character, not
// inside one) for the scene's and the bodies' names.
TEST(TurntableCommand, HugeUnitsAndLongFileNamesStillMakeAScene) {
  const fs::path dir = scratch_dir("turntable_units_names");
  const fs::path huge = write_box_off(dir / "huge.off", Eigen::Vector3d::Zero(), Eigen::Vector3d(2e8, 1e8, 1.5e8));
  const CommandResult r = run_recoil("turntable " + shell_quote(huge) + " --turn-frames 1 --resolution 32x32 -q -o " +
                                     shell_quote(dir / "huge"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json scene = nlohmann::json::parse(file_bytes(dir / "huge/scene.json"));
  EXPECT_NEAR(scene["bodies"][1]["transform"]["scale"].get<double>(), 1.5e-9, 1e-15);
  std::string stem;
  for (int i = 0; i < 100; ++i) stem += "\u00e9";  // 200 bytes of two-byte characters
  const fs::path named = write_box_off(dir / (stem + ".off"), Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.2));
  for (const std::string command : {"turntable", "drop"}) {
    const CommandResult n = run_recoil(command + " " + shell_quote(named) + " --frames 1 --resolution 32x32 -q -o " +
                                       shell_quote(dir / command));
    ASSERT_EQ(n.exit_code, 0) << n.err;
    const nlohmann::json s = nlohmann::json::parse(file_bytes(dir / command / "scene.json"));
    const std::string name = s["name"], body = s["bodies"][1]["name"];
    EXPECT_LE(name.size(), 128u) << command;
    EXPECT_EQ(name.substr(0, 120), stem.substr(0, 120)) << command;
    EXPECT_EQ(body.substr(0, 120), stem.substr(0, 120)) << command;
  }
}

// --frames picks frames of the turn as it does in `run`, and the scene.json
// written beside them reruns the same turntable.
TEST(TurntableCommand, FramesSelectsAsInRunAndTheSceneReruns) {
  const fs::path dir = scratch_dir("turntable_frames");
  const std::string size = " --resolution 64x48 --msaa 0 -q";
  const CommandResult r =
      run_recoil("turntable " + bunny() + " --turn-frames 8 --frames 2,5" + size + " -o " + shell_quote(dir / "a"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::set<std::string> frames;
  for (const auto& entry : fs::directory_iterator(dir / "a"))
    if (entry.path().extension() == ".png") frames.insert(entry.path().filename().string());
  EXPECT_EQ(frames, (std::set<std::string>{"frame_0002.png", "frame_0005.png"}));
  const CommandResult rerun = run_recoil("run " + shell_quote(dir / "a" / "scene.json") + " --frames 5" + size +
                                         " -o " + shell_quote(dir / "b"));
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_EQ(file_bytes(dir / "a" / "frame_0005.png"), file_bytes(dir / "b" / "frame_0005.png"));
  // run.json records the whole command line.
  const std::string command = nlohmann::json::parse(file_bytes(dir / "a" / "run.json"))["command"];
  EXPECT_NE(command.find("--turn-frames 8 --frames 2,5"), std::string::npos) << command;
  // --save-scene keeps the render options given, so the saved scene alone redraws the frame.
  const CommandResult saved = run_recoil("turntable " + bunny() + " --turn-frames 8 --frames 5" + size + " --save-scene " +
                                         shell_quote(dir / "t.json") + " -o " + shell_quote(dir / "c"));
  ASSERT_EQ(saved.exit_code, 0) << saved.err;
  const CommandResult from_saved =
      run_recoil("run " + shell_quote(dir / "t.json") + " --frames 5 -q -o " + shell_quote(dir / "d"));
  ASSERT_EQ(from_saved.exit_code, 0) << from_saved.err;
  EXPECT_EQ(file_bytes(dir / "a" / "frame_0005.png"), file_bytes(dir / "d" / "frame_0005.png"));
  // A frame past the turn is refused, as in run, naming the option that makes the turn longer.
  const CommandResult past = run_recoil("turntable " + bunny() + " --turn-frames 8 --frames 5,12" + size + " -o " +
                                        shell_quote(dir / "e"));
  EXPECT_EQ(past.exit_code, 2);
  EXPECT_NE(past.err.find("--frames: frame 12 is past the last, 8"), std::string::npos) << past.err;
  EXPECT_NE(past.err.find("turntable: --turn-frames"), std::string::npos) << past.err;
  const CommandResult bad = run_recoil("turntable " + bunny() + " --frames 0" + size + " -o " + shell_quote(dir / "f"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--frames"), std::string::npos) << bad.err;
}

// A camera under the ground sees only the ground's underside: the run says
// so, and does not once the ground is hidden.
TEST(TurntableCommand, ACameraBelowTheGroundIsWarnedOf) {
  const fs::path dir = scratch_dir("turntable_below_ground");
  const std::string command = "turntable " + bunny() + " --elevation -30 --turn-frames 2 --resolution 32x32 --msaa 0 -o ";
  const CommandResult below = run_recoil(command + shell_quote(dir / "a"));
  ASSERT_EQ(below.exit_code, 0) << below.err;
  EXPECT_NE(below.err.find("warning: the camera is below the ground in 2 frames"), std::string::npos) << below.err;
  const CommandResult hidden = run_recoil(command + shell_quote(dir / "b") + " --no-ground");
  ASSERT_EQ(hidden.exit_code, 0) << hidden.err;
  EXPECT_EQ(hidden.err.find("below the ground"), std::string::npos) << hidden.err;
}

// A tall box modelled leaning 25 degrees stands on one edge: --settle lets it
// fall onto a long side and rest there before the orbit; without --settle it
// is drawn as modelled, its lowest edge on the ground.
TEST(TurntableCommand, SettleLaysALeaningBoxOnItsSideAtRest) {
  const fs::path dir = scratch_dir("turntable_settle");
  const Eigen::Matrix3d lean = Eigen::AngleAxisd(25.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const fs::path box = write_box_off(dir / "leaning.off", Eigen::Vector3d(-0.05, -0.15, -0.05),
                                     Eigen::Vector3d(0.05, 0.15, 0.05), false,
                                     [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(lean * p); });
  const std::string common = " --turn-frames 2 --resolution 48x32 --msaa 0 -q -o ";
  const CommandResult settled = run_recoil("turntable " + shell_quote(box) + " --settle" + common + shell_quote(dir / "s"));
  ASSERT_EQ(settled.exit_code, 0) << settled.err;
  const nlohmann::json run = nlohmann::json::parse(file_bytes(dir / "s" / "run.json"));
  EXPECT_TRUE(run["settle"]["at_rest"].get<bool>()) << run["settle"];
  EXPECT_LT(run["settle"]["time_s"].get<double>(), 5.0);
  const double margin = run["warnings"]["margin"].get<double>();
  EXPECT_LE(run["warnings"]["max_penetration"].get<double>(), margin);
  EXPECT_EQ(run["warnings"]["summary"], "");
  std::istringstream lines(file_bytes(dir / "s" / "stats.jsonl"));
  std::string line;
  int frames = 0;
  while (std::getline(lines, line)) {
    const nlohmann::json body = nlohmann::json::parse(line)["bodies"][0];
    // Lying on a 0.1 x 0.3 m side: its centre half the 0.1 m edge up, still.
    EXPECT_NEAR(body["com"][1].get<double>(), 0.05, margin) << line;
    const nlohmann::json v = body["velocity"];
    EXPECT_LT(std::hypot(v[0].get<double>(), v[1].get<double>(), v[2].get<double>()), 1e-3) << line;
    ++frames;
  }
  EXPECT_EQ(frames, 2);
  const CommandResult modelled = run_recoil("turntable " + shell_quote(box) + common + shell_quote(dir / "m"));
  ASSERT_EQ(modelled.exit_code, 0) << modelled.err;
  EXPECT_NE(file_bytes(dir / "s" / "frame_0001.png"), file_bytes(dir / "m" / "frame_0001.png"));
  const nlohmann::json scene = nlohmann::json::parse(file_bytes(dir / "m" / "scene.json"));
  EXPECT_EQ(scene["bodies"][1]["type"], "static");
  EXPECT_EQ(scene["simulation"]["settle"], 0.0);
}

// --video as in `run`: the frames and an MP4 or a GIF beside them, nothing partial left.
TEST(TurntableCommand, VideoAsMp4AndGif) {
  const fs::path dir = scratch_dir("turntable_video");
  for (const char* name : {"turn.mp4", "turn.gif"}) {
    const CommandResult r = run_recoil("turntable " + bunny() + " --turn-frames 6 --resolution 64x48 --msaa 0 -q --video " +
                                       shell_quote(dir / name) + " -o " + shell_quote(dir / "frames"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string video = file_bytes(dir / name);
    ASSERT_GT(video.size(), 100u) << name;
    if (std::string(name) == "turn.gif") EXPECT_EQ(video.substr(0, 6), "GIF89a");
    else EXPECT_EQ(video.substr(4, 4), "ftyp");
    EXPECT_FALSE(fs::exists(dir / (std::string(name) + ".partial")));
    EXPECT_FALSE(fs::exists(dir / (std::string(name) + ".log")));
  }
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame_0006.png"));
}

// Over a transparent background a GIF keeps the transparency (one palette
// entry), and a video whose codec cannot hold it is refused before anything is written.
TEST(TurntableCommand, ATransparentGifIsTransparentAndAnMp4IsRefused) {
  const fs::path dir = scratch_dir("turntable_video_alpha");
  const std::string command = "turntable " + bunny() + " --turn-frames 2 --resolution 64x48 --msaa 0 -q --background transparent";
  const CommandResult gif = run_recoil(command + " --video " + shell_quote(dir / "t.gif") + " -o " + shell_quote(dir / "g"));
  ASSERT_EQ(gif.exit_code, 0) << gif.err;
  std::FILE* decoded = ::popen(("ffmpeg -v error -i " + shell_quote(dir / "t.gif") + " -vframes 1 -f rawvideo -pix_fmt rgba -")
                                   .c_str(), "r");
  ASSERT_NE(decoded, nullptr);
  std::string rgba(64 * 48 * 4, '\0');
  const size_t got = std::fread(rgba.data(), 1, rgba.size(), decoded);
  ::pclose(decoded);
  ASSERT_EQ(got, rgba.size());
  int clear = 0;
  for (size_t i = 3; i < rgba.size(); i += 4) clear += rgba[i] == 0;
  EXPECT_GT(clear, 64 * 48 / 2);  // the bunny and its shadow cover less than half the frame
  const CommandResult mp4 = run_recoil(command + " --video " + shell_quote(dir / "t.mp4") + " -o " + shell_quote(dir / "m"));
  EXPECT_EQ(mp4.exit_code, 2);
  EXPECT_NE(mp4.err.find("holds no transparency; name it .webm or .gif"), std::string::npos) << mp4.err;
  EXPECT_FALSE(fs::exists(dir / "m"));
}

// Every 4th frame of a 30 fps turn plays at 7.5 fps, so the video runs in
// real time rather than four times as fast.
TEST(TurntableCommand, AVideoOfEveryNthFramePlaysInRealTime) {
  const fs::path dir = scratch_dir("turntable_video_stride");
  const fs::path video = dir / "turn.mp4";
  const CommandResult r = run_recoil("turntable " + bunny() + " --turn-frames 24 --frames 1-24:4 --resolution 64x48 --msaa 0 --video " +
                                     shell_quote(video) + " -o " + shell_quote(dir / "frames"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The summary names the video beside the frames.
  EXPECT_NE(r.err.find(", wrote 6 frames to " + (dir / "frames").string() + " and " + video.string()), std::string::npos)
      << r.err;
  std::FILE* probe = ::popen(("ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate,nb_frames -of csv=p=0 " +
                              shell_quote(video)).c_str(), "r");
  ASSERT_NE(probe, nullptr);
  char line[128] = {};
  const bool read = std::fgets(line, sizeof line, probe) != nullptr;
  ::pclose(probe);
  ASSERT_TRUE(read);
  EXPECT_EQ(std::string(line), "15/2,6\n");
}

}  // namespace recoil::test
