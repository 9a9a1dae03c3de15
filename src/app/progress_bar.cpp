// Progress bar on stderr.
#include "app/progress_bar.h"

#include <unistd.h>

#include <cstdio>

namespace wp {

ProgressBar::ProgressBar() : enabled_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(double fraction) {
  int permille = int(fraction * 1000.0);
  if (!enabled_ || permille == lastPermille_) {
    return;
  }
  lastPermille_ = permille;
  constexpr int kWidth = 40;
  int filled = int(fraction * kWidth);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) {
    bar[i] = i < filled ? '#' : '.';
  }
  bar[kWidth] = '\0';
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r[%s] %5.1f%%  %.1f s, %.1f s left ", bar, fraction * 100.0, elapsed, remaining);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (enabled_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
}

}  // namespace wp
