// A reader run in a child process: its answer and its errors come back as
// they were, and its death (a crash, an abort, an endless loop, an exit without an answer) is
// a bad_input error naming the file and the reader, with the caller unharmed.
#include "sim/geometry/isolated_reader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <stdexcept>

#include "core/error.h"
#include "sim/geometry/mesh_import.h"
#include "tests/test_support.h"

namespace recoil::sim {
namespace {

// The error `read` ends in, run through read_in_child for the file "in.obj".
Error error_of(const std::function<std::string()>& read, int cpu_seconds = 5) {
  try {
    read_in_child(read, "in.obj", "the test reader", cpu_seconds);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return Error(ErrorKind::internal, "");
}

TEST(IsolatedReader, AnswerComesBackByteForByte) {
  std::string bytes(300000, '\0');  // more than a pipe holds at once
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7919 % 251);
  EXPECT_EQ(read_in_child([&] { return bytes; }, "in.obj", "the test reader", 5), bytes);
  EXPECT_EQ(read_in_child([] { return std::string(); }, "in.obj", "the test reader", 5), "");
}

TEST(IsolatedReader, ErrorsKeepTheirKindAndMessage) {
  const Error input = error_of([]() -> std::string { throw bad_input("in.obj: line 3: bad face"); });
  EXPECT_EQ(input.kind(), ErrorKind::bad_input);
  EXPECT_STREQ(input.what(), "in.obj: line 3: bad face");
  const Error output = error_of([]() -> std::string { throw output_error("disk full"); });
  EXPECT_EQ(output.kind(), ErrorKind::output_failed);
  EXPECT_STREQ(output.what(), "disk full");
  // Whatever else a third-party reader throws is the file's fault.
  const Error other = error_of([]() -> std::string { throw std::runtime_error("unexpected token"); });
  EXPECT_EQ(other.kind(), ErrorKind::bad_input);
  EXPECT_STREQ(other.what(), "unexpected token");
}

TEST(IsolatedReader, CrashOrSilentExitIsABadFile) {
  for (const int sig : {SIGSEGV, SIGABRT}) {
    const Error crash = error_of([sig]() -> std::string {
      std::signal(sig, SIG_DFL);
      std::raise(sig);
      return "unreachable";
    });
    EXPECT_EQ(crash.kind(), ErrorKind::bad_input);
    EXPECT_NE(std::string(crash.what()).find("in.obj: the test reader crashed reading this file ("),
              std::string::npos)
        << crash.what();
  }
  const Error stuck = error_of([]() -> std::string {
    std::atomic<unsigned> spins{0};
    for (;;) spins.fetch_add(1, std::memory_order_relaxed);
  }, 1);
  EXPECT_EQ(stuck.kind(), ErrorKind::bad_input);
  EXPECT_STREQ(stuck.what(), "in.obj: the test reader did not finish reading this file in 1 s of CPU time");
  const Error silent = error_of([]() -> std::string { ::_exit(0); });
  EXPECT_EQ(silent.kind(), ErrorKind::bad_input);
  EXPECT_STREQ(silent.what(), "in.obj: the test reader stopped reading this file without an answer");
}

TEST(IsolatedReader, ChildMemoryIsNotTheCallers) {
  int value = 1;
  read_in_child([&] { value = 2; return std::string(); }, "in.obj", "the test reader", 5);
  EXPECT_EQ(value, 1);
}

// import_surface reads through a child: a crash while assimp reads is the file's bad luck, not the caller's.
TEST(IsolatedReader, MeshImportReadsInAChild) {
  set_reader_child_setup([] {
    std::signal(SIGSEGV, SIG_DFL);
    std::raise(SIGSEGV);
  });
  const std::string bunny = test::source_path("assets/meshes/bunny.obj").string();
  try {
    import_surface(bunny);
    ADD_FAILURE() << "read although its reader crashed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    EXPECT_EQ(std::string(e.what()).rfind(bunny + ": the mesh reader (assimp) crashed reading this file", 0), 0u)
        << e.what();
  }
  set_reader_child_setup(nullptr);
  EXPECT_GT(import_surface(bunny).num_triangles(), 1000);
}

}  // namespace
}  // namespace recoil::sim
