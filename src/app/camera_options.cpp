// Camera, exposure and tone-mapping flags.
#include "app/camera_options.h"

#include <map>

#include <CLI/CLI.hpp>

#include "app/number_checks.h"
#include "core/error.h"
#include "render/camera_lens.h"
#include "shaders/common/exposure.h"
#include "shaders/common/tone_curves.h"

namespace wp {

void addCameraFlags(CLI::App& cmd, CameraFlags& f) {
  cmd.add_option("--fstop", f.fStop, "Aperture f-number; sets depth of field (default: a pinhole, all sharp)")
      ->check(CLI::Range(0.5f, 1024.0f));
  cmd.add_option("--focus-distance", f.focusDistance,
                 "Focus distance in scene units (default: what the image centre sees)")
      ->check(moreThanZero());
  cmd.add_option("--focal-length", f.focalLengthMm,
                 "Focal length in mm on the 36x24 mm sensor (default: from the glTF field of view)")
      ->check(CLI::Range(1.0f, 10000.0f));
  cmd.add_option("--aperture-blades", f.blades, "Aperture blades (3 or more); default: a round aperture")
      ->check(CLI::Range(3u, 64u));
  cmd.add_option("--shutter", f.shutter, "Shutter time in seconds, for a physical exposure")
      ->check(CLI::Range(1e-6f, 3600.0f));
  cmd.add_option("--iso", f.iso, "Sensor sensitivity (ISO), for a physical exposure")->check(CLI::Range(1.0f, 1e7f));
  cmd.add_option("--ev100", f.ev100, "Exposure value at ISO 100; overrides f-stop, shutter and ISO")
      ->check(CLI::Range(-20.0f, 30.0f));
  cmd.add_flag("--auto-exposure", f.autoExposure, "Expose the image's log-average luminance as middle grey");
  cmd.add_option("--tonemap", f.toneMapper, "PNG tone curve: clamp, reinhard, filmic (Hable) or aces")
      ->check(CLI::IsMember({"clamp", "reinhard", "filmic", "aces"}));
  cmd.add_option("--gamma", f.gamma, "Encode the PNG with this plain gamma instead of the sRGB curve")
      ->check(CLI::Range(0.1f, 10.0f));
}

void applyCameraFlags(const CameraFlags& f, Camera& camera, const GpuScene& scene) {
  CameraOptics& o = camera.optics;
  if (f.fStop) o.fNumber = *f.fStop;
  if (f.focusDistance) o.focusDistance = *f.focusDistance;
  if (f.focalLengthMm) o.focalLength = *f.focalLengthMm * 1e-3f;
  if (f.blades) o.blades = *f.blades;
  if (f.shutter) o.shutter = *f.shutter;
  if (f.iso) o.iso = *f.iso;
  if (o.fNumber > 0.0f && o.focusDistance == 0.0f) {
    o.focusDistance = autofocusDistance(camera, scene);
  }
  if (o.fNumber > 0.0f && o.focalLength > 0.0f && !(o.focusDistance > o.focalLength)) {
    throw Error("focus distance " + std::to_string(o.focusDistance) + " is not beyond the focal length " +
                std::to_string(o.focalLength) + " (scene units); raise --focus-distance or lower --focal-length");
  }
}

DisplaySettings displaySettings(const CameraFlags& f, const CameraOptics& o, const RadianceImage& image) {
  static const std::map<std::string, uint32_t> mappers = {
      {"clamp", WP_TONE_CLAMP}, {"reinhard", WP_TONE_REINHARD}, {"filmic", WP_TONE_HABLE}, {"aces", WP_TONE_ACES}};
  DisplaySettings d;
  d.toneMapper = mappers.at(f.toneMapper);
  if (f.gamma) {
    d.transfer = WP_TRANSFER_GAMMA;
    d.gamma = *f.gamma;
  }
  if (f.ev100) {
    d.exposure = gpu::exposureScale(gpu::maxLuminanceFromEv100(*f.ev100));
  } else if (o.shutter > 0.0f || o.iso > 0.0f) {
    float fNumber = o.fNumber > 0.0f ? o.fNumber : 16.0f;
    float shutter = o.shutter > 0.0f ? o.shutter : 0.01f;
    float iso = o.iso > 0.0f ? o.iso : 100.0f;
    d.exposure = gpu::exposureScale(gpu::maxLuminanceFromSettings(fNumber, shutter, iso));
  } else if (f.autoExposure) {
    d.exposure = autoExposure(image);
  }
  return d;
}

}  // namespace wp
