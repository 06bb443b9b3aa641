#include "render/frame_writer.h"

#include <algorithm>

#include <chrono>

#include "core/check.h"

namespace recoil::render {

FrameWriterSize default_frame_writer_size() {
  const int threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1);
  return {threads, 2 * threads + 1};
}

FrameWriter::FrameWriter(PngOptions options, int threads, int capacity) : m_options(options), m_capacity(capacity) {
  RECOIL_CHECK(threads >= 1 && capacity >= 1, "threads " << threads << ", capacity " << capacity);
  for (int i = 0; i < threads; ++i) m_threads.emplace_back([this] { worker_loop(); });
}

FrameWriter::~FrameWriter() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stopping = true;
  }
  m_job_ready.notify_all();
  for (std::thread& thread : m_threads) thread.join();
}

void FrameWriter::rethrow_if_failed() {
  if (m_error) std::rethrow_exception(m_error);
}

void FrameWriter::submit(std::filesystem::path path, Image image) {
  std::unique_lock<std::mutex> lock(m_mutex);
  m_space_or_idle.wait(lock, [&] { return static_cast<int>(m_queue.size()) < m_capacity || m_error; });
  rethrow_if_failed();
  m_queue.push_back({std::move(path), std::move(image)});
  m_job_ready.notify_one();
}

void FrameWriter::finish() {
  std::unique_lock<std::mutex> lock(m_mutex);
  m_space_or_idle.wait(lock, [&] { return (m_queue.empty() && m_busy == 0) || m_error; });
  rethrow_if_failed();
}

double FrameWriter::encode_ms() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_encode_ms;
}

void FrameWriter::worker_loop() {
  std::unique_lock<std::mutex> lock(m_mutex);
  while (true) {
    // Pending frames are still written when stopping, unless a write failed.
    m_job_ready.wait(lock, [&] { return !m_queue.empty() || m_stopping; });
    if (m_queue.empty() || m_error) return;
    Job job = std::move(m_queue.front());
    m_queue.pop_front();
    ++m_busy;
    m_space_or_idle.notify_all();
    lock.unlock();
    const auto start = std::chrono::steady_clock::now();
    std::exception_ptr error;
    try {
      write_png(job.path, job.image, m_options);
    } catch (...) {
      error = std::current_exception();
    }
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    lock.lock();
    --m_busy;
    m_encode_ms += elapsed.count();
    if (error && !m_error) m_error = error;
    m_space_or_idle.notify_all();
  }
}

}  // namespace recoil::render
