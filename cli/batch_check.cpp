#include "cli/batch_check.h"

#include <CLI/CLI.hpp>

#include "cli/render_options.h"
#include "cli/run_options.h"
#include "cli/video_encoder.h"
#include "core/error.h"

namespace recoil::cli {

void fail_at_option(const JsonCursor& item, const std::string& message) {
  const size_t colon = message.find(": ");
  if (message.rfind("--", 0) == 0 && colon != std::string::npos && item.has(message.substr(2, colon - 2)))
    item.child(message.substr(2, colon - 2)).fail(message.substr(colon + 2));
  for (const auto& [key, value] : item.value().items())
    if (message.find("--" + key) != std::string::npos) item.child(key).fail(message);
  item.fail(message);
}

void check_option_values(const std::vector<std::string>& args, const JsonCursor& item) {
  // The options every command shares, parsed by their own definitions into a
  // RunOptions; the command's other options and its files are left over.
  CLI::App probe;
  probe.allow_extras();
  RunOptions run;
  add_run_options(probe, run);
  std::vector<std::string> line(args.rbegin(), args.rend());  // CLI11 takes the arguments last first
  try {
    probe.parse(line);
  } catch (const CLI::ParseError& e) {
    fail_at_option(item, e.what());
  }
  const auto given = [&](const char* name) { return probe.count(name) > 0; };
  try {
    if (given("--color")) parse_color(run.render.color, "--color");
    if (given("--camera-position")) parse_point(run.render.camera_position, "--camera-position");
    if (given("--camera-target")) parse_point(run.render.camera_target, "--camera-target");
    to_render_settings(run.render);
    if (given("--video")) require_video(run.video, run.render.background == "transparent");
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::bad_input) throw;
    fail_at_option(item, e.what());
  }
}

}  // namespace recoil::cli
