// Tone curves for exposed linear radiance, the display transfer functions and 8-bit packing.
#ifndef WP_TONE_CURVES_H
#define WP_TONE_CURVES_H

#include "tonemap.h"

WP_BEGIN

// Tone mappers (the order is the CLI's; values are stable for settings files and buffers).
#define WP_TONE_CLAMP 0u     // none: clip at 1
#define WP_TONE_REINHARD 1u  // x / (1 + x)
#define WP_TONE_HABLE 2u     // Uncharted 2 filmic
#define WP_TONE_ACES 3u      // Narkowicz's fit of ACES

// Display transfer functions applied after the tone curve.
#define WP_TRANSFER_SRGB 0u   // IEC 61966-2-1 piecewise curve (linearToSrgb)
#define WP_TRANSFER_GAMMA 1u  // plain power law c^(1 / gamma)
#define WP_DEFAULT_GAMMA 2.2f

// Hable's Uncharted 2 curve as published in Hable 2010, "Filmic Tonemapping Operators"
// (filmicworlds.com): shoulder strength A, linear strength B, linear angle C, toe strength D,
// toe numerator E, toe denominator F, and the linear white point W that is mapped to 1.
#define WP_HABLE_A 0.15f
#define WP_HABLE_B 0.50f
#define WP_HABLE_C 0.10f
#define WP_HABLE_D 0.20f
#define WP_HABLE_E 0.02f
#define WP_HABLE_F 0.30f
#define WP_HABLE_WHITE 11.2f

// Every curve below takes exposed radiance x >= 0 of one channel (1.0 is the luminance that
// saturates the sensor) and returns a display value in [0, 1]. Channels are mapped
// independently, as all three published curves were; bright saturated colours therefore
// drift towards white, as on film.

// Reinhard et al. 2002, "Photographic tone reproduction for digital images", eq. 3.
WP_FN float toneReinhard(float x) { return x / (1.0f + x); }

// The unnormalised Uncharted 2 curve: a rational toe and shoulder (Hable 2010).
WP_FN float hableCurve(float x) {
  return (x * (WP_HABLE_A * x + WP_HABLE_C * WP_HABLE_B) + WP_HABLE_D * WP_HABLE_E) /
             (x * (WP_HABLE_A * x + WP_HABLE_B) + WP_HABLE_D * WP_HABLE_F) -
         WP_HABLE_E / WP_HABLE_F;
}

// Hable's curve scaled so the white point W maps to 1, and 1 above W (evaluated at min(x, W),
// which also keeps huge x from overflowing to inf / inf). Hable's sample code multiplied the
// input by an "exposure bias" of 2; here exposure belongs to the camera, so the curve is taken
// as published without it.
WP_FN float toneHable(float x) { return hableCurve(min(x, WP_HABLE_WHITE)) / hableCurve(WP_HABLE_WHITE); }

// Narkowicz 2016, "ACES Filmic Tone Mapping Curve" (knarkowicz.wordpress.com): a rational fit
// of the ACES reference rendering and output transforms' tone scale, without ACES's gamut
// mapping. It passes 1 at x = 7.24 on its way to 2.51 / 2.43, so it is clipped at 1; x is
// capped at 100, where it is long clipped, so that huge x cannot overflow to inf / inf.
WP_FN float toneAces(float x) {
  float c = min(x, 100.0f);
  return min(c * (2.51f * c + 0.03f) / (c * (2.43f * c + 0.59f) + 0.14f), 1.0f);
}

// The curve `mapper` (WP_TONE_*) of one channel; negative and NaN input is black, because the
// curves are defined for x >= 0 only and a NaN must not reach the display, and +inf is taken
// as the largest float, so it comes out white.
WP_FN float toneMapChannel(float x, uint mapper) {
  float c = x > 0.0f ? min(x, WP_FLT_MAX) : 0.0f;
  if (mapper == WP_TONE_REINHARD) return toneReinhard(c);
  if (mapper == WP_TONE_HABLE) return toneHable(c);
  if (mapper == WP_TONE_ACES) return toneAces(c);
  return min(c, 1.0f);
}

WP_FN vec3 toneMap(vec3 exposed, uint mapper) {
  return make_vec3(toneMapChannel(exposed.x, mapper), toneMapChannel(exposed.y, mapper),
                   toneMapChannel(exposed.z, mapper));
}

// A plain power-law display encoding for c in [0, 1] (gamma > 0), for displays or tools that
// expect it instead of the sRGB curve.
WP_FN float linearToGamma(float c, float gamma) { return pow(c, 1.0f / gamma); }

// Encodes tone-mapped c in [0, 1] with `transfer` (WP_TRANSFER_*); `gamma` is used by
// WP_TRANSFER_GAMMA only.
WP_FN vec3 encodeTransfer(vec3 c, uint transfer, float gamma) {
  if (transfer == WP_TRANSFER_GAMMA) {
    return make_vec3(linearToGamma(c.x, gamma), linearToGamma(c.y, gamma), linearToGamma(c.z, gamma));
  }
  return linearToSrgb3(c);
}

// The whole display path of one pixel: radiance times `exposure` (exposureScale or
// autoExposureScale in exposure.h), the tone curve, the transfer function, then 8 bits per
// channel rounded to nearest and packed like packSrgba8 (R in the lowest byte, A = 255).
// With WP_TONE_CLAMP and WP_TRANSFER_SRGB it equals packSrgba8(radiance * exposure).
WP_FN uint packDisplay(vec3 radiance, float exposure, uint mapper, uint transfer, float gamma) {
  vec3 display = encodeTransfer(toneMap(radiance * exposure, mapper), transfer, gamma);
  uint r = toUint(saturateOrZero(display.x) * 255.0f + 0.5f);
  uint g = toUint(saturateOrZero(display.y) * 255.0f + 0.5f);
  uint b = toUint(saturateOrZero(display.z) * 255.0f + 0.5f);
  return r | (g << 8u) | (b << 16u) | (255u << 24u);
}

WP_END

#endif
