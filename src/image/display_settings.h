// How linear radiance becomes a display image: exposure, tone curve, transfer function.
#pragma once

#include <cstdint>

namespace wp {

// How linear radiance becomes a display image (PNG): scaled by `exposure` (1 / the luminance
// that maps to white), tone mapped (WP_TONE_* in tone_curves.h), then encoded with the sRGB
// transfer function or a plain gamma (WP_TRANSFER_*). EXR output ignores it: it stays linear.
struct DisplaySettings {
  float exposure = 1.0f;
  uint32_t toneMapper = 0;  // WP_TONE_CLAMP
  uint32_t transfer = 0;    // WP_TRANSFER_SRGB
  float gamma = 2.2f;       // used with WP_TRANSFER_GAMMA
};

}  // namespace wp
