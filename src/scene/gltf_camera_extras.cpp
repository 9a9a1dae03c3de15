// Physical camera settings from a glTF camera's extras.
#include "scene/gltf_camera_extras.h"

#include <cmath>
#include <limits>
#include <string>

namespace wp::gltf {

namespace {

// extras.wavepath.<key> as a number in (low, high], or `fallback` when absent.
double readNumber(const Context& ctx, const tinygltf::Value& extras, const std::string& where, const char* key,
                  double fallback, double low, double high) {
  if (!extras.Has(key)) return fallback;
  const tinygltf::Value& value = extras.Get(key);
  const double number = value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
  if (!(number > low && number <= high)) {
    fail(ctx, where,
         std::string("extras.wavepath.") + key + " must be a number above " + std::to_string(low) +
             (std::isfinite(high) ? " and at most " + std::to_string(high) : std::string()) + "; fix the camera");
  }
  return number;
}

}  // namespace

CameraOptics readCameraOptics(const Context& ctx, size_t index) {
  const tinygltf::Camera& camera = ctx.model.cameras[index];
  CameraOptics optics;
  if (!camera.extras.Has("wavepath")) return optics;
  const std::string where = describe("camera", index, camera.name);
  const tinygltf::Value& extras = camera.extras.Get("wavepath");
  if (!extras.IsObject()) fail(ctx, where, "extras.wavepath must be an object; fix the camera");
  const double inf = std::numeric_limits<double>::infinity();
  optics.fNumber = static_cast<float>(readNumber(ctx, extras, where, "fStop", 0.0, 0.0, 1024.0));
  optics.focusDistance = static_cast<float>(readNumber(ctx, extras, where, "focusDistance", 0.0, 0.0, inf));
  optics.focalLength = static_cast<float>(readNumber(ctx, extras, where, "focalLength", 0.0, 0.0, 10000.0) * 1e-3);
  optics.blades = static_cast<uint32_t>(readNumber(ctx, extras, where, "blades", 0.0, -1.0, 64.0));
  optics.bladeRotation = static_cast<float>(readNumber(ctx, extras, where, "bladeRotation", 0.0, -inf, inf));
  optics.sensorSize.x = static_cast<float>(readNumber(ctx, extras, where, "sensorWidth", 36.0, 0.0, 1000.0) * 1e-3);
  optics.sensorSize.y = static_cast<float>(readNumber(ctx, extras, where, "sensorHeight", 24.0, 0.0, 1000.0) * 1e-3);
  optics.shutter = static_cast<float>(readNumber(ctx, extras, where, "shutter", 0.0, 0.0, 3600.0));
  optics.iso = static_cast<float>(readNumber(ctx, extras, where, "iso", 0.0, 0.0, 1e7));
  return optics;
}

}  // namespace wp::gltf
