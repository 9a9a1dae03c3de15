// Display encoding of linear radiance: the sRGB transfer function and 8-bit RGBA packing.
#ifndef WP_TONEMAP_H
#define WP_TONEMAP_H

#include "portable.h"

WP_BEGIN

// Exposure and the tone curves that come before this encoding are in exposure.h and tone_curves.h.

// The sRGB opto-electronic transfer function (IEC 61966-2-1), exact piecewise form, for c
// in [0, 1].
WP_FN float linearToSrgb(float c) {
  return c < 0.0031308f ? 12.92f * c : 1.055f * pow(c, 1.0f / 2.4f) - 0.055f;
}

WP_FN vec3 linearToSrgb3(vec3 c) { return make_vec3(linearToSrgb(c.x), linearToSrgb(c.y), linearToSrgb(c.z)); }

// Clamps to [0, 1] and sends NaN to 0: written with a comparison because clamp() of NaN is
// undefined in GLSL and OpenCL, and a NaN pixel must not turn into garbage bytes.
WP_FN float saturateOrZero(float c) { return c > 0.0f ? min(c, 1.0f) : 0.0f; }

// 8-bit sRGB of linear radiance, rounded to nearest, packed with R in the lowest byte, then
// G, B and A = 255 (the byte order of an RGBA8 texel on a little-endian host).
WP_FN uint packSrgba8(vec3 linear) {
  uint r = toUint(linearToSrgb(saturateOrZero(linear.x)) * 255.0f + 0.5f);
  uint g = toUint(linearToSrgb(saturateOrZero(linear.y)) * 255.0f + 0.5f);
  uint b = toUint(linearToSrgb(saturateOrZero(linear.z)) * 255.0f + 0.5f);
  return r | (g << 8u) | (b << 16u) | (255u << 24u);
}

WP_END

#endif
