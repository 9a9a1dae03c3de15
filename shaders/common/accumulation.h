// What one path adds to its pixel's running sums (the accumulate stage of both backends).
#ifndef WP_ACCUMULATION_H
#define WP_ACCUMULATION_H

#include "portable.h"

WP_BEGIN

// The largest radiance one path adds to its pixel's sums (per channel): a pixel sums up to
// 2^20 samples (--spp's limit) and their squares in floats, and 2^20 * (1e16)^2 stays below
// WP_FLT_MAX. Inputs are bounded far below it (src/scene/scene_limits.h), but a lamp a
// hair's breadth from a surface (I / r^2) is not; an overflow would make the pixel's variance,
// then its mean, NaN.
#define WP_MAX_SAMPLE_RADIANCE 1e16f

// What a path's radiance `l` adds to its pixel's sums: clamped to WP_MAX_SAMPLE_RADIANCE, and
// nothing of a channel that is not a number (infinity times a zero cosine, say).
WP_FN vec3 accumulableRadiance(vec3 l) {
  const float m = WP_MAX_SAMPLE_RADIANCE;
  return make_vec3(notANumber(l.x) ? 0.0f : clamp(l.x, -m, m), notANumber(l.y) ? 0.0f : clamp(l.y, -m, m),
                   notANumber(l.z) ? 0.0f : clamp(l.z, -m, m));
}

WP_END

#endif
