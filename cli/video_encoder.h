#pragma once
// `--video FILE.mp4`: frames piped as raw RGBA to an ffmpeg child process
// (H.264, yuv420p). ffmpeg is an optional dependency: find_ffmpeg() lets a
// command fail at once, before simulating, when it is missing.
#include <cstdio>
#include <filesystem>
#include <string>

#include "render/image.h"

namespace recoil::cli {

// The ffmpeg executable on PATH, or empty.
std::filesystem::path find_ffmpeg();

// Throws bad_input with the install command when ffmpeg is missing.
void require_ffmpeg();

class VideoEncoder {
 public:
  // Starts ffmpeg writing `path` at `fps` frames per second of width x height.
  VideoEncoder(const std::filesystem::path& path, int width, int height, double fps);
  ~VideoEncoder();  // closes the pipe (errors ignored; call finish() to see them)
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Throws output_error when ffmpeg has gone away.
  void add(const render::Image& image);
  // Waits for ffmpeg; throws output_error when it failed.
  void finish();

 private:
  std::FILE* m_pipe = nullptr;
  std::filesystem::path m_path;
  int m_width, m_height;
};

}  // namespace recoil::cli
