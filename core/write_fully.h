#pragma once
// Writing a whole buffer to a file descriptor, which one write() may not do.
#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace recoil {

// Writes the `size` bytes at `data` to `fd`, again after a signal interrupts;
// returns 0, or the errno of the failure (ENOSPC when a write takes no bytes,
// as a full disk does).
inline int write_fully(int fd, const void* data, size_t size) {
  const char* bytes = static_cast<const char*>(data);
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, bytes + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    done += static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace recoil
