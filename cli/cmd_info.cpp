#include "cli/commands.h"

namespace recoil::cli {

void add_info_command(CLI::App& app, const GlobalOptions&, Action&) {
  app.add_subcommand("info", "(in progress)");
}

}  // namespace recoil::cli
