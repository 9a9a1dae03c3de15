// The progress line of a render: samples done, samples per second and the time left.
#pragma once

#include <cstdint>
#include <string>

namespace wp {

struct RenderProgress {
  uint64_t pixels = 0;        // pixels rendered (the region's)
  uint64_t pathsDone = 0;     // samples of this render traced so far, a checkpoint's included
  uint64_t pathsTotal = 0;    // samples of the whole render
  uint64_t pathsThisRun = 0;  // of pathsDone, those this process traced (the rate's numerator)
  double seconds = 0.0;       // this process's rendering time
};

// "27.3 of 64 spp (42.7%), 0.85 M samples/s, 0:12 spent, 0:17 left": samples per pixel done
// of the render's, the rate of this process, its time, and the time left at that rate
// ("?" before anything was measured). Times are m:ss, or h:mm:ss from an hour.
std::string progressLine(const RenderProgress& progress);

}  // namespace wp
