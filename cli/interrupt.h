#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a frame loop: the handler only records
// the signal (async-signal-safe), and the loop polls pending_interrupt()
// between steps and frames, so it can stop with whole frames and run.json on
// disk. A second signal before the loop stops exits at once.
#include <string>

namespace recoil::cli {

// Installs the handlers for its lifetime and restores the previous ones after.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

// The signal received inside the current InterruptScope, or 0.
int pending_interrupt();

// Outside every InterruptScope (reading meshes, building the world, writing
// the last outputs), SIGINT and SIGTERM still stop the process at once, but
// first write the end line a caught interrupt writes (as JSON with
// `log_json`); exit 128 + the signal. Installed once, after the arguments
// are parsed; an InterruptScope restores it when it ends.
void report_interrupts_outside_the_loops(bool log_json);

// "SIGINT", "SIGKILL", ... (or "signal N" for a number with no name).
std::string signal_name(int signal_number);

}  // namespace recoil::cli
