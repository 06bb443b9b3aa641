#pragma once
// The checks an item's own run would make of its input files and option
// values, made for every item of a batch before the first one starts, so that
// a refusal names the manifest's field rather than failing one item later.
#include <filesystem>
#include <string>
#include <vector>

#include "cli/json_cursor.h"

namespace recoil::cli {

// Fails with `message`, a parser's refusal that names an option ("--NAME:
// why"), at the field NAME of `item` (with the why alone), or at the first
// field whose option the message mentions, else at the item itself.
[[noreturn]] void fail_at_option(const JsonCursor& item, const std::string& message);

// Parses the option values of `args` (an item's command line) with the
// parsers its run applies after CLI11 (resolution, colours, points, the
// video's format); a refusal fails at the field of `item` that gave the
// option it names.
void check_option_values(const std::vector<std::string>& args, const JsonCursor& item);

}  // namespace recoil::cli
