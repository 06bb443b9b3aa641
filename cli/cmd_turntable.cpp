#include "cli/commands.h"

namespace recoil::cli {

void add_turntable_command(CLI::App& app, const GlobalOptions&, Action&) {
  app.add_subcommand("turntable", "(in progress)");
}

}  // namespace recoil::cli
