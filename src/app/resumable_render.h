// A render that can be interrupted and resumed: periodic checkpoints, SIGINT/SIGTERM, the
// progress line.
#pragma once

#include <string>

#include "render/checkpoint.h"
#include "render/wavefront.h"

namespace wp {

struct CheckpointOptions {
  std::string path;           // --checkpoint FILE; empty: no checkpoints
  double everySeconds = 60.0;  // --checkpoint-every: seconds of rendering between checkpoints (0: every pass)
  bool resume = false;        // --resume: go on from `path`
};

// Throws a flag error before anything is rendered when the checkpoint flags cannot work:
// --resume without the file, a file in the way without --resume (it could be hours of
// someone's work), or the checkpoint and the image `output` being one file.
void checkCheckpointFlags(const CheckpointOptions& options, const std::string& output);

struct RenderOutcome {
  RenderStats stats;
  int interruptedBy = 0;  // the signal that stopped the render before its end, or 0
};

// Renders what is left of `renderer`'s samples with the progress line on stderr. With a
// checkpoint path: first, with resume, restores the checkpoint (throws a one-line wp::Error,
// touching nothing, when it is not of this render: `here` says what this render is), then
// writes one every everySeconds and when a signal stops the render. Stops at the end of the
// pass in flight when interruptSignal() says so. With a time limit (seconds above 0), the
// render ends with the sample every pixel is in once that much time has passed
// (WavefrontRenderer::render).
RenderOutcome renderResumably(WavefrontRenderer& renderer, const Checkpoint& here, const CheckpointOptions& options,
                              double timeLimitSeconds);

}  // namespace wp
