// Stopping `recoil run` with SIGINT or SIGTERM and finishing it with
// --resume: the exit codes, run.json's status, no temporary left behind, and
// frames byte-identical to an uninterrupted run; --resume also draws again
// the frames a crash cut short and removes the temporaries it left. A batch
// item killed from outside is a retryable failure.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "render/png_probe.h"
#include "tests/cli/sphere_stl_file.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A box dropped on a plane, tiny frames, and enough of them (601) that the
// run is still going when the test signals it after the third.
fs::path write_tiny_box_scene(const fs::path& dir) {
  const fs::path scene = dir / "tiny-box.json";
  std::ofstream(scene) << R"({"recoil": 1, "name": "tiny-box",
    "simulation": {"dt": 0.01, "duration": 20},
    "bodies": [{"name": "ground", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]},
               {"name": "box", "type": "rigid", "primitive": {"box": [0.2, 0.2, 0.2]}, "density": 500,
                "transform": {"position": [0, 0.5, 0]}}],
    "render": {"fps": 30, "resolution": [64, 48], "msaa": 0, "shadows": false}})";
  return scene;
}

// The frame files in `dir`, sorted by name.
std::vector<std::string> frame_files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && e.path().extension() == ".png") names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> temporaries_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) names.push_back(e.path().filename().string());
  return names;
}

// Every frame of `reference` is in `dir` with the same bytes, and no other.
void expect_same_frames(const fs::path& dir, const fs::path& reference) {
  const std::vector<std::string> names = frame_files_in(reference);
  ASSERT_EQ(frame_files_in(dir), names);
  for (const std::string& name : names) ASSERT_EQ(file_bytes(dir / name), file_bytes(reference / name)) << name;
}

// The tiny box scene run to the end once per test process.
const fs::path& uninterrupted_run() {
  static const fs::path dir = [] {
    const fs::path out = scratch_dir("interrupt_reference");
    const fs::path scene = write_tiny_box_scene(out);
    const CommandResult r = run_recoil("run " + shell_quote(scene) + " -q -o " + shell_quote(out / "frames"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out / "frames";
  }();
  return dir;
}

// `recoil run SCENE -q -o OUT` as a child process, stderr into `err`.
// Starts `recoil ARGS` with stdout and stderr to `err`, in a process group of
// its own (as a shell starts a job); returns its pid, the group's id.
pid_t start_recoil(std::vector<std::string> args, const fs::path& err) {
  args.insert(args.begin(), RECOIL_BINARY);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  ::setpgid(0, 0);
  const int null_in = ::open("/dev/null", O_RDONLY);
  const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(null_in, STDIN_FILENO);
  ::dup2(err_fd, STDOUT_FILENO);
  ::dup2(err_fd, STDERR_FILENO);
  ::execv(RECOIL_BINARY, argv.data());
  ::_exit(127);
}

pid_t start_run(const fs::path& scene, const fs::path& out, const fs::path& err) {
  return start_recoil({"run", scene.string(), "-q", "-o", out.string()}, err);
}

// Polls until `file` exists (true) or the child has ended (false, with its
// exit status in *status): no fixed sleep, however loaded the machine is.
bool wait_for_file(pid_t pid, const fs::path& file, int* status) {
  while (!fs::exists(file)) {
    if (::waitpid(pid, status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

// Polls until process `pid` has a child and returns the child's pid; 0 when
// `pid` ended first.
pid_t wait_for_child(pid_t pid) {
  const fs::path children = "/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children";
  for (;;) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return 0;
    std::ifstream in(children);
    pid_t child = 0;
    if (in >> child) return child;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

int exit_code_of(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

struct StoppedRun {
  int exit_code = -1;
  std::string err;
  fs::path scene, out;
};

// Starts the tiny box run, sends `signal_number` once frame 3 is on disk and
// waits for the run to end.
StoppedRun interrupt_run(const std::string& name, int signal_number) {
  const fs::path dir = scratch_dir(name);
  StoppedRun result{-1, "", write_tiny_box_scene(dir), dir / "frames"};
  const pid_t pid = start_run(result.scene, result.out, dir / "stderr.txt");
  EXPECT_GT(pid, 0);
  int status = 0;
  if (!wait_for_file(pid, result.out / "frame_0003.png", &status)) {
    ADD_FAILURE() << "the run ended before its third frame (status " << status << "): "
                  << file_bytes(dir / "stderr.txt");
    return result;
  }
  ::kill(pid, signal_number);
  result.exit_code = exit_code_of(pid);
  result.err = file_bytes(dir / "stderr.txt");
  return result;
}

}  // namespace

TEST(InterruptRun, SigintLeavesWholeFramesAndRunJsonAndResumeMatchesAnUninterruptedRun) {
  const StoppedRun run = interrupt_run("interrupt_sigint", SIGINT);
  ASSERT_EQ(run.exit_code, 130) << run.err;
  EXPECT_NE(run.err.find("recoil: interrupted by SIGINT after "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--resume"), std::string::npos) << run.err;
  EXPECT_EQ(temporaries_in(run.out), std::vector<std::string>{});
  const json report = json::parse(file_bytes(run.out / "run.json"));
  EXPECT_EQ(report["exit"]["status"], "interrupted");
  EXPECT_EQ(report["exit"]["code"], 130);
  const std::vector<std::string> kept = frame_files_in(run.out);
  ASSERT_GE(kept.size(), 3u);
  EXPECT_LT(kept.size(), frame_files_in(uninterrupted_run()).size()) << "the signal came after the last frame";
  for (const std::string& name : kept) EXPECT_TRUE(render::is_whole_png(run.out / name, 64, 48)) << name;
  EXPECT_EQ(report["frames"]["written"], static_cast<int>(kept.size()));

  const CommandResult resumed = run_recoil("run " + shell_quote(run.scene) + " -q --resume -o " + shell_quote(run.out));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  expect_same_frames(run.out, uninterrupted_run());
  const json after = json::parse(file_bytes(run.out / "run.json"));
  EXPECT_EQ(after["exit"]["status"], "ok");
  EXPECT_EQ(after["frames"]["skipped"], static_cast<int>(kept.size()));
}

// A signal to the job while the mesh is still being read (in a child process
// of recoil's, whose appearance also says recoil is past its arguments), as
// a terminal's Ctrl-C sends it to the whole process group, stops the command
// at once with one end line, the one a caught interrupt writes (JSON under
// --log-json), and nothing on disk.
TEST(InterruptRun, ASignalWhileTheMeshIsReadIsReported) {
  const fs::path dir = scratch_dir("interrupt_loading");
  const fs::path stl = write_sphere_stl(dir / "scan.stl", 250);
  for (const int signal_number : {SIGINT, SIGTERM}) {
    const fs::path out = dir / ("out" + std::to_string(signal_number)), err = dir / "stderr.txt";
    std::vector<std::string> args = {"turntable", stl.string(), "--turn-frames", "2", "--resolution", "64x48", "-o",
                                     out.string()};
    if (signal_number == SIGTERM) args.insert(args.begin(), "--log-json");
    const pid_t pid = start_recoil(args, err);
    ASSERT_GT(pid, 0);
    ASSERT_GT(wait_for_child(pid), 0) << "it ended before reading: " << file_bytes(err);
    ::kill(-pid, signal_number);
    EXPECT_EQ(exit_code_of(pid), 128 + signal_number);
    const std::string message = "interrupted by " + std::string(signal_number == SIGINT ? "SIGINT" : "SIGTERM") +
                                " outside the frame loop: stopped at once (files are written whole or not at all)";
    if (signal_number == SIGINT) {
      EXPECT_EQ(file_bytes(err), "recoil: " + message + "\n");
    } else {
      const json line = json::parse(file_bytes(err));
      EXPECT_EQ(line["event"], "interrupted");
      EXPECT_EQ(line["message"], message);
      EXPECT_EQ(line["exit_code"], 143);
    }
    EXPECT_FALSE(fs::exists(out));
  }
}

// A batch item killed from outside (SIGKILL, as the kernel's out-of-memory
// killer sends it) is a failed item that a rerun may retry, not a bug: the
// batch exits 4, and batch.json names the signal.
TEST(InterruptBatch, AnItemKilledFromOutsideIsRetryable) {
  const fs::path dir = scratch_dir("interrupt_batch_item");
  write_tiny_box_scene(dir);
  std::ofstream(dir / "manifest.json") << R"([{"scene": "tiny-box.json"}])";
  const fs::path out = dir / "out";
  const pid_t pid = start_recoil({"batch", (dir / "manifest.json").string(), "-q", "-o", out.string()},
                                 dir / "stderr.txt");
  ASSERT_GT(pid, 0);
  const pid_t item = wait_for_child(pid);
  ASSERT_GT(item, 0) << "the batch ended before its item started: " << file_bytes(dir / "stderr.txt");
  ::kill(item, SIGKILL);
  EXPECT_EQ(exit_code_of(pid), 4) << file_bytes(dir / "stderr.txt");
  const json record = json::parse(file_bytes(out / "batch.json"));
  const json& entry = record["items"][0];
  EXPECT_EQ(entry["status"], "failed");
  EXPECT_EQ(entry["exit_code"], 128 + SIGKILL);
  EXPECT_NE(entry["message"].get<std::string>().find("killed by SIGKILL"), std::string::npos) << entry;
}

TEST(InterruptRun, SigtermExits143WithRunJsonInterrupted) {
  const StoppedRun run = interrupt_run("interrupt_sigterm", SIGTERM);
  ASSERT_EQ(run.exit_code, 143) << run.err;
  EXPECT_NE(run.err.find("recoil: interrupted by SIGTERM after "), std::string::npos) << run.err;
  EXPECT_EQ(temporaries_in(run.out), std::vector<std::string>{});
  const json report = json::parse(file_bytes(run.out / "run.json"));
  EXPECT_EQ(report["exit"]["status"], "interrupted");
  EXPECT_EQ(report["exit"]["code"], 143);
}

TEST(ResumeRun, DrawsCutAndEmptyFramesAgainAndRemovesStaleTemporaries) {
  const fs::path reference = uninterrupted_run();
  const fs::path dir = scratch_dir("resume_damaged");
  const fs::path scene = write_tiny_box_scene(dir), out = dir / "frames";
  fs::copy(reference, out);
  // What a kill -9 or a full disk leaves: a frame cut short, an empty one,
  // and temporaries of a frame and of run.json.
  const std::string frame2 = file_bytes(out / "frame_0002.png");
  { std::ofstream(out / "frame_0002.png", std::ios::binary | std::ios::trunc) << frame2.substr(0, frame2.size() / 2); }
  { std::ofstream(out / "frame_0004.png", std::ios::binary | std::ios::trunc); }
  { std::ofstream(out / "frame_0003.png.tmp-12345-0", std::ios::binary) << std::string(1 << 20, 'x'); }
  { std::ofstream(out / "run.json.tmp-12345-1", std::ios::binary) << "{"; }
  ASSERT_FALSE(render::is_whole_png(out / "frame_0002.png", 64, 48));
  ASSERT_FALSE(render::is_whole_png(out / "frame_0004.png", 64, 48));

  const CommandResult r = run_recoil("run " + shell_quote(scene) + " -q --resume -o " + shell_quote(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(temporaries_in(out), std::vector<std::string>{});
  expect_same_frames(out, reference);
  const json report = json::parse(file_bytes(out / "run.json"));
  EXPECT_EQ(report["frames"]["written"], 2);
}

}  // namespace recoil::test
