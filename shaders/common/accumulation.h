// What one path adds to its pixel's running sums (the accumulate stage of both backends).
#ifndef WP_ACCUMULATION_H
#define WP_ACCUMULATION_H

#include "portable.h"

WP_BEGIN

// The accumulation buffer holds these layers of vec4 per pixel, one layer after another:
#define WP_ACCUMULATION_LAYERS 4u
#define WP_LAYER_RADIANCE 0u          // rgb: the sum of the samples' radiance, w: their count
#define WP_LAYER_RADIANCE_SQUARES 1u  // rgb: the sum of its squares, w: 1 once the pixel stopped
#define WP_LAYER_ALBEDO_DEPTH 2u      // rgb: the sum of the albedo pass, w: of the depth pass
#define WP_LAYER_NORMAL 3u            // xyz: the sum of the normal pass

// Where `layer` of pixel `pixel` (of `pixels`) lies in the accumulation buffer.
WP_FN uint accumulationIndex(uint layer, uint pixel, uint pixels) { return layer * pixels + pixel; }

// The samples a pixel's WP_LAYER_RADIANCE entry holds (a float counts exactly up to 2^24,
// past --spp's limit of 2^20).
WP_FN float sampleCountOf(vec4 radianceSum) { return radianceSum.w; }
WP_FN vec4 withSampleCounted(vec4 radianceSum) {
  radianceSum.w += 1.0f;
  return radianceSum;
}
// Whether adaptive sampling stopped the pixel, from its WP_LAYER_RADIANCE_SQUARES entry.
WP_FN bool pixelStopped(vec4 radianceSquares) { return radianceSquares.w != 0.0f; }
WP_FN vec4 withPixelStopped(vec4 radianceSquares) {
  radianceSquares.w = 1.0f;
  return radianceSquares;
}

// Adaptive sampling, as Cycles does it: from the minimum sample count on, every
// WP_ADAPTIVE_INTERVAL samples, a pixel whose estimated relative error is below the threshold
// receives no more samples. The error is the standard error of the pixel's mean (the root of
// the channels' mean sample variance over n) over its mean radiance (the channels' mean),
// the radiance floored at WP_ADAPTIVE_DARK so that an almost black pixel is judged by an
// absolute error rather than sampled for ever. A pixel's decision depends on its own samples
// alone, in sample order, so it does not depend on how passes cut the render.
#define WP_ADAPTIVE_INTERVAL 8u
#define WP_ADAPTIVE_DARK 1e-3f

WP_FN float relativeErrorOf(vec4 radianceSum, vec4 radianceSquares) {
  float n = sampleCountOf(radianceSum);
  vec3 mean = make_vec3(radianceSum.x, radianceSum.y, radianceSum.z) / n;
  vec3 meanSquare = make_vec3(radianceSquares.x, radianceSquares.y, radianceSquares.z) / n;
  vec3 variance = max(meanSquare - mean * mean, make_vec3(0.0f, 0.0f, 0.0f)) * (n / max(n - 1.0f, 1.0f));
  float standardError = sqrt((variance.x + variance.y + variance.z) / (3.0f * n));
  return standardError / max((mean.x + mean.y + mean.z) / 3.0f, WP_ADAPTIVE_DARK);
}

// Whether a pixel whose sums are these stops sampling now (threshold 0: adaptive sampling off).
WP_FN bool stopsSampling(vec4 radianceSum, vec4 radianceSquares, float threshold, uint minSamples) {
  uint n = toUint(sampleCountOf(radianceSum));
  if (!(threshold > 0.0f) || n < minSamples || (n - minSamples) % WP_ADAPTIVE_INTERVAL != 0u) {
    return false;
  }
  return relativeErrorOf(radianceSum, radianceSquares) < threshold;
}

// The sums of the albedo and depth passes in a WP_LAYER_ALBEDO_DEPTH entry.
WP_FN vec3 albedoSumOf(vec4 albedoDepth) { return make_vec3(albedoDepth.x, albedoDepth.y, albedoDepth.z); }
WP_FN float depthSumOf(vec4 albedoDepth) { return albedoDepth.w; }

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
