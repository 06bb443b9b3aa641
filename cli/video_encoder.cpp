#include "cli/video_encoder.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "cli/output_dir.h"
#include "cli/shell_quote.h"
#include "core/atomic_write.h"
#include "core/error.h"
#include "core/lower_case.h"

namespace recoil::cli {
namespace fs = std::filesystem;

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

namespace {

struct VideoFormat {
  const char* extension;
  const char* muxer;        // ffmpeg's -f
  const char* codec;        // what follows the input in the ffmpeg command
  const char* alpha_codec;  // the same for frames with transparency; null: the codec holds none
};

// Even sizes for the 4:2:0 codecs; a GIF keeps its size and gets one palette
// for the clip, with one entry kept for "transparent" when the frames have it.
constexpr const char* kH264 = "-c:v libx264 -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2'";
const VideoFormat kFormats[] = {
    {".mp4", "mp4", kH264, nullptr},
    {".mov", "mov", kH264, nullptr},
    {".mkv", "matroska", kH264, nullptr},
    {".webm", "webm", "-c:v libvpx-vp9 -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2'",
     "-c:v libvpx-vp9 -pix_fmt yuva420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2:color=black@0'"},
    {".gif", "gif", "-filter_complex 'split[a][b];[a]palettegen=reserve_transparent=0[p];[b][p]paletteuse'",
     "-filter_complex 'split[a][b];[a]palettegen=reserve_transparent=1[p];[b][p]paletteuse=alpha_threshold=128'"},
};

const VideoFormat* format_of(const fs::path& path) {
  const std::string extension = lower_case(path.extension().string());
  for (const VideoFormat& f : kFormats)
    if (extension == f.extension) return &f;
  return nullptr;
}

}  // namespace

void require_video(const fs::path& path, bool transparent) {
  const VideoFormat* format = format_of(path);
  if (!format)
    throw bad_input("--video: cannot write '" + path.filename().string() +
                    "'; name the file .mp4, .mov, .mkv, .webm or .gif");
  // The video is encoded beside the path and renamed over it, which would
  // turn a device or a FIFO into a plain file.
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw bad_input("--video " + path.string() + ": not a regular file (a folder, device or FIFO); name a file");
  if (transparent && !format->alpha_codec)
    throw bad_input("--video: '" + path.filename().string() +
                    "' (H.264) holds no transparency; name it .webm or .gif, or give --background a colour");
  if (find_ffmpeg().empty())
    throw bad_input("--video needs ffmpeg, which is not installed; install it with: apt-get install ffmpeg");
}

VideoEncoder::VideoEncoder(const fs::path& path, int width, int height, double fps, bool transparent)
    : m_path(path), m_partial(path.string() + ".partial"), m_log(path.string() + ".log"), m_width(width),
      m_height(height) {
  require_video(path, transparent);
  const VideoFormat& format = *format_of(path);
  // ffmpeg opens the file only once frames arrive: whether it can be written
  // is found out here, before anything is simulated, as for the other outputs.
  try {
    if (path.has_parent_path()) ensure_output_dir(path.parent_path());
  } catch (const Error& e) {
    throw output_error("--video " + path.string() + ": " + e.what());
  }
  errno = 0;
  if (std::FILE* probe = std::fopen(m_partial.c_str(), "wb")) {
    std::fclose(probe);
  } else {
    throw output_error("--video " + path.string() + ": cannot write " + m_partial.string() + ": " + errno_message(errno));
  }
  // A dead ffmpeg must surface as a write error, not kill us with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  std::ostringstream command;
  command << shell_quote(find_ffmpeg().string()) << " -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgba -s "
          << width << "x" << height << " -framerate " << fps << " -i - " << (transparent ? format.alpha_codec : format.codec) << " -f " << format.muxer
          << " " << shell_quote(m_partial.string()) << " 2> " << shell_quote(m_log.string());
  m_pipe = ::popen(command.str().c_str(), "w");
  if (!m_pipe) {
    std::error_code ec;
    fs::remove(m_partial, ec);
    throw output_error("cannot start ffmpeg for " + path.string());
  }
}

VideoEncoder::~VideoEncoder() {
  std::error_code ec;
  if (m_pipe) {
    ::pclose(m_pipe);
    fs::remove(m_partial, ec);
  }
  fs::remove(m_log, ec);
}

// " (the last line ffmpeg printed)", its own error, or empty when it printed nothing.
std::string VideoEncoder::ffmpeg_said() const {
  std::ifstream log(m_log);
  std::string line, last;
  while (std::getline(log, line))
    if (!line.empty()) last = line;
  return last.empty() ? "" : " (" + last + ")";
}

void VideoEncoder::add(const render::Image& image) {
  if (!m_pipe) throw output_error("video " + m_path.string() + ": already finished");
  if (image.width != m_width || image.height != m_height)
    throw output_error("video " + m_path.string() + ": frame size changed");
  if (std::fwrite(image.rgba.data(), 1, image.rgba.size(), m_pipe) != image.rgba.size())
    throw output_error("video " + m_path.string() + ": ffmpeg stopped accepting frames" + ffmpeg_said());
}

void VideoEncoder::finish() {
  if (!m_pipe) return;
  const int status = ::pclose(m_pipe);
  m_pipe = nullptr;
  std::error_code ec;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    fs::remove(m_partial, ec);
    throw output_error("ffmpeg failed to write " + m_path.string() + ffmpeg_said());
  }
  fs::rename(m_partial, m_path, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(m_partial, ec);
    throw output_error("cannot write " + m_path.string() + ": " + why);
  }
}

}  // namespace recoil::cli
