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

}  // namespace

std::string progressLine(const RenderProgress& p) {
  const double pixels = double(std::max<uint64_t>(p.pixels, 1));
  const double fraction = p.pathsTotal > 0 ? double(p.pathsDone) / double(p.pathsTotal) : 1.0;
  const double rate = p.seconds > 0.0 ? double(p.pathsThisRun) / p.seconds : 0.0;
  const std::string left = rate > 0.0 ? duration(double(p.pathsTotal - p.pathsDone) / rate) : "?";
  char text[160];
  std::snprintf(text, sizeof(text), "%.1f of %.0f spp (%.1f%%), %.2f M samples/s, %s spent, %s left",
                double(p.pathsDone) / pixels, double(p.pathsTotal) / pixels, fraction * 100.0, rate * 1e-6,
                duration(p.seconds).c_str(), left.c_str());
  return text;
}

}  // namespace wp
