// recoil: the command-line entry point. Parses the command line, runs the
// chosen subcommand and turns every failure into one `recoil: error:` line
// (a JSON line with --log-json) and the exit code (README, "Exit codes").
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/build_info.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "cli/number_range.h"
#include "cli/usage_error.h"
#include "cli/work_limits.h"
#include "core/error.h"

namespace {

// A run's failure or interruption: one `recoil: error: ...` (or `recoil:
// interrupted ...`) line, or with --log-json one {"event": ...} line a log
// reader can parse like the rest.
void report_end(const recoil::cli::GlobalOptions& global, const char* event, const std::string& message, int code) {
  if (global.log_json) {
    // A path in the message may hold bytes that are not UTF-8 (info and compare read such files).
    std::cerr << nlohmann::json{{"event", event}, {"message", message}, {"exit_code", code}}.dump(
                     -1, ' ', false, nlohmann::json::error_handler_t::replace)
              << std::endl;
  } else {
    std::cerr << "recoil: " << (std::string(event) == "error" ? "error: " : "") << message << std::endl;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace recoil;
  CLI::App app{"recoil: simulate elastic and rigid bodies colliding with friction, and render every frame to PNG."};
  app.set_version_flag("--version", std::string("recoil ") + RECOIL_VERSION + " (" + cli::build_commit() + ")");
  app.require_subcommand(1);
  app.fallthrough();  // global flags (-q, --log-json) may follow the subcommand
  app.footer("Run `recoil COMMAND --help` for a command's options and examples.");

  cli::GlobalOptions global;
  global.arguments.assign(argv + 1, argv + argc);
  app.add_flag("-q,--quiet", global.quiet, "No progress bar or summary lines (a summary that carries a warning still prints)")->configurable(false);
  app.add_flag("--log-json", global.log_json,
               "Machine-readable lines (JSON) on stderr: progress, the summary, an error (-q does not silence them)");
  app.add_option("--max-memory", global.max_memory_gib,
                 "GiB a run may use: one estimated to need more is refused before it starts (default: 80% of RAM)")
      ->check(cli::NumberIn(cli::kLeastMaxMemoryGib, cli::kMostMaxMemoryGib));
  cli::Action action;
  cli::add_run_command(app, global, action);
  cli::add_drop_command(app, global, action);
  cli::add_turntable_command(app, global, action);
  cli::add_info_command(app, global, action);
  cli::add_compare_command(app, global, action);
  cli::add_batch_command(app, global, action);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    // --help or --version; after a word that names no command, that word is the mistake.
    if (e.get_exit_code() == 0 && cli::unknown_command(app, args).empty()) return app.exit(e);
    std::cerr << "recoil: error: " << cli::usage_error(app, e, args) << std::endl;
    return static_cast<int>(ErrorKind::bad_input);
  }
  cli::report_interrupts_outside_the_loops(global.log_json);
  try {
    return action ? action() : 0;
  } catch (const Interrupted& e) {
    report_end(global, "interrupted", e.what(), e.exit_code());
    return e.exit_code();
  } catch (const Error& e) {
    report_end(global, "error", e.what(), e.exit_code());
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    std::cerr << "recoil: error: out of memory" << std::endl;
    return static_cast<int>(ErrorKind::internal);
  } catch (const std::exception& e) {
    std::cerr << "recoil: error: internal: " << e.what() << std::endl;
    return static_cast<int>(ErrorKind::internal);
  }
}
