#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>
#include <nlohmann/json.hpp>

namespace recoil::cli {
namespace {
double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}
}  // namespace

std::string format_rate(double per_second, const std::string& unit) {
  char text[64];
  if (per_second >= 1.0) std::snprintf(text, sizeof text, "%.1f/s", per_second);
  else if (per_second > 0.0) std::snprintf(text, sizeof text, "%.1f s/%s", 1.0 / per_second, unit.c_str());
  else std::snprintf(text, sizeof text, "-");
  return text;
}

Progress::Progress(const GlobalOptions& global, std::string label, int total)
    : m_label(std::move(label)),
      m_total(total),
      m_bar(!global.quiet && !global.log_json && ::isatty(STDERR_FILENO)),
      m_json(global.log_json),
      m_start(std::chrono::steady_clock::now()),
      m_last_draw(m_start - std::chrono::seconds(1)) {}

Progress::~Progress() { finish(); }

void Progress::update(int done) {
  const auto now = std::chrono::steady_clock::now();
  m_done = done;
  if (m_first_done < 0) {
    m_first_done = done;
    m_first_time = now;
  }
  if (m_json) {
    const double elapsed = seconds_between(m_first_time, now);
    const double rate = elapsed > 0 && done > m_first_done ? (done - m_first_done) / elapsed : 0.0;
    const nlohmann::json line = {{"command", m_label}, {"event", "progress"}, {"done", done}, {"total", m_total},
                                 {"rate", rate},        {"eta_s", rate > 0 ? nlohmann::json((m_total - done) / rate)
                                                                             : nlohmann::json(nullptr)}};
    std::fprintf(stderr, "%s\n", line.dump().c_str());
    return;
  }
  // Redraw at most 10 times a second, and always for the last item.
  if (!m_bar || (done < m_total && now - m_last_draw < std::chrono::milliseconds(100))) return;
  draw("");
}

bool Progress::due() const {
  if (!m_bar && !m_json) return false;
  // A log keeps every line, so it gets fewer than the bar that redraws in place.
  const auto interval = m_json ? std::chrono::milliseconds(1000) : std::chrono::milliseconds(100);
  return std::chrono::steady_clock::now() - m_last_draw >= interval;
}

void Progress::working(const std::string& detail) {
  if (!due()) return;
  if (m_json) {
    m_last_draw = std::chrono::steady_clock::now();
    const nlohmann::json line = {{"command", m_label}, {"event", "working"}, {"done", m_done}, {"detail", detail}};
    std::fprintf(stderr, "%s\n", line.dump().c_str());
    return;
  }
  draw(detail);
}

void Progress::stage(const std::string& what) {
  if (m_json) {
    const nlohmann::json line = {{"command", m_label}, {"event", "stage"}, {"stage", what}};
    std::fprintf(stderr, "%s\n", line.dump().c_str());
  } else if (m_bar) {
    draw(what);
  }
}

void Progress::draw(const std::string& detail) {
  const auto now = std::chrono::steady_clock::now();
  m_last_draw = now;
  constexpr int kWidth = 30;
  const int filled = m_total > 0 ? kWidth * m_done / m_total : kWidth;
  std::string bar(static_cast<size_t>(filled), '#');
  bar.append(static_cast<size_t>(kWidth - filled), '-');
  const double since_first = m_first_done < 0 ? 0.0 : seconds_between(m_first_time, now);
  const double rate = since_first > 0 && m_done > m_first_done ? (m_done - m_first_done) / since_first : 0.0;
  char eta[32] = "ETA -";
  if (rate > 0) std::snprintf(eta, sizeof eta, "ETA %.0fs", (m_total - m_done) / rate);
  std::fprintf(stderr, "\r%s [%s] %d/%d  %s  %s%s%s \x1b[K", m_label.c_str(), bar.c_str(), m_done, m_total,
               format_rate(rate, "frame").c_str(), eta, detail.empty() ? "" : "  ", detail.c_str());
  std::fflush(stderr);
}

void Progress::finish() {
  if (m_finished) return;
  m_finished = true;
  if (m_bar) {
    std::fprintf(stderr, "\r\x1b[K");
    std::fflush(stderr);
  }
}

}  // namespace recoil::cli
