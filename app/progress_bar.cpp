#include "progress_bar.h"

#include <unistd.h>

#include <cstdio>

namespace obscura::app {

std::string format_seconds(double s) {
  char buffer[32];
  if (s < 10)
    std::snprintf(buffer, sizeof buffer, "%.2fs", s);
  else if (s < 60)
    std::snprintf(buffer, sizeof buffer, "%.1fs", s);
  else
    std::snprintf(buffer, sizeof buffer, "%dm%02ds", int(s) / 60, int(s) % 60);
  return buffer;
}

ProgressBar::ProgressBar(std::string label, bool quiet)
    : label_(std::move(label)),
      quiet_(quiet),
      terminal_(isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(int done, int total) {
  if (quiet_ || total <= 0) return;
  double fraction = double(done) / total;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    constexpr int kWidth = 30;
    int filled = int(fraction * kWidth);
    std::string bar(filled, '#');
    bar.append(kWidth - filled, '.');
    std::string eta = done > 0 ? format_seconds(elapsed / fraction - elapsed) : "?";
    std::fprintf(stderr, "\r%s [%s] %3d%%  elapsed %s  ETA %s ", label_.c_str(), bar.c_str(),
                 int(fraction * 100), format_seconds(elapsed).c_str(), eta.c_str());
    std::fflush(stderr);
    drawn_ = true;
  } else {
    int decile = int(fraction * 10);
    if (decile > last_decile_) {
      last_decile_ = decile;
      std::fprintf(stderr, "%s: %d%% (elapsed %s)\n", label_.c_str(), decile * 10,
                   format_seconds(elapsed).c_str());
    }
  }
}

void ProgressBar::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace obscura::app
