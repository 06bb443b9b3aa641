#include "cli/interrupt.h"

#include <unistd.h>

#include <atomic>
#include <csignal>

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

}  // namespace

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
  if (signal_number == SIGINT) return "SIGINT";
  if (signal_number == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal_number);
}

}  // namespace recoil::cli
