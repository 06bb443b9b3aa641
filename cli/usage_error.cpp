#include "cli/usage_error.h"

#include "cli/json_cursor.h"

namespace recoil::cli {
namespace {

// Long option names ("--frames") of `app` and, for a subcommand, of the
// top-level options that may follow it.
std::vector<std::string> long_options(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* a = &app; a != nullptr; a = a->get_parent())
    for (const CLI::Option* option : a->get_options())
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  return names;
}

std::string known_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

std::string unknown_command(const CLI::App& app, const std::vector<std::string>& args) {
  if (!app.get_subcommands().empty()) return "";
  std::vector<std::string> commands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) commands.push_back(sub->get_name());
  // Before any command was recognised, the first word past the top-level
  // options (and their values) is a mistyped command.
  size_t word = 0;
  while (word < args.size() && args[word].rfind('-', 0) == 0 && args[word] != "--") {
    const std::string name = args[word].substr(0, args[word].find('='));
    const CLI::Option* option = app.get_option_no_throw(name);
    const bool takes_value = option != nullptr && option->get_type_size() > 0 && name.size() == args[word].size();
    word += takes_value ? 2 : 1;
  }
  if (word >= args.size() || args[word] == "--") return "";
  const std::string guess = near_miss(args[word], commands);
  return "unknown command \"" + args[word] + "\"; " +
         (guess.empty() ? "the commands are " + known_list(commands) : "did you mean \"" + guess + "\"?") +
         " (see --help)";
}

std::string usage_error(const CLI::App& app, const CLI::ParseError& error, const std::vector<std::string>& args) {
  if (const std::string unknown = unknown_command(app, args); !unknown.empty()) return unknown;
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  const CLI::App& command = chosen.empty() ? app : *chosen.front();
  const std::vector<std::string> options = long_options(command);
  const std::string see = " (see recoil " + (chosen.empty() ? "" : command.get_name() + " ") + "--help)";
  for (const std::string& arg : args) {
    if (arg == "--") break;  // what follows is positional
    if (arg.rfind("--", 0) != 0) continue;
    const std::string name = arg.substr(0, arg.find('='));
    if (std::find(options.begin(), options.end(), name) != options.end()) continue;
    const std::string guess = near_miss(name, options);
    return "unknown option " + name + (guess.empty() ? "" : "; did you mean " + guess + "?") + see;
  }
  return std::string(error.what()) + see;
}

}  // namespace recoil::cli
