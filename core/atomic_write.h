#pragma once
// Replacing a file whole: the bytes go to TARGET.tmp-PID-N beside it, are
// flushed to disk (fsync) and only then renamed over TARGET, so a crash, a
// kill or a full disk leaves the old file or the new one, never a mixture
// (at worst a stray temporary, which `run --resume` removes). Shared by the
// PNG frames and the CLI's JSON and HTML outputs. A target that exists and is
// not a regular file (a device, a FIFO, /dev/stdout) is written through
// instead: renaming over it would replace the device node with a file.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "core/error.h"
#include "core/write_fully.h"

namespace recoil {

// The text of a saved errno; 0 (a failure that set none) never reads "Success".
inline std::string errno_message(int saved_errno) {
  return saved_errno != 0 ? std::generic_category().message(saved_errno) : "unknown cause (no errno)";
}

// Writes `size` bytes at `data` into the existing non-regular file `target`;
// throws Error(output_failed) naming it and the system's reason.
inline void write_through(const std::filesystem::path& target, const void* data, size_t size) {
  const auto fail = [&](const char* step, int saved_errno) {
    return output_error("cannot write " + target.string() + " (" + step + "): " + errno_message(saved_errno));
  };
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw fail("opening", errno);
  if (const int saved = write_fully(fd, data, size); saved != 0) {
    ::close(fd);
    throw fail("writing", saved);
  }
  if (::close(fd) != 0) throw fail("closing", errno);
}

// Writes `size` bytes at `data` as `target`, atomically and durably; throws
// Error(output_failed) naming `target` and the system's reason.
inline void replace_file(const std::filesystem::path& target, const void* data, size_t size) {
  struct stat existing {};
  if (::stat(target.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode) && !S_ISDIR(existing.st_mode)) {
    write_through(target, data, size);
    return;
  }
  static std::atomic<unsigned> counter{0};
  const std::string temporary =
      target.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const auto fail = [&](const char* step, int saved_errno, bool remove) {
    if (remove) ::unlink(temporary.c_str());
    return output_error("cannot write " + target.string() + " (" + step + "): " + errno_message(saved_errno));
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw fail("creating the temporary file", errno, false);
  if (const int saved = write_fully(fd, data, size); saved != 0) {
    ::close(fd);
    throw fail("writing", saved, true);
  }
  if (::fsync(fd) != 0) {
    const int saved = errno;
    ::close(fd);
    throw fail("flushing to disk", saved, true);
  }
  if (::close(fd) != 0) throw fail("closing", errno, true);
  if (::rename(temporary.c_str(), target.c_str()) != 0) throw fail("renaming into place", errno, true);
}

}  // namespace recoil
