#pragma once
// FrameWriter: encodes PNG frames on worker threads while the caller renders
// the next frame. The queue is bounded so a fast renderer cannot pile up
// unbounded memory behind a slow disk: submit() blocks when it is full.
// Each file is written atomically (render/png.h). The first error raised by a
// worker is rethrown by the next submit() or by finish().
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "render/png.h"

namespace recoil::render {

// The writer every command uses: one encoder thread per spare core
// (llvmpipe draws on the others) and room for two frames per encoder waiting.
struct FrameWriterSize {
  int threads = 1;
  int capacity = 3;
};
FrameWriterSize default_frame_writer_size();

class FrameWriter {
 public:
  // threads: encoder threads (>= 1); capacity: frames waiting at most.
  FrameWriter(PngOptions options, int threads, int capacity);
  ~FrameWriter();  // finishes pending work, swallowing errors (call finish() to see them)
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  void submit(std::filesystem::path path, Image image);

  // Waits until every submitted frame is on disk; rethrows the first error.
  void finish();

  // Milliseconds spent encoding and writing, summed over all frames so far.
  double encode_ms() const;

 private:
  struct Job {
    std::filesystem::path path;
    Image image;
  };
  void worker_loop();
  void rethrow_if_failed();

  PngOptions m_options;
  int m_capacity;
  mutable std::mutex m_mutex;
  std::condition_variable m_job_ready;
  std::condition_variable m_space_or_idle;
  std::deque<Job> m_queue;
  int m_busy = 0;
  bool m_stopping = false;
  std::exception_ptr m_error;
  double m_encode_ms = 0.0;
  std::vector<std::thread> m_threads;
};

}  // namespace recoil::render
