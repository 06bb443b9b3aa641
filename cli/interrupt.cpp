#include "cli/interrupt.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

namespace recoil::cli {
namespace {

// Lock-free, so reading and writing it from a signal handler is defined.
std::atomic<int> g_interrupt_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction g_previous_int, g_previous_term;

extern "C" void record_interrupt(int signal_number) {
  // The user asked twice: the loop is too slow to notice, so stop now.
  if (g_interrupt_signal.exchange(signal_number) != 0) ::_exit(128 + signal_number);
}

// report_interrupts_outside_the_loops' lines, made before any signal can
// come and never freed (a signal may arrive while the process exits): the
// handler may only read them, write(2) and _exit(2).
struct EndLine {
  char text[512];
  size_t size;
};
EndLine g_sigint_line{}, g_sigterm_line{};
// The process that installed the handler: a child forked while it is
// installed (the mesh reader) inherits it, and on a terminal's Ctrl-C, which
// reaches the whole process group, must leave the line to its parent.
pid_t g_reporting_process = 0;

extern "C" void report_and_exit(int signal_number) {
  const EndLine& line = signal_number == SIGINT ? g_sigint_line : g_sigterm_line;
  if (::getpid() == g_reporting_process) {
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.text, line.size);
  }
  ::_exit(128 + signal_number);
}

}  // namespace

void report_interrupts_outside_the_loops(bool log_json) {
  for (const int signal_number : {SIGINT, SIGTERM}) {
    const std::string message = "interrupted by " + signal_name(signal_number) +
                                " outside the frame loop: stopped at once (files are written whole or not at all)";
    const int code = 128 + signal_number;
    const std::string line =
        (log_json ? nlohmann::json{{"event", "interrupted"}, {"message", message}, {"exit_code", code}}.dump()
                  : "recoil: " + message) +
        "\n";
    EndLine& out = signal_number == SIGINT ? g_sigint_line : g_sigterm_line;
    out.size = std::min(line.size(), sizeof(out.text));
    std::memcpy(out.text, line.data(), out.size);
  }
  g_reporting_process = ::getpid();
  struct sigaction action {};
  action.sa_handler = report_and_exit;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction previous {};
    ::sigaction(signal_number, nullptr, &previous);
    // A signal the caller chose to ignore (a background job's SIGINT) stays ignored.
    if (previous.sa_handler != SIG_IGN) ::sigaction(signal_number, &action, nullptr);
  }
}

InterruptScope::InterruptScope() {
  g_interrupt_signal = 0;
  struct sigaction action {};
  action.sa_handler = record_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // file writes on the encoder threads carry on
  ::sigaction(SIGINT, &action, &g_previous_int);
  ::sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptScope::~InterruptScope() {
  ::sigaction(SIGINT, &g_previous_int, nullptr);
  ::sigaction(SIGTERM, &g_previous_term, nullptr);
}

int pending_interrupt() { return g_interrupt_signal.load(); }

std::string signal_name(int signal_number) {
  const char* abbreviation = ::sigabbrev_np(signal_number);  // "INT", "KILL"; null for an unknown number
  return abbreviation != nullptr ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal_number);
}

}  // namespace recoil::cli
