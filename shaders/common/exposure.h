// Physical camera exposure (EV100 and the saturation-based sensitivity) and automatic exposure.
#ifndef WP_EXPOSURE_H
#define WP_EXPOSURE_H

#include "sampling.h"

WP_BEGIN

// Radiance is read as photometric: the Rec. 709 luminance of an RGB radiance (luminance() in
// sampling.h) is its luminance in cd/m^2, so a camera set by f-number, shutter and ISO sees a
// scene as a real one would (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR").

// Saturation-based sensitivity (ISO 12232): a sensor of ISO S saturates at the photometric
// exposure H = 78 / S lux s, and the lens passes H = q t L / N^2 of a scene luminance L, where
// q = 0.65 stands for lens transmission, vignetting and the angle to the axis.
#define WP_EXPOSURE_Q 0.65f
#define WP_EXPOSURE_SATURATION 78.0f

// Automatic exposure after Reinhard et al. 2002, "Photographic tone reproduction for digital
// images", eqs. 1-2: the log-average luminance is mapped to the key value, middle grey. The
// epsilon keeps black pixels (log 0) from dragging the average to zero; 1e-4 cd/m^2 is far
// below anything a display shows.
#define WP_AUTO_EXPOSURE_KEY 0.18f
#define WP_AUTO_EXPOSURE_EPSILON 1e-4f

// EV100 = log2(100 N^2 / (t S)) for f-number N, shutter time t in seconds and ISO S (all > 0):
// the exposure value the same setting would have at ISO 100.
WP_FN float ev100FromSettings(float fNumber, float shutterTime, float iso) {
  return log2(100.0f * fNumber * fNumber / (shutterTime * iso));
}

// Lmax = 78 N^2 / (S q t): the luminance (cd/m^2) that just saturates the sensor, which the
// display maps to 1.0 (equate H = q t Lmax / N^2 with 78 / S).
WP_FN float maxLuminanceFromSettings(float fNumber, float shutterTime, float iso) {
  return WP_EXPOSURE_SATURATION * fNumber * fNumber / (iso * WP_EXPOSURE_Q * shutterTime);
}

// Lmax from EV100 alone: N^2 / t = 2^EV100 S / 100, so Lmax = 78 / (100 q) 2^EV100, which is
// 1.2 * 2^EV100 and the same for every (N, t, S) with that EV100.
WP_FN float maxLuminanceFromEv100(float ev100) {
  return WP_EXPOSURE_SATURATION / (100.0f * WP_EXPOSURE_Q) * exp2(ev100);
}

// The inverse of maxLuminanceFromEv100, to report the EV100 an automatic exposure chose.
WP_FN float ev100FromMaxLuminance(float maxLuminance) {
  return log2(maxLuminance * (100.0f * WP_EXPOSURE_Q) / WP_EXPOSURE_SATURATION);
}

// The factor that linear radiance is multiplied by before the tone curve: 1 / Lmax.
WP_FN float exposureScale(float maxLuminance) { return 1.0f / maxLuminance; }

// One pixel's term of the log-average luminance: log(L + epsilon). Sum it over the image and
// divide by the pixel count to get the mean that autoExposureScale takes. Negative or NaN
// luminance (which radiance should never have) counts as black.
WP_FN float logLuminance(vec3 radiance) {
  float l = luminance(radiance);
  return log((l > 0.0f ? l : 0.0f) + WP_AUTO_EXPOSURE_EPSILON);
}

// Exposure scale key / exp(mean log(L + epsilon)) for the mean of logLuminance over the image:
// it maps the log-average luminance to middle grey. Its Lmax is 1 / the result.
WP_FN float autoExposureScale(float meanLogLuminance) { return WP_AUTO_EXPOSURE_KEY / exp(meanLogLuminance); }

WP_END

#endif
