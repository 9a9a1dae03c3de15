// The progress line on stderr: a bar redrawn in place on a terminal, else (a batch job's
// log) a line a minute.
#pragma once

#include <chrono>

#include "render/render_progress.h"

namespace wp {

class ProgressBar {
public:
  ProgressBar();
  // Shows `progress` (render/render_progress.h); cheap to call often.
  void update(const RenderProgress& progress);
  // Clears the bar's line.
  void finish();

private:
  bool terminal_;
  std::chrono::steady_clock::time_point lastDrawn_;
  bool drawn_ = false;
};

}  // namespace wp
