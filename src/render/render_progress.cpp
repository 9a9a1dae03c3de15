// Formatting of the progress line.
#include "render/render_progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wp {

namespace {

std::string duration(double seconds) {
  const long long s = std::llround(std::max(seconds, 0.0));
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof(text), "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  } else {
    std::snprintf(text, sizeof(text), "%lld:%02lld", s / 60, s % 60);
  }
  return text;
}

// This process's samples per second so far (0 before anything was measured).
double rateOf(const RenderProgress& p) { return p.seconds > 0.0 ? double(p.pathsThisRun) / p.seconds : 0.0; }

// The seconds the samples left take at that rate (infinite before it was measured).
double secondsAtRate(const RenderProgress& p) {
  const double rate = rateOf(p);
  return rate > 0.0 ? double(p.pathsTotal - p.pathsDone) / rate : HUGE_VAL;
}

// Whether the time limit ends the render before its samples do, at the rate so far.
bool timeLimitComesFirst(const RenderProgress& p) {
  return p.timeLimitSeconds > 0.0 && p.seconds + secondsAtRate(p) > p.timeLimitSeconds;
}

}  // namespace

double progressFraction(const RenderProgress& p) {
  if (timeLimitComesFirst(p)) return std::min(p.seconds / p.timeLimitSeconds, 1.0);
  return p.pathsTotal > 0 ? double(p.pathsDone) / double(p.pathsTotal) : 1.0;
}

std::string progressLine(const RenderProgress& p) {
  const double pixels = double(std::max<uint64_t>(p.pixels, 1));
  const double fraction = progressFraction(p);
  const double rate = rateOf(p);
  char text[160];
  if (timeLimitComesFirst(p)) {
    std::snprintf(text, sizeof(text), "%.1f spp (%.1f%% of the time limit), %.2f M samples/s, %s spent, %s left",
                  double(p.pathsDone) / pixels, fraction * 100.0, rate * 1e-6, duration(p.seconds).c_str(),
                  duration(p.timeLimitSeconds - p.seconds).c_str());
    return text;
  }
  const std::string left = rate > 0.0 ? duration(secondsAtRate(p)) : "?";
  std::snprintf(text, sizeof(text), "%.1f of %.0f spp (%.1f%%), %.2f M samples/s, %s spent, %s left",
                double(p.pathsDone) / pixels, double(p.pathsTotal) / pixels, fraction * 100.0, rate * 1e-6,
                duration(p.seconds).c_str(), left.c_str());
  return text;
}

}  // namespace wp
