#pragma once
// The one line recoil prints for a command line CLI11 refused: an unknown
// command or option gets the closest known one as a suggestion.
#include <CLI/CLI.hpp>
#include <string>

namespace recoil::cli {

// `args` are argv[1..]; the message has no "recoil: error:" prefix.
std::string usage_error(const CLI::App& app, const CLI::ParseError& error, const std::vector<std::string>& args);

// The message for a first word that names no command, or empty when it
// names one or there is none; also after a parse that stopped for --help.
std::string unknown_command(const CLI::App& app, const std::vector<std::string>& args);

}  // namespace recoil::cli
