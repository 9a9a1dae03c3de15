// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <chrono>

namespace wp {

class ProgressBar {
public:
  ProgressBar();
  // Redraws the bar for fraction in [0, 1]; cheap to call often.
  void update(double fraction);
  // Clears the bar's line.
  void finish();

private:
  bool enabled_;
  int lastPermille_ = -1;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace wp
