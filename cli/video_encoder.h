#pragma once
// `--video FILE`: frames piped as raw RGBA to an ffmpeg child process, the
// container and codec chosen by the file's extension (.mp4, .mov, .mkv:
// H.264; .webm: VP9; .gif: a palette made for the whole clip), with alpha
// where the frames have it and the codec can hold it. ffmpeg is an
// optional dependency: require_video() lets a command fail at once, before
// simulating, when it is missing or the extension is unknown. The video is
// written to FILE.partial and renamed into place once ffmpeg has finished, so
// a failed or interrupted run leaves no video rather than a cut one. Its
// messages go to FILE.log, whose last line a failure quotes; the log is
// removed with the encoder.
#include <cstdio>
#include <filesystem>
#include <string>

#include "render/image.h"

namespace recoil::cli {

// The ffmpeg executable on PATH, or empty.
std::filesystem::path find_ffmpeg();

// Throws bad_input naming --video for an extension it cannot write, or one
// that holds no transparency for `transparent` frames (H.264), and with the
// install command when ffmpeg is missing.
void require_video(const std::filesystem::path& path, bool transparent);

class VideoEncoder {
 public:
  // Starts ffmpeg writing `path` at `fps` frames per second of width x height;
  // `transparent` frames keep their alpha (WebM's VP9, GIF's transparent entry).
  VideoEncoder(const std::filesystem::path& path, int width, int height, double fps, bool transparent);
  ~VideoEncoder();  // without finish(): stops ffmpeg and removes the partial file
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Throws output_error when ffmpeg has gone away.
  void add(const render::Image& image);
  // Waits for ffmpeg and renames the video into place; throws output_error when it failed.
  void finish();

 private:
  std::string ffmpeg_said() const;

  std::FILE* m_pipe = nullptr;
  std::filesystem::path m_path, m_partial;
  std::filesystem::path m_log;  // ffmpeg's stderr, for the message when it fails
  int m_width, m_height;
};

}  // namespace recoil::cli
