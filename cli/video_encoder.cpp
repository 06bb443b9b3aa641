#include "cli/video_encoder.h"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

}  // namespace

fs::path find_ffmpeg() {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / "ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

void require_ffmpeg() {
  if (find_ffmpeg().empty())
    throw bad_input("--video needs ffmpeg, which is not installed; install it with: scripts/install-deps.sh --video");
}

VideoEncoder::VideoEncoder(const fs::path& path, int width, int height, double fps)
    : m_path(path), m_width(width), m_height(height) {
  const fs::path ffmpeg = find_ffmpeg();
  if (ffmpeg.empty()) require_ffmpeg();
  // A dead ffmpeg must surface as a write error, not kill us with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  std::ostringstream command;
  command << shell_quote(ffmpeg.string()) << " -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgba -s "
          << width << "x" << height << " -framerate " << fps
          << " -i - -c:v libx264 -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' "
          << shell_quote(path.string());
  m_pipe = ::popen(command.str().c_str(), "w");
  if (!m_pipe) throw output_error("cannot start ffmpeg for " + path.string());
}

VideoEncoder::~VideoEncoder() {
  if (m_pipe) ::pclose(m_pipe);
}

void VideoEncoder::add(const render::Image& image) {
  if (!m_pipe) throw output_error("video " + m_path.string() + ": already finished");
  if (image.width != m_width || image.height != m_height)
    throw output_error("video " + m_path.string() + ": frame size changed");
  if (std::fwrite(image.rgba.data(), 1, image.rgba.size(), m_pipe) != image.rgba.size())
    throw output_error("video " + m_path.string() + ": ffmpeg stopped accepting frames");
}

void VideoEncoder::finish() {
  if (!m_pipe) return;
  const int status = ::pclose(m_pipe);
  m_pipe = nullptr;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw output_error("ffmpeg failed to write " + m_path.string());
}

}  // namespace recoil::cli
