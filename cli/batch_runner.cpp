#include "cli/batch_runner.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <deque>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cli/format_number.h"
#include "cli/interrupt.h"
#include "cli/item_lock.h"
#include "cli/output_dir.h"
#include "cli/progress.h"
#include "cli/work_limits.h"
#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

struct Running {
  const BatchItem* item;
  std::vector<InputStamp> inputs;  // its input files as it started
  fs::path partial;
  std::chrono::steady_clock::time_point start;
  ItemLock lock;  // released once the item has stopped and its folder is in place
};

// The item's command line, with its output folder and its share of the
// cores and of the memory (GiB).
std::vector<std::string> child_arguments(const BatchItem& item, const fs::path& partial, int threads,
                                         double memory_gib) {
  std::ostringstream cap;
  cap.precision(17);
  cap << memory_gib;
  std::vector<std::string> args = {"--max-memory", cap.str()};
  args.insert(args.end(), item.args.begin(), item.args.end());
  args.insert(args.end(), {"-o", partial.string()});
  const bool takes_threads = item.mode == "run" || item.mode == "drop";
  if (takes_threads && std::find(args.begin(), args.end(), "--threads") == args.end())
    args.insert(args.end(), {"--threads", std::to_string(threads)});
  return args;
}

// Starts `recoil ARGS` with stderr to `log` (stdin and stdout closed off),
// holding `lock`; it is stopped with SIGTERM if this process dies first.
pid_t start_child(const std::vector<std::string>& args, const fs::path& log, int threads, const ItemLock& lock) {
  std::vector<std::string> line = {"recoil"};
  line.insert(line.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : line) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string lp_threads = std::to_string(threads);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw Error(ErrorKind::internal, std::string("cannot start an item process: ") + std::strerror(errno));
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(143);  // the batch died before the line above took effect
    lock.inherit();
    const int null = ::open("/dev/null", O_RDWR);
    const int err = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (null < 0 || err < 0) ::_exit(4);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(err, 2);
    // llvmpipe's rasteriser threads, so that concurrent items share the cores rather than oversubscribe them.
    ::setenv("LP_NUM_THREADS", lp_threads.c_str(), 1);
    ::execv("/proc/self/exe", argv.data());
    ::_exit(5);
  }
  return pid;
}

// The item's own error line ("recoil: error: ..."), or a description of how it ended.
std::string failure_message(const fs::path& log, int status) {
  std::ifstream in(log);
  std::string line, found;
  while (std::getline(in, line))
    if (line.rfind("recoil: ", 0) == 0 && line.find("error") != std::string::npos) found = line.substr(8);
  if (!found.empty()) return found.rfind("error: ", 0) == 0 ? found.substr(7) : found;
  if (WIFSIGNALED(status))
    return "killed by " + signal_name(WTERMSIG(status)) +
           (WTERMSIG(status) == SIGKILL ? " (the kernel's out-of-memory killer sends it, as do schedulers at a limit; "
                                          "fewer --jobs leave each item more memory)"
                                        : "");
  return "exit " + std::to_string(WEXITSTATUS(status));
}

// Where an item's earlier folder waits to be deleted once the new one is in place.
fs::path replaced_folder(const fs::path& output, const BatchItem& item) { return output / (item.name + ".replaced"); }

void remove_or_throw(const fs::path& path) {
  std::error_code ec;
  fs::remove_all(path, ec);
  if (ec) throw output_error("cannot remove " + path.string() + ": " + ec.message());
}

// Records how the item ended and moves its folder into place.
ItemRecord finish_item(const Running& run, int status, const Shard& shard, const fs::path& output) {
  ItemRecord r;
  r.index = run.item->index;
  r.name = run.item->name;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.status = r.exit_code == 0 ? "succeeded" : "failed";
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - run.start).count();
  if (r.exit_code != 0) r.message = failure_message(run.partial / "log.txt", status);
  r.shard = shard.text();
  r.command = run.item->args;
  r.inputs = run.inputs;
  write_item_record(run.partial, r);
  const fs::path final_dir = output / run.item->name, old_dir = replaced_folder(output, *run.item);
  // An earlier run's folder (a failure, or a success of another command line
  // or other inputs) is renamed aside before it is deleted: deleting it in
  // place could be cut short with item.json gone and frames left, a folder
  // that batch could no longer tell from a user's.
  std::error_code ec;
  if (fs::exists(fs::symlink_status(final_dir, ec))) {
    remove_or_throw(old_dir);
    fs::rename(final_dir, old_dir, ec);
    if (ec) throw output_error("cannot move " + final_dir.string() + " to " + old_dir.string() + ": " + ec.message());
  }
  fs::rename(run.partial, final_dir, ec);
  if (ec) throw output_error("cannot move " + run.partial.string() + " to " + final_dir.string() + ": " + ec.message());
  remove_or_throw(old_dir);
  return r;
}

void report_item(const ItemRecord& r, const GlobalOptions& global) {
  if (global.log_json) {
    const nlohmann::json line = {{"command", "batch"},       {"event", "item"},   {"index", r.index},
                                 {"name", r.name},           {"status", r.status}, {"exit_code", r.exit_code},
                                 {"seconds", r.seconds},     {"message", r.message}, {"shard", r.shard}};
    std::cerr << line.dump() << std::endl;
  } else if (!global.quiet && !r.succeeded()) {
    std::cerr << "recoil: batch: item " << r.index << " (" << r.name << ") failed with exit " << r.exit_code << ": "
              << r.message << "\n";
  }
}

// The record of `item` when an earlier run finished it with its present
// command line; nothing when it is still to run.
std::optional<ItemRecord> finished_record(const fs::path& output, const BatchItem& item) {
  std::optional<ItemRecord> record = read_item_record(output / item.name);
  if (!record || !record->succeeded() || !records_item(*record, item)) return std::nullopt;
  record->reused = true;
  return record;
}

// Throws when OUT/NAME of an item this process runs is there but not a
// batch item's folder (every one holds item.json): a finished item replaces
// its folder, and what a user put there must not go with it.
void check_item_folders_are_ours(const std::vector<BatchItem>& items, const BatchRunOptions& options) {
  for (const BatchItem& item : items) {
    const fs::path dir = options.output / item.name;
    std::error_code ec;
    if (!options.shard.keeps(item.index) || !fs::exists(fs::symlink_status(dir, ec))) continue;
    if (fs::is_directory(fs::symlink_status(dir, ec)) && fs::exists(dir / "item.json")) continue;
    throw output_error(dir.string() + " is there but was not written by recoil batch (it has no item.json); item " +
                       std::to_string(item.index) +
                       " would replace it: move it away, or give the item another \"name\"");
  }
}

}  // namespace

std::vector<ItemRecord> run_batch_items(const std::vector<BatchItem>& items, const BatchRunOptions& options,
                                        const GlobalOptions& global) {
  ensure_output_dir(options.output);
  check_item_folders_are_ours(items, options);
  std::map<int, ItemRecord> records;
  std::deque<const BatchItem*> todo;
  for (const BatchItem& item : items) {
    if (!options.shard.keeps(item.index)) continue;
    if (const std::optional<ItemRecord> done = finished_record(options.output, item)) records[item.index] = *done;
    else todo.push_back(&item);
  }
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(todo.size())));
  const int threads = std::max(1, cores / jobs);
  // --max-memory (or its default) holds for the batch: the items running at once share it.
  const double memory_gib =
      std::min(memory_limit_bytes(global.max_memory_gib) / jobs / (1024.0 * 1024.0 * 1024.0), kMostMaxMemoryGib);
  if (memory_gib < kLeastMaxMemoryGib)
    throw bad_input("--max-memory: " + std::to_string(jobs) + " items at once (--jobs) would get " +
                    format_number("%.3g", memory_gib) + " GiB each; at least " +
                    format_number("%g", kLeastMaxMemoryGib));

  const InterruptScope interrupts;
  Progress progress(global, "batch", static_cast<int>(records.size() + todo.size()));
  progress.update(static_cast<int>(records.size()));
  std::map<pid_t, Running> running;
  int done = static_cast<int>(records.size());
  while (!todo.empty() || !running.empty()) {
    // An item another process holds (an orphan of a killed batch, another
    // shard) waits at the back of the queue; once claimed, it may turn out done.
    for (size_t held = 0; held < todo.size() && static_cast<int>(running.size()) < jobs && !pending_interrupt();) {
      const BatchItem& item = *todo.front();
      todo.pop_front();
      std::optional<ItemLock> lock = ItemLock::try_take(options.output, item.name);
      if (!lock) {
        todo.push_back(&item);
        ++held;
        continue;
      }
      held = 0;
      if (const std::optional<ItemRecord> r = finished_record(options.output, item)) {
        records[item.index] = *r;
        progress.update(++done);
        continue;
      }
      const std::vector<InputStamp> inputs = input_stamps(item);  // before it reads them
      const fs::path partial = options.output / (item.name + ".partial");
      remove_or_throw(partial);  // what a killed run left
      remove_or_throw(replaced_folder(options.output, item));
      ensure_output_dir(partial);
      const pid_t pid =
          start_child(child_arguments(item, partial, threads, memory_gib), partial / "log.txt", threads, *lock);
      running.emplace(pid, Running{&item, inputs, partial, std::chrono::steady_clock::now(), std::move(*lock)});
    }
    if (pending_interrupt()) {
      for (const auto& [pid, run] : running) ::kill(pid, SIGTERM);
      for (const auto& [pid, run] : running) ::waitpid(pid, nullptr, 0);
      progress.finish();
      const int sig = pending_interrupt();
      throw Interrupted(sig, "interrupted by " + signal_name(sig) + " after " + std::to_string(done) + " items; " +
                                 "a rerun skips the finished ones");
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid <= 0) {
      if (progress.due())
        progress.working(running.empty() ? "waiting for another process to finish " + std::to_string(todo.size()) +
                                               (todo.size() == 1 ? " item" : " items")
                                         : std::to_string(running.size()) + " running");
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    if (pending_interrupt()) {  // it stopped for the same signal: left partial, for the rerun
      running.erase(it);
      continue;
    }
    const ItemRecord r = finish_item(it->second, status, options.shard, options.output);
    running.erase(it);
    records[r.index] = r;
    report_item(r, global);
    progress.update(++done);
  }
  progress.finish();
  std::vector<ItemRecord> out;
  for (const auto& [index, r] : records) out.push_back(r);
  return out;
}

int batch_exit_code(const std::vector<ItemRecord>& records) {
  const auto severity = [](int code) {
    if (code <= static_cast<int>(ErrorKind::internal)) return code;
    const int signal_number = code - 128;  // the shell's convention, which recoil's own interrupts follow too
    const bool from_outside = signal_number == SIGKILL || signal_number == SIGTERM || signal_number == SIGINT ||
                              signal_number == SIGHUP || signal_number == SIGXCPU;
    return static_cast<int>(from_outside ? ErrorKind::output_failed : ErrorKind::internal);
  };
  int code = 0;
  for (const ItemRecord& r : records) code = std::max(code, severity(r.exit_code));
  return code;
}

}  // namespace recoil::cli
