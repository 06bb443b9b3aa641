#pragma once
// Files no reader should read: a FIFO (opening it blocks until a writer comes)
// and a symlink to /dev/zero (endless), for the readers' refusal tests.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"

namespace recoil::test {

// Makes a FIFO at `path` (fails the test when it cannot).
inline void make_fifo(const std::filesystem::path& path) {
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0) << "mkfifo " << path;
}

// Makes `path` a symlink to /dev/zero.
inline void link_to_dev_zero(const std::filesystem::path& path) {
  std::filesystem::create_symlink("/dev/zero", path);
}

// The message of the bad_input error `read` throws, within 1 s. A reader that
// blocks on the FIFO `fifo` is released by opening it for writing (so the
// test fails instead of hanging); one that throws nothing or another kind fails too.
inline std::string bad_input_within_a_second(const std::function<void()>& read, const std::filesystem::path& fifo = {}) {
  auto done = std::async(std::launch::async, [&]() -> std::string {
    try {
      read();
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::bad_input) return "wrong kind: " + std::string(e.what());
      return e.what();
    }
    return "no error";
  });
  if (done.wait_for(std::chrono::seconds(1)) == std::future_status::timeout) {
    ADD_FAILURE() << "the reader blocked for 1 s";
    if (!fifo.empty()) {
      const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) ::close(fd);
    }
  }
  const std::string message = done.get();
  EXPECT_NE(message, "no error");
  EXPECT_EQ(message.rfind("wrong kind: ", 0), std::string::npos) << message;
  return message;
}

}  // namespace recoil::test
