// What one path adds to its pixel's running sums (the accumulate stage of both backends).
#ifndef WP_ACCUMULATION_H
#define WP_ACCUMULATION_H

#include "portable.h"

WP_BEGIN

// The accumulation buffer holds these layers of vec4 per pixel, one layer after another:
#define WP_ACCUMULATION_LAYERS 4u
#define WP_LAYER_RADIANCE 0u          // rgb: the sum of the samples' radiance
#define WP_LAYER_RADIANCE_SQUARES 1u  // rgb: the sum of its squares
#define WP_LAYER_ALBEDO_DEPTH 2u      // rgb: the sum of the albedo pass, w: of the depth pass
#define WP_LAYER_NORMAL 3u            // xyz: the sum of the normal pass

// Where `layer` of pixel `pixel` (of `pixels`) lies in the accumulation buffer.
WP_FN uint accumulationIndex(uint layer, uint pixel, uint pixels) { return layer * pixels + pixel; }

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
