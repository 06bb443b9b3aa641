// `recoil batch` end to end: a folder of real meshes from assimp-testmodels,
// restarts (after a kill -9 too, or a change of the input files), shards,
// manifest errors, item paths, folders it did not write and the contact sheet.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "render/png.h"
#include "tests/cli/json_lines.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kModels = "/usr/share/assimp/models";

json read_json(const fs::path& path) { return json::parse(file_bytes(path)); }

// The "event": "item" lines of a --log-json run.
std::vector<json> item_events(const std::string& err) {
  std::vector<json> events;
  for (const json& j : json_lines(err))
    if (j.is_object() && j.value("event", "") == "item") events.push_back(j);
  return events;
}

void write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// A manifest of `n` small turntables of the cube (one frame, 64x48).
fs::path cube_manifest(const fs::path& dir, int n) {
  json items = json::array();
  for (int i = 0; i < n; ++i)
    items.push_back({{"mesh", (kModels / "OFF/Cube.off").string()}, {"frames", 1}, {"resolution", "64x48"},
                     {"name", "cube" + std::to_string(i)}});
  write_text(dir / "m.json", items.dump());
  return dir / "m.json";
}

}  // namespace

TEST(BatchCommand, FolderOfRealMeshesRendersTheValidOnesAndRecordsTheBroken) {
  const fs::path dir = scratch_dir("batch_folder");
  const std::vector<std::string> valid = {
      "OBJ/box.obj",           "OBJ/WusonOBJ.obj",     "OBJ/spider.obj",          "OBJ/concave_polygon.obj",
      "OFF/Cube.off",          "OFF/Wuson.off",        "PLY/cube_binary.ply",     "PLY/Wuson.ply",
      "STL/Spider_ascii.stl",  "STL/sphereWithHole.stl", "STL/triangle.stl",      "Collada/duck.dae",
      "Collada/sphere.dae",    "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"};
  const std::vector<std::string> broken = {"OFF/invalid.off",      "invalid/empty.ply", "invalid/empty.off",
                                           "invalid/OutOfMemory.off", "invalid/malformed.obj", "PLY/points.ply",
                                           "OBJ/testpoints.obj",   "glTF2/IndexOutOfRange/IndexOutOfRange.gltf"};
  fs::create_directories(dir / "in");
  for (const auto& list : {valid, broken})
    for (const std::string& f : list) fs::copy_file(kModels / f, dir / "in" / fs::path(f).filename());
  ASSERT_GE(valid.size() + broken.size(), 20u);

  const CommandResult r =
      run_recoil("batch " + shell_quote(dir / "in") + " -o " + shell_quote(dir / "out") +
                 " --set frames=1 --set resolution=64x48 --jobs 2 --log-json --contact-sheet " +
                 shell_quote(dir / "sheet.png"));
  EXPECT_EQ(r.exit_code, 2) << r.err;  // every broken file is bad input
  const json summary = read_json(dir / "out/batch.json");
  ASSERT_EQ(summary["items"].size(), valid.size() + broken.size());
  EXPECT_EQ(summary["succeeded"], valid.size());
  EXPECT_EQ(summary["failed"], broken.size());
  std::set<std::string> broken_files;
  for (const std::string& f : broken) broken_files.insert(fs::path(f).filename().string());
  for (const json& item : summary["items"]) {
    const std::string file = fs::path(item["command"][1].get<std::string>()).filename().string();
    const fs::path out = item["output"].get<std::string>();
    if (broken_files.count(file)) {
      EXPECT_EQ(item["status"], "failed") << file;
      EXPECT_EQ(item["exit_code"], 2) << file;
      EXPECT_NE(item["message"].get<std::string>().find(file), std::string::npos) << file << ": " << item["message"];
    } else {
      EXPECT_EQ(item["status"], "succeeded") << file << ": " << item["message"];
      EXPECT_TRUE(fs::exists(out / "frame_0001.png")) << file;
    }
  }
  EXPECT_EQ(item_events(r.err).size(), valid.size() + broken.size());
  const render::Image sheet = render::read_png(dir / "sheet.png");
  EXPECT_GT(sheet.width, 4 * 256);  // a grid, not one tile
  EXPECT_GT(sheet.height, 3 * 144);
}

TEST(BatchCommand, RerunSkipsCompleteItemsAndRedoesPartialAndFailedOnes) {
  const fs::path dir = scratch_dir("batch_rerun");
  const fs::path manifest = cube_manifest(dir, 4);
  const std::string args = "batch " + shell_quote(manifest) + " -o " + shell_quote(dir / "out") + " --log-json";
  ASSERT_EQ(run_recoil(args).exit_code, 0);
  // What a rerun redoes: an item whose marker cannot be read, what a kill
  // leaves (a half-written folder, and the finished one gone or renamed
  // aside to be replaced), a failure record.
  write_text(dir / "out/cube1/item.json", "{\"status\": \"succ");
  fs::create_directories(dir / "out/cube2.partial");
  write_text(dir / "out/cube2.partial/frame_0001.png", "half");
  fs::rename(dir / "out/cube2", dir / "out/cube2.replaced");
  write_text(dir / "out/cube3/item.json", json{{"status", "failed"}, {"exit_code", 4}}.dump());
  const CommandResult again = run_recoil(args);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  std::set<int> ran;
  for (const json& e : item_events(again.err)) ran.insert(e["index"].get<int>());
  EXPECT_EQ(ran, (std::set<int>{1, 2, 3}));
  EXPECT_FALSE(fs::exists(dir / "out/cube2.partial"));
  EXPECT_FALSE(fs::exists(dir / "out/cube2.replaced"));
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(read_json(dir / ("out/cube" + std::to_string(i)) / "item.json")["status"], "succeeded") << i;
}

// Every frame of every item folder under `out`, by relative path.
std::map<std::string, std::string> frames_under(const fs::path& out) {
  std::map<std::string, std::string> frames;
  for (const auto& e : fs::recursive_directory_iterator(out))
    if (e.path().extension() == ".png") frames[fs::relative(e.path(), out).string()] = file_bytes(e.path());
  return frames;
}

// An item is finished only for the command line it ran: one whose manifest
// entry changed is run again, its old output replaced, while the unchanged
// ones are kept and the summary says so.
TEST(BatchCommand, ARerunRedoesTheItemsWhoseCommandChanged) {
  const fs::path dir = scratch_dir("batch_changed");
  const fs::path manifest = cube_manifest(dir, 2);
  const std::string args = "batch " + shell_quote(manifest) + " -o " + shell_quote(dir / "out");
  ASSERT_EQ(run_recoil(args).exit_code, 0);
  const CommandResult same = run_recoil(args);
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_NE(same.err.find("2 succeeded (2 finished by an earlier run), 0 failed"), std::string::npos) << same.err;
  json items = read_json(manifest);
  items[1]["color"] = "#ff0000";
  write_text(manifest, items.dump());
  const CommandResult changed = run_recoil(args + " --log-json");
  ASSERT_EQ(changed.exit_code, 0) << changed.err;
  std::set<int> ran;
  for (const json& e : item_events(changed.err)) ran.insert(e["index"].get<int>());
  EXPECT_EQ(ran, (std::set<int>{1}));
  EXPECT_EQ(read_json(dir / "out/cube1/scene.json")["bodies"][1]["color"], "#ff0000");
  const json summary = read_json(dir / "out/batch.json");
  EXPECT_EQ(summary["succeeded"], 2);
  EXPECT_EQ(summary["items"][1]["status"], "succeeded");
  const std::vector<std::string> command = read_json(dir / "out/cube1/item.json")["command"];
  EXPECT_NE(std::find(command.begin(), command.end(), "#ff0000"), command.end());
}

// An item is finished only for the input files it read: a mesh file, or a
// mesh file that a scene item's scene names, changed since is run again.
TEST(BatchCommand, ARerunRedoesTheItemsWhoseInputFilesChanged) {
  const fs::path dir = scratch_dir("batch_inputs_changed");
  fs::copy_file(kModels / "OFF/Cube.off", dir / "model.off");
  fs::copy_file(kModels / "OFF/Cube.off", dir / "part.off");
  write_text(dir / "s.json",
             json({{"recoil", 1}, {"name", "s"}, {"simulation", {{"duration", 0.1}}},
                   {"bodies", json::array({{{"name", "box"}, {"type", "static"}, {"mesh", "part.off"}}})}})
                 .dump());
  write_text(dir / "m.json", json::array({{{"mesh", "model.off"}, {"frames", "1"}, {"resolution", "64x48"}},
                                          {{"scene", "s.json"}, {"frames", "1"}, {"resolution", "64x48"}}})
                                 .dump());
  const std::string args = "--log-json batch " + shell_quote(dir / "m.json") + " -o " + shell_quote(dir / "out");
  auto ran = [&] {
    const CommandResult r = run_recoil(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::vector<json> lines = json_lines(r.err);
    for (const json& line : lines) EXPECT_TRUE(line.is_object()) << "not one JSON object per line:\n" << r.err;
    EXPECT_TRUE(!lines.empty() && lines.back().value("event", "") == "summary") << r.err;
    std::set<int> items;
    for (const json& e : item_events(r.err)) items.insert(e["index"].get<int>());
    return items;
  };
  EXPECT_EQ(ran(), (std::set<int>{0, 1}));
  // The stamp's time is the file's, counted from the Unix epoch as stat(1) counts it.
  const json stamp = json::parse(file_bytes(dir / "out/model/item.json"))["inputs"][0];
  EXPECT_EQ(stamp["path"], (dir / "model.off").string());
  struct stat status {};
  ASSERT_EQ(::stat((dir / "model.off").c_str(), &status), 0);
  EXPECT_EQ(stamp["mtime_ns"].get<long long>(),
            static_cast<long long>(status.st_mtim.tv_sec) * 1000000000LL + status.st_mtim.tv_nsec);
  EXPECT_EQ(ran(), (std::set<int>{}));
  const std::string cube = file_bytes(dir / "out/model/frame_0001.png");
  fs::copy_file(kModels / "OFF/Wuson.off", dir / "model.off", fs::copy_options::overwrite_existing);
  EXPECT_EQ(ran(), (std::set<int>{0}));
  EXPECT_NE(file_bytes(dir / "out/model/frame_0001.png"), cube) << "the old mesh's frame was kept";
  fs::copy_file(kModels / "OFF/Wuson.off", dir / "part.off", fs::copy_options::overwrite_existing);
  EXPECT_EQ(ran(), (std::set<int>{1}));
  EXPECT_EQ(ran(), (std::set<int>{}));
}

// Batch replaces an item's folder when the item finishes; a folder (or file)
// of that name that batch did not write is the user's, and the batch stops
// before running anything rather than delete it.
TEST(BatchCommand, AFolderBatchDidNotWriteIsNeverReplaced) {
  const fs::path dir = scratch_dir("batch_foreign_folder");
  const fs::path manifest = cube_manifest(dir, 2);
  fs::create_directories(dir / "out/cube1/approved");
  write_text(dir / "out/cube1/approved/signoff.txt", "client sign-off");
  const std::string args = "batch " + shell_quote(manifest) + " -o " + shell_quote(dir / "out");
  const CommandResult r = run_recoil(args);
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find((dir / "out/cube1").string() + " is there but was not written by recoil batch"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(file_bytes(dir / "out/cube1/approved/signoff.txt"), "client sign-off");
  EXPECT_FALSE(fs::exists(dir / "out/cube0")) << "nothing runs";
  fs::remove_all(dir / "out/cube1");
  write_text(dir / "out/cube1", "a file");
  EXPECT_EQ(run_recoil(args).exit_code, 4);
  EXPECT_EQ(file_bytes(dir / "out/cube1"), "a file");
  fs::remove(dir / "out/cube1");
  const CommandResult ours = run_recoil(args);
  ASSERT_EQ(ours.exit_code, 0) << ours.err;
  write_text(manifest, json::array({{{"mesh", (kModels / "OFF/Cube.off").string()}, {"frames", 1},
                                     {"resolution", "32x24"}, {"name", "cube0"}}})
                           .dump());
  EXPECT_EQ(run_recoil(args).exit_code, 0) << "its own folders are replaced as before";
  EXPECT_EQ(render::read_png(dir / "out/cube0/frame_0001.png").width, 32);
  EXPECT_FALSE(fs::exists(dir / "out/cube0.replaced"));
}

// --max-memory before `batch` caps every item, shared out among the items
// that run at once; in a manifest or a --set it is refused, naming where.
TEST(BatchCommand, MaxMemoryIsSharedOutAmongTheItemsRunningAtOnce) {
  const fs::path dir = scratch_dir("batch_max_memory");
  const fs::path manifest = cube_manifest(dir, 2);
  for (const int jobs : {1, 2}) {
    const fs::path out = dir / ("out" + std::to_string(jobs));
    const CommandResult r = run_recoil("--max-memory 0.04 batch " + shell_quote(manifest) + " --jobs " +
                                       std::to_string(jobs) + " -o " + shell_quote(out));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    const std::string allowed = jobs == 1 ? "more than the 0.04 GiB allowed" : "more than the 0.02 GiB allowed";
    for (int i = 0; i < 2; ++i) {
      const json item = read_json(out / ("cube" + std::to_string(i)) / "item.json");
      EXPECT_EQ(item["exit_code"], 2);
      EXPECT_NE(item["message"].get<std::string>().find(allowed), std::string::npos) << item["message"];
    }
  }
  const CommandResult little = run_recoil("--max-memory 0.015 batch " + shell_quote(manifest) + " --jobs 2 -o " +
                                          shell_quote(dir / "out_little"));
  EXPECT_EQ(little.exit_code, 2);
  EXPECT_NE(little.err.find("2 items at once (--jobs) would get 0.0075 GiB each; at least 0.01"), std::string::npos)
      << little.err;
  const CommandResult set = run_recoil("batch " + shell_quote(manifest) + " --set max-memory=1 -o " +
                                       shell_quote(dir / "out_set"));
  EXPECT_EQ(set.exit_code, 2);
  EXPECT_NE(set.err.find("--max-memory is an option of recoil itself"), std::string::npos) << set.err;
}

TEST(BatchCommand, KillNineAtSeveralMomentsLosesOnlyTheItemsInFlight) {
  const fs::path dir = scratch_dir("batch_kill");
  json items = json::array();
  for (int i = 0; i < 5; ++i)
    items.push_back({{"mesh", source_path("assets/meshes/bunny.obj").string()}, {"mode", "drop"},
                     {"material", "rigid"}, {"seconds", 0.3}, {"resolution", "64x48"},
                     {"name", "b" + std::to_string(i)}});
  write_text(dir / "m.json", items.dump());
  const auto args = [&](const std::string& out) {
    return "batch " + shell_quote(dir / "m.json") + " -o " + shell_quote(dir / out) + " --log-json";
  };
  ASSERT_EQ(run_recoil(args("whole")).exit_code, 0);

  // The items whose folder is complete (item.json in place).
  const auto complete = [&] {
    std::set<int> done;
    for (int i = 0; i < 5; ++i)
      if (fs::exists(dir / ("out/b" + std::to_string(i)) / "item.json")) done.insert(i);
    return done;
  };
  const auto logged = [](const std::string& log) {
    std::multiset<int> indices;
    for (const json& e : item_events(log)) indices.insert(e["index"].get<int>());
    return indices;
  };
  // Killed with SIGKILL as soon as k items are complete (k = 1, 2, 3), then run to the end.
  // A killed run logs only items it completed itself, though maybe not all of
  // them: the kill can land between an item's folder and its log line.
  for (int k = 1; k <= 3; ++k) {
    const std::set<int> before = complete();
    const fs::path pid_file = dir / "pid", log = dir / ("run" + std::to_string(k) + ".log");
    write_text(dir / "start.sh", "'" RECOIL_BINARY "' " + args("out") + " </dev/null >/dev/null 2>" +
                                    shell_quote(log) + " &\necho $! > " + shell_quote(pid_file) + "\n");
    ASSERT_EQ(std::system(("sh " + shell_quote(dir / "start.sh")).c_str()), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const pid_t pid = std::stoi(file_bytes(pid_file));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (static_cast<int>(complete().size()) < k && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_GE(static_cast<int>(complete().size()), k);
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the orphaned item stops on its parent's death
    const std::set<int> after = complete();
    for (const int index : logged(file_bytes(log))) {
      EXPECT_TRUE(after.count(index) && !before.count(index)) << "run " << k << " logged item " << index;
      EXPECT_EQ(logged(file_bytes(log)).count(index), 1u) << "run " << k << " logged item " << index << " twice";
    }
  }
  // No item is run again once it was complete: the last run does exactly the rest.
  const std::set<int> before_last = complete();
  const CommandResult last = run_recoil(args("out"));
  ASSERT_EQ(last.exit_code, 0) << last.err;
  std::multiset<int> rest;
  for (int i = 0; i < 5; ++i)
    if (!before_last.count(i)) rest.insert(i);
  EXPECT_EQ(logged(last.err), rest);
  EXPECT_EQ(complete(), (std::set<int>{0, 1, 2, 3, 4}));
  const std::map<std::string, std::string> whole = frames_under(dir / "whole"), resumed = frames_under(dir / "out");
  EXPECT_GT(whole.size(), 5u);
  EXPECT_TRUE(whole == resumed) << whole.size() << " frames uninterrupted, " << resumed.size() << " after the kills";
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(fs::exists(dir / ("out/b" + std::to_string(i) + ".partial"))) << i;
}

// An item another process holds (here the test, as an orphaned item of a
// killed batch would) is not touched until it is let go; the rest run meanwhile.
TEST(BatchCommand, AnItemHeldByAnotherProcessWaitsUntilItIsLetGo) {
  const fs::path dir = scratch_dir("batch_held_item");
  json items = json::array();
  for (int i = 0; i < 2; ++i)
    items.push_back({{"mesh", source_path("assets/meshes/bunny.obj").string()}, {"mode", "drop"},
                     {"material", "rigid"}, {"seconds", 0.1}, {"resolution", "64x48"},
                     {"name", "b" + std::to_string(i)}});
  write_text(dir / "m.json", items.dump());
  fs::create_directories(dir / "out/.recoil-locks");
  const int held = ::open((dir / "out/.recoil-locks/b0").c_str(), O_RDWR | O_CREAT, 0666);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX | LOCK_NB), 0);
  fs::create_directories(dir / "out/b0.partial");  // what the holder is still writing
  write_text(dir / "out/b0.partial/frame_0001.png", "still being written");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::close(held);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 2);
    ::execl(RECOIL_BINARY, "recoil", "batch", (dir / "m.json").c_str(), "-o", (dir / "out").c_str(), nullptr);
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(dir / "out/b1/item.json") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(dir / "out/b1/item.json"));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(file_bytes(dir / "out/b0.partial/frame_0001.png"), "still being written");
  EXPECT_FALSE(fs::exists(dir / "out/b0"));
  ::close(held);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_TRUE(fs::exists(dir / "out/b0/item.json"));
  EXPECT_FALSE(fs::exists(dir / "out/b0.partial"));
}

TEST(BatchCommand, FourShardsGiveExactlyTheUnshardedRun) {
  const fs::path dir = scratch_dir("batch_four_shards");
  const fs::path manifest = cube_manifest(dir, 9);
  ASSERT_EQ(run_recoil("batch " + shell_quote(manifest) + " -o " + shell_quote(dir / "whole")).exit_code, 0);
  for (int i = 0; i < 4; ++i)
    ASSERT_EQ(run_recoil("batch " + shell_quote(manifest) + " -o " + shell_quote(dir / "sharded") + " --shard " +
                         std::to_string(i) + "/4").exit_code,
              0);
  EXPECT_TRUE(frames_under(dir / "whole") == frames_under(dir / "sharded"));
  EXPECT_EQ(read_json(dir / "sharded/batch.json")["succeeded"], 9);
}

TEST(BatchCommand, ShardsTakeTheirItemsFromOptionsOrTheFarmsVariables) {
  const fs::path dir = scratch_dir("batch_shards");
  const fs::path manifest = cube_manifest(dir, 7);
  std::multiset<int> ran;
  for (int shard = 0; shard < 3; ++shard) {
    // One shard from each source: --shard, Slurm's array variables, an Indexed Job's index.
    const std::string env = shard == 1   ? "SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=3 "
                            : shard == 2 ? "JOB_COMPLETION_INDEX=2 "
                                         : "";
    const std::string select = shard == 0 ? " --shard 0/3" : shard == 2 ? " --shard-count 3" : "";
    const fs::path log = dir / ("shard" + std::to_string(shard) + ".log");
    ASSERT_EQ(std::system((env + "'" RECOIL_BINARY "' batch " + shell_quote(manifest) + " -o " +
                           shell_quote(dir / "sharded") + select + " --log-json 2>" + shell_quote(log))
                              .c_str()),
              0);
    for (const json& e : item_events(file_bytes(log))) {
      EXPECT_EQ(e["index"].get<int>() % 3, shard) << e;
      EXPECT_EQ(e["shard"], std::to_string(shard) + "/3");
      ran.insert(e["index"].get<int>());
    }
  }
  EXPECT_EQ(ran, (std::multiset<int>{0, 1, 2, 3, 4, 5, 6}));
  const json summary = read_json(dir / "sharded/batch.json");
  EXPECT_EQ(summary["succeeded"], 7);
  EXPECT_EQ(run_recoil("batch " + shell_quote(manifest) + " --shard 3/3").exit_code, 2);
  EXPECT_EQ(run_recoil("batch " + shell_quote(manifest) + " --shard-count 3").exit_code, 2);
  // An array index without the array's size would run every item in every task.
  EXPECT_NE(std::system(("SLURM_ARRAY_TASK_ID=1 '" RECOIL_BINARY "' batch " + shell_quote(manifest) + " --list -q " +
                         "2>/dev/null >/dev/null")
                            .c_str()),
            0);
}

TEST(BatchCommand, ManifestErrorsNameTheItemAndTheFieldBeforeAnythingRuns) {
  const fs::path dir = scratch_dir("batch_errors");
  const std::string cube = (kModels / "OFF/Cube.off").string();
  const auto error_for = [&](const json& manifest) {
    write_text(dir / "m.json", manifest.dump());
    const CommandResult r = run_recoil("batch " + shell_quote(dir / "m.json") + " -o " + shell_quote(dir / "out"));
    EXPECT_EQ(r.exit_code, 2) << manifest;
    EXPECT_FALSE(fs::exists(dir / "out")) << manifest;  // validated up front: nothing ran
    return r.err;
  };
  const json ok = {{"mesh", cube}};
  std::string e = error_for(json::array({ok, {{"mesh", cube}, {"frames", 0}}}));
  EXPECT_NE(e.find("m.json: /1/frames:"), std::string::npos) << e;
  e = error_for(json::array({ok, ok, {{"mesh", cube}, {"frame", 3}}}));
  EXPECT_NE(e.find("/2/frame:"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean \"frames\""), std::string::npos) << e;
  e = error_for(json::array({{{"mesh", cube}, {"mode", "spin"}}}));
  EXPECT_NE(e.find("/0/mode:"), std::string::npos) << e;
  e = error_for(json::array({{{"mesh", cube}, {"no-ground", "yes"}}}));
  EXPECT_NE(e.find("/0/no-ground:"), std::string::npos) << e;
  e = error_for(json::array({{{"scene", "a.json"}, {"mesh", cube}}}));
  EXPECT_NE(e.find("/0:"), std::string::npos) << e;
  e = error_for(json::object({{"mesh", cube}}));
  EXPECT_NE(e.find("JSON list"), std::string::npos) << e;
  e = error_for(json::array({{{"mesh", cube}, {"resolution", {320, 240}}}}));
  EXPECT_NE(e.find("/0/resolution: --resolution takes one value, written as on the command line"), std::string::npos)
      << e;
  e = error_for(json::array({{{"mesh", cube}, {"turn-frames", "many"}}}));
  EXPECT_NE(e.find("/0/turn-frames: must be a whole number in [1, 1000000], got 'many'"), std::string::npos) << e;
  // An option only some commands take, given to all by --set, is blamed on --set.
  write_text(dir / "m.json", json::array({ok}).dump());
  const CommandResult set = run_recoil("batch " + shell_quote(dir / "m.json") + " --set seconds=0.3 --list");
  EXPECT_EQ(set.exit_code, 2);
  EXPECT_NE(set.err.find("/0: --set seconds: `recoil turntable` has no option --seconds"), std::string::npos) << set.err;
}

// Items that only their run would refuse (a missing file, a value the command
// line accepts as text) are refused up front too, by batch and by --list alike.
TEST(BatchCommand, EveryItemIsCheckedAsItsRunWouldBeBeforeTheFirstRuns) {
  const fs::path dir = scratch_dir("batch_item_values");
  fs::create_directories(dir / "m/folder");
  fs::copy_file(kModels / "OFF/Cube.off", dir / "m/cube.off");
  const json ok = {{"mesh", "cube.off"}, {"mode", "turntable"}, {"frames", 1}, {"resolution", "64x48"}};
  // The error of a manifest of `ok` then `bad`, which both batch and --list refuse.
  const auto error_for = [&](const json& bad) {
    write_text(dir / "m/m.json", json::array({ok, bad}).dump());
    const std::string base = "batch " + shell_quote(dir / "m/m.json") + " -o " + shell_quote(dir / "out");
    const CommandResult listed = run_recoil(base + " --list");
    EXPECT_EQ(listed.exit_code, 2) << bad << "\n" << listed.out;
    const CommandResult r = run_recoil(base);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_FALSE(fs::exists(dir / "out")) << bad << ": an item ran";
    EXPECT_EQ(listed.err, r.err) << bad;
    fs::remove_all(dir / "out");
    return r.err;
  };
  const auto expect_error = [&](const json& bad, const std::string& field, const std::string& why) {
    const std::string e = error_for(bad);
    EXPECT_NE(e.find("m.json: " + field + ": " + why), std::string::npos) << bad << ": " << e;
    EXPECT_EQ(e.find("--"), std::string::npos) << bad << ": names the option, not the field: " << e;
  };
  expect_error({{"mesh", "nope.obj"}}, "/1/mesh", "file not found: ");
  expect_error({{"mesh", "folder"}}, "/1/mesh", "a folder, not a file: ");
  expect_error({{"mesh", {"cube.off", "nope.obj"}}, {"mode", "drop"}}, "/1/mesh/1", "file not found: ");
  expect_error({{"scene", "nope.json"}}, "/1/scene", "file not found: ");
  expect_error({{"mesh", "cube.off"}, {"resolution", 5}}, "/1/resolution", "expected WxH");
  expect_error({{"mesh", "cube.off"}, {"video", "v.avi"}}, "/1/video", "cannot write 'v.avi'");
  expect_error({{"mesh", "cube.off"}, {"background", "pink"}}, "/1/background", "expected a colour #rrggbb");
  expect_error({{"mesh", "cube.off"}, {"color", "#12345"}}, "/1/color", "expected a colour #rrggbb");
  expect_error({{"mesh", "cube.off"}, {"mode", "drop"}, {"camera-target", "1,2"}}, "/1/camera-target",
               "expected X,Y,Z");
  expect_error({{"mesh", "cube.off"}, {"video", ""}}, "/1/video", "expected a file name");
  expect_error({{"mesh", "cube.off"}, {"frames", 0}}, "/1/frames", "frame numbers start at 1");
  // A default from --set is refused at the first item it reaches.
  write_text(dir / "m/m.json", json::array({{{"mesh", "cube.off"}}}).dump());
  const CommandResult set = run_recoil("batch " + shell_quote(dir / "m/m.json") + " --list --set resolution=big");
  EXPECT_EQ(set.exit_code, 2);
  EXPECT_NE(set.err.find("m.json: /0/resolution: expected WxH"), std::string::npos) << set.err;
}

// Runs `recoil ARGS` from inside `cwd`, its output streams kept outside it.
CommandResult run_recoil_in(const fs::path& cwd, const std::string& args) {
  const fs::path logs = scratch_dir("batch_run_in_logs");
  const int status = std::system(("cd " + shell_quote(cwd) + " && '" RECOIL_BINARY "' " + args + " </dev/null >" +
                                  shell_quote(logs / "out") + " 2>" + shell_quote(logs / "err"))
                                     .c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = file_bytes(logs / "out");
  r.err = file_bytes(logs / "err");
  return r;
}

TEST(BatchCommand, EveryPathInAnItemIsRelativeToTheManifest) {
  const fs::path dir = scratch_dir("batch_item_paths");
  fs::create_directories(dir / "m");
  fs::create_directories(dir / "elsewhere");
  fs::copy_file(kModels / "OFF/Cube.off", dir / "m/cube.off");
  const json one_frame = {{"mesh", "cube.off"}, {"frames", 1}, {"resolution", "64x48"}};
  json relative = one_frame, absolute = one_frame;
  relative.update({{"name", "rel"}, {"video", "v.gif"}, {"save-scene", "s.json"}, {"stats", "st.jsonl"}});
  absolute.update({{"name", "abs"}, {"video", (dir / "abs.gif").string()}});
  write_text(dir / "m/m.json", json::array({relative, absolute}).dump());
  // Given as a relative path from another folder, which is where the run's own relative paths would land.
  const std::string args = "batch ../m/m.json -o ../out";
  const CommandResult listed = run_recoil_in(dir / "elsewhere", args + " --list");
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_NE(listed.out.find("--video ../m/v.gif"), std::string::npos) << listed.out;
  EXPECT_NE(listed.out.find("--video " + (dir / "abs.gif").string()), std::string::npos) << listed.out;
  const CommandResult r = run_recoil_in(dir / "elsewhere", args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* written : {"m/v.gif", "m/s.json", "m/st.jsonl", "abs.gif", "out/rel/frame_0001.png"})
    EXPECT_TRUE(fs::is_regular_file(dir / written)) << written;
  EXPECT_TRUE(fs::is_empty(dir / "elsewhere"));
}

// --list and --contact-sheet-only run nothing: an option that would shape a
// run or write an output cannot apply to them, and is refused, not ignored.
TEST(BatchCommand, WhatRunsNothingRefusesTheOptionsOfARun) {
  const fs::path dir = scratch_dir("batch_list_options");
  const std::string batch = "batch " + shell_quote(cube_manifest(dir, 1)) + " -o " + shell_quote(dir / "out");
  for (const auto& [options, message] : std::vector<std::pair<std::string, std::string>>{
           {"--list --jobs 3", "--jobs excludes --list"},
           {"--list --contact-sheet " + shell_quote(dir / "s.png"), "--contact-sheet excludes --list"},
           {"--contact-sheet-only --jobs 2", "--jobs excludes --contact-sheet-only"}}) {
    const CommandResult r = run_recoil(batch + " " + options);
    EXPECT_EQ(r.exit_code, 2) << options;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "s.png"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The default output folder is named after the source, a folder given with
// a trailing slash included (it used to be output/ itself).
TEST(BatchCommand, AFolderGivenWithASlashNamesItsOutputFolder) {
  const fs::path dir = scratch_dir("batch_slash") / "shapes";
  fs::create_directories(dir);
  fs::copy_file(kModels / "OFF/Cube.off", dir / "Cube.off");
  const CommandResult r = run_recoil("batch " + shell_quote(dir.string() + "/") + " --list");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("-o output/shapes/Cube"), std::string::npos) << r.out;
}

TEST(BatchCommand, ContactSheetIsRebuiltFromFinishedOutputsAlone) {
  const fs::path dir = scratch_dir("batch_sheet");
  const fs::path manifest = cube_manifest(dir, 3);
  const std::string base = "batch " + shell_quote(manifest) + " -o " + shell_quote(dir / "out");
  ASSERT_EQ(run_recoil(base + " --shard 0/2").exit_code, 0);
  ASSERT_EQ(run_recoil(base + " --shard 1/2").exit_code, 0);
  const CommandResult r = run_recoil(base + " --contact-sheet-only --contact-sheet " + shell_quote(dir / "sheet.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_json(dir / "out/batch.json")["succeeded"], 3);
  const render::Image sheet = render::read_png(dir / "sheet.png");
  EXPECT_GT(sheet.width, 256);
  // The same outputs give the same sheet, byte for byte.
  ASSERT_EQ(run_recoil(base + " --contact-sheet-only --contact-sheet " + shell_quote(dir / "again.png")).exit_code, 0);
  EXPECT_EQ(file_bytes(dir / "sheet.png"), file_bytes(dir / "again.png"));
}

}  // namespace recoil::test
