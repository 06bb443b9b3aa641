#pragma once
// Atomic file output (compare's HTML report and --update copies, run's
// scene.json and run.json, drop's --save-scene): write beside the target,
// then rename, so a reader or a crash never leaves a half-written file behind
//.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace recoil::cli {

class AtomicFile {
 public:
  // Opens `target`.tmp-PID-N for writing; throws recoil::Error(output_failed).
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();  // removes the temporary file unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return m_stream; }
  // Flushes, closes and renames over the target; throws output_failed.
  void commit();

 private:
  std::filesystem::path m_target;
  std::filesystem::path m_temporary;
  std::ofstream m_stream;
  bool m_committed = false;
};

// Replaces `target` with `text`, atomically; throws output_failed.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

// The whole content of a file; throws recoil::Error(bad_input) naming it.
std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& path);

// Replaces `target` with a copy of `source`, atomically.
void copy_file_atomically(const std::filesystem::path& source, const std::filesystem::path& target);

}  // namespace recoil::cli
