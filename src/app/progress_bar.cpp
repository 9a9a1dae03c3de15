// Progress on stderr: redrawn in place at most ten times a second on a terminal, printed as
// a plain line once a minute otherwise, so a batch job's log shows it without filling up.
#include "app/progress_bar.h"

#include <unistd.h>

#include <cstdio>

namespace wp {

ProgressBar::ProgressBar() : terminal_(isatty(STDERR_FILENO) != 0) {}

void ProgressBar::update(const RenderProgress& progress) {
  const auto now = std::chrono::steady_clock::now();
  const auto interval = terminal_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(60000);
  if (drawn_ ? now - lastDrawn_ < interval : !terminal_ && progress.seconds < 60.0) return;
  drawn_ = true;
  lastDrawn_ = now;
  const std::string line = progressLine(progress);
  if (!terminal_) {
    std::fprintf(stderr, "wavepath: %s\n", line.c_str());
    return;
  }
  constexpr int kWidth = 30;
  const double fraction = progressFraction(progress);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < int(fraction * kWidth) ? '#' : '.';
  bar[kWidth] = '\0';
  std::fprintf(stderr, "\r\033[K[%s] %s", bar, line.c_str());
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (terminal_ && drawn_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
}

}  // namespace wp
