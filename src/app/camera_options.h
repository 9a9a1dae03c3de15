// Camera, exposure and tone-mapping flags of `wavepath render`, and how they resolve.
#pragma once

#include <optional>
#include <string>

#include "image/image_io.h"
#include "scene/scene.h"

namespace CLI {
class App;
}

namespace wp {

struct GpuScene;

// What the flags set; unset values fall back to the glTF camera's extras, then defaults.
struct CameraFlags {
  std::optional<float> fStop;
  std::optional<float> focusDistance;  // metres
  std::optional<float> focalLengthMm;
  std::optional<uint32_t> blades;
  std::optional<float> shutter;  // seconds
  std::optional<float> iso;
  std::optional<float> ev100;
  bool autoExposure = false;
  std::string toneMapper = "clamp";
  std::optional<float> gamma;  // a plain gamma instead of the sRGB transfer function
};

void addCameraFlags(CLI::App& command, CameraFlags& flags);

// Puts the flags into `camera`, and focuses on what the image centre sees when the lens has
// an aperture but no focus distance. Throws wp::Error when the focus lies inside the lens.
void applyCameraFlags(const CameraFlags& flags, Camera& camera, const GpuScene& scene);

// Exposure and tone mapping for the PNG: --ev100; else a physical exposure from f-number,
// shutter and ISO when either of the last two is set (defaults f/16, 1/100 s, ISO 100, the
// "sunny 16" rule); else --auto-exposure from the image; else 1, which shows radiance 1 as
// white.
DisplaySettings displaySettings(const CameraFlags& flags, const CameraOptics& optics, const RadianceImage& image);

}  // namespace wp
