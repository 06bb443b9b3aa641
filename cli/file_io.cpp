#include "cli/file_io.h"

#include <cerrno>
#include <cstdint>
#include <fstream>

#include "core/atomic_write.h"
#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;

AtomicFile::AtomicFile(fs::path target) : m_target(std::move(target)) {}

void AtomicFile::commit() {
  const std::string text = m_stream.str();
  replace_file(m_target, text.data(), text.size());
}

void write_text_atomically(const fs::path& target, const std::string& text) {
  replace_file(target, text.data(), text.size());
}

std::vector<std::uint8_t> read_file_bytes(const fs::path& path) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad_input("cannot read " + path.string() + ": " + errno_message(errno));
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw bad_input("cannot read " + path.string() + ": " + errno_message(errno));
  return bytes;
}

void copy_file_atomically(const fs::path& source, const fs::path& target) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(source);
  replace_file(target, bytes.data(), bytes.size());
}

}  // namespace recoil::cli
