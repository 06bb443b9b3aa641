#pragma once
// recoil::Error: bad input or a broken environment, thrown and caught only in
// main(), which turns its kind into the exit code (README, "Exit codes").
// Bugs use RECOIL_CHECK (core/check.h) instead; numerical trouble during a
// simulation is a status in the step report, never an exception.
#include <stdexcept>
#include <string>

namespace recoil {

enum class ErrorKind {
  bad_input = 2,       // scene, mesh, options: the message names file and field
  sim_failed = 3,      // diverged, NaN, inverted beyond recovery
  output_failed = 4,   // disk full, permissions: retryable
  internal = 5,        // a bug that was caught
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), m_kind(kind) {}
  ErrorKind kind() const { return m_kind; }
  int exit_code() const { return static_cast<int>(m_kind); }

 private:
  ErrorKind m_kind;
};

// SIGINT or SIGTERM stopped a command cleanly (outputs so far complete and
// consistent); main() prints "recoil: <what>" and exits 128 + the signal, as
// a shell expects of a program killed by it (130 for Ctrl-C, 143 for SIGTERM).
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal_number, const std::string& message) : std::runtime_error(message), m_signal(signal_number) {}
  int exit_code() const { return 128 + m_signal; }

 private:
  int m_signal;
};

// Shorthands for the common kinds.
inline Error bad_input(const std::string& message) { return Error(ErrorKind::bad_input, message); }
inline Error output_error(const std::string& message) { return Error(ErrorKind::output_failed, message); }

}  // namespace recoil
