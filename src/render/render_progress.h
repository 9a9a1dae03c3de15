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
  double timeLimitSeconds = 0.0;  // --time-limit: the render ends once `seconds` reach it (0: none)
};

// How far the render is, from 0 to 1: of its samples, or of its time limit where that would
// end it first.
double progressFraction(const RenderProgress& progress);

// "27.3 of 64 spp (42.7%), 0.85 M samples/s, 0:12 spent, 0:17 left": samples per pixel done
// of the render's, the rate of this process, its time, and the time left at that rate
// ("?" before anything was measured). Times are m:ss, or h:mm:ss from an hour. Where a time
// limit would end the render before its samples, the time is what it is a share of:
// "27.3 spp (20.0% of the time limit), 0.85 M samples/s, 0:12 spent, 0:48 left".
std::string progressLine(const RenderProgress& progress);

}  // namespace wp
