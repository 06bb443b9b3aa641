#pragma once
// Atomic file output (compare's HTML report and --update copies, run's
// scene.json and run.json, drop's --save-scene): the whole text is replaced
// through core/atomic_write.h, so a reader or a crash never sees a
// half-written file.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace recoil::cli {

class AtomicFile {
 public:
  // Collects the content in memory until commit().
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return m_stream; }
  // Writes, flushes to disk and renames over the target; throws
  // recoil::Error(output_failed) with the system's reason. Without it the
  // target is left untouched.
  void commit();

 private:
  std::filesystem::path m_target;
  std::ostringstream m_stream;
};

// Replaces `target` with `text`, atomically; throws output_failed.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

// The whole content of a file; throws recoil::Error(bad_input) naming it and why.
std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& path);

// Replaces `target` with a copy of `source`, atomically.
void copy_file_atomically(const std::filesystem::path& source, const std::filesystem::path& target);

}  // namespace recoil::cli
