#include "cli/utf8_arguments.h"

#include <filesystem>

#include "core/error.h"
#include "core/utf8.h"

namespace recoil::cli {

void require_utf8(const std::string& text, const std::string& what) {
  if (first_invalid_utf8(text) == std::string::npos) return;
  throw bad_input(what + " '" + escape_invalid_utf8(text) +
                  "' is not UTF-8 text; recoil records its command lines and file paths in JSON (run.json, "
                  "scene.json, batch.json), which holds UTF-8 only: give it a UTF-8 name "
                  "(`convmv -f latin1 -t utf8 --notest NAME` renames a Latin-1 one)");
}

void require_utf8_arguments(const GlobalOptions& global) {
  for (const std::string& argument : global.arguments) require_utf8(argument, "argument");
  // Relative paths are recorded made absolute, through the working directory.
  std::error_code ec;
  const std::filesystem::path here = std::filesystem::current_path(ec);
  if (!ec) require_utf8(here.string(), "the working directory");
}

}  // namespace recoil::cli
