#pragma once
// The subcommands of the recoil executable. Each add_*_command registers one
// CLI11 subcommand; when the user picks it, its callback stores the work to do
// in `action`, which main() runs inside the one error handler (exit codes in
// the README).
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "cli/shell_quote.h"

namespace recoil::cli {

struct GlobalOptions {
  bool quiet = false;     // -q: no progress bar, no summary lines
  bool log_json = false;  // --log-json: machine-readable progress on stderr
  double max_memory_gib = 0.0;  // --max-memory: a run estimated to need more is refused; 0: 80 % of the machine's
  std::vector<std::string> arguments;  // the words after `recoil`, as given
  // The command as typed, shell-quoted: what run.json records.
  std::string command_line() const {
    std::string line = "recoil";
    for (const std::string& argument : arguments) line += " " + shell_word(argument);
    return line;
  }
};

using Action = std::function<int()>;

void add_info_command(CLI::App& app, const GlobalOptions& global, Action& action);
void add_turntable_command(CLI::App& app, const GlobalOptions& global, Action& action);
void add_compare_command(CLI::App& app, const GlobalOptions& global, Action& action);
void add_run_command(CLI::App& app, const GlobalOptions& global, Action& action);
void add_drop_command(CLI::App& app, const GlobalOptions& global, Action& action);
void add_batch_command(CLI::App& app, const GlobalOptions& global, Action& action);

}  // namespace recoil::cli
