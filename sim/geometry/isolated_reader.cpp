#include "sim/geometry/isolated_reader.h"

#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <new>
#include <stdexcept>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/write_fully.h"

namespace recoil::sim {
namespace {

void (*g_child_setup)() = nullptr;

[[noreturn]] void system_failed(const std::string& call, int saved_errno) {
  throw Error(ErrorKind::internal, call + ": " + errno_message(saved_errno));
}

// Closes the descriptor when the read ends, whichever way.
struct FdGuard {
  int fd;
  ~FdGuard() { ::close(fd); }
};

// The child's answer: one byte, 0 for a result or an ErrorKind, then the result or the message.
std::string answer_of(const std::function<std::string()>& read) {
  try {
    return std::string(1, '\0') + read();
  } catch (const Error& e) {
    return std::string(1, static_cast<char>(e.exit_code())) + e.what();
  } catch (const std::bad_alloc&) {
    return std::string(1, static_cast<char>(ErrorKind::bad_input)) + "out of memory while reading";
  } catch (const std::exception& e) {
    return std::string(1, static_cast<char>(ErrorKind::bad_input)) + e.what();
  }
}

// The whole of the in-memory file `fd`, which nobody writes any more.
std::string read_whole(int fd) {
  struct stat info {};
  if (::fstat(fd, &info) != 0) system_failed("fstat", errno);
  std::string bytes(static_cast<size_t>(info.st_size), '\0');
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::pread(fd, bytes.data() + done, bytes.size() - done, static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) system_failed("pread", n < 0 ? errno : 0);
    done += static_cast<size_t>(n);
  }
  return bytes;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) system_failed("waitpid", errno);
  return status;
}

// Never returns into the caller's code: the child is a copy of the caller's
// process, and whatever escaped here would run on as a second one.
[[noreturn]] void run_child(const std::function<std::string()>& read, int fd, int cpu_seconds, pid_t parent) noexcept {
  // Ends with its parent, as a killed recoil leaves no reader behind.
  if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent) ::_exit(1);
  // SIGXCPU at the soft limit, SIGKILL a second later; no core file of a reader stopped on purpose.
  const rlimit cpu{static_cast<rlim_t>(cpu_seconds), static_cast<rlim_t>(cpu_seconds) + 1};
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CPU, &cpu);
  ::setrlimit(RLIMIT_CORE, &no_core);
  int code = 1;
  try {
    if (g_child_setup) g_child_setup();
    const std::string answer = answer_of(read);
    code = write_fully(fd, answer.data(), answer.size()) == 0 ? 0 : 1;
  } catch (...) {
  }
  // _exit: the parent's exit handlers (and a sanitizer's leak check) are not the child's to run.
  ::_exit(code);
}

}  // namespace

void set_reader_child_setup(void (*setup)()) { g_child_setup = setup; }

std::string read_in_child(const std::function<std::string()>& read, const std::string& file, const std::string& reader,
                          int cpu_seconds) {
  // The answer goes through an in-memory file read once the child has ended,
  // rather than a pipe, which the parent would have to drain while the child runs.
  const FdGuard answer_file{::memfd_create("recoil-reader-answer", MFD_CLOEXEC)};
  if (answer_file.fd < 0) system_failed("memfd_create", errno);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) system_failed("fork", errno);
  if (pid == 0) run_child(read, answer_file.fd, std::max(cpu_seconds, 1), parent);
  const int status = wait_for(pid);
  std::string answer = read_whole(answer_file.fd);
  const std::string who = file + ": " + reader;
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
    throw bad_input(who + " did not finish reading this file in " + std::to_string(cpu_seconds) + " s of CPU time");
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
    throw bad_input(who + " was killed reading this file (out of memory, or past its CPU time)");
  if (WIFSIGNALED(status))
    throw bad_input(who + " crashed reading this file (" + ::strsignal(WTERMSIG(status)) + ")");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty())
    throw bad_input(who + " stopped reading this file without an answer");
  const int kind = static_cast<unsigned char>(answer[0]);
  if (kind == 0) return answer.erase(0, 1);
  const bool known = kind == static_cast<int>(ErrorKind::bad_input) || kind == static_cast<int>(ErrorKind::sim_failed) ||
                     kind == static_cast<int>(ErrorKind::output_failed) || kind == static_cast<int>(ErrorKind::internal);
  throw Error(known ? static_cast<ErrorKind>(kind) : ErrorKind::internal, answer.substr(1));
}

}  // namespace recoil::sim
