#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>
#include <nlohmann/json.hpp>

namespace recoil::cli {

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
  const double elapsed = std::chrono::duration<double>(now - m_start).count();
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double eta = rate > 0 ? (m_total - done) / rate : 0.0;
  if (m_json) {
    const nlohmann::json line = {{"command", m_label}, {"event", "progress"}, {"done", done}, {"total", m_total},
                                 {"rate", rate},        {"eta_s", eta}};
    std::fprintf(stderr, "%s\n", line.dump().c_str());
    return;
  }
  // Redraw at most 10 times a second, and always for the last item.
  if (!m_bar || (done < m_total && now - m_last_draw < std::chrono::milliseconds(100))) return;
  m_last_draw = now;
  constexpr int kWidth = 30;
  const int filled = m_total > 0 ? kWidth * done / m_total : kWidth;
  std::string bar(static_cast<size_t>(filled), '#');
  bar.append(static_cast<size_t>(kWidth - filled), '-');
  std::fprintf(stderr, "\r%s [%s] %d/%d  %.1f/s  ETA %.0fs \x1b[K", m_label.c_str(), bar.c_str(), done, m_total, rate,
               eta);
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
