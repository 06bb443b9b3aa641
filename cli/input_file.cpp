#include "cli/input_file.h"

namespace recoil::cli {
namespace fs = std::filesystem;

void require_regular_file(const JsonCursor& field, const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_regular_file(status)) return;
  if (!fs::exists(status)) field.fail("file not found: " + path.string());
  if (fs::is_directory(status)) field.fail("a folder, not a file: " + path.string());
  field.fail("not a regular file (a device, FIFO or socket): " + path.string());
}

}  // namespace recoil::cli
