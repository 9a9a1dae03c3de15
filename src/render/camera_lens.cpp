// Thin-lens set-up and autofocus.
#include "render/camera_lens.h"

#include <cmath>
#include <limits>

#include "bvh/device_buffers.h"
#include "bvh/gpu_scene.h"
#include "scene/scene.h"
#include "shaders/common/traverse.h"

namespace wp {

gpu::ThinLens makeLens(const Camera& camera, uint32_t width, uint32_t height) {
  if (camera.orthographic) {
    const float halfHeight = camera.orthographicHalfHeight;
    return gpu::makeOrthographicLens(camera.position, camera.forward, camera.up,
                                     glm::vec2(halfHeight * float(width) / float(height), halfHeight));
  }
  const CameraOptics& o = camera.optics;
  glm::vec2 filmHalf = gpu::filmHalfExtent(o.sensorSize, float(width) / float(height));
  bool pinhole = !(o.fNumber > 0.0f);
  float focus = pinhole ? std::numeric_limits<float>::max() : o.focusDistance;
  // Image distance at which the film sees yfov; the thin-lens equation 1/f = 1/D + 1/V then
  // gives the focal length that puts the film there for focus distance D.
  float filmDistance = gpu::focalLengthForFieldOfView(camera.yfov, filmHalf.y);
  float focalLength = o.focalLength > 0.0f ? o.focalLength
                      : pinhole            ? filmDistance
                                           : filmDistance * focus / (filmDistance + focus);
  float fNumber = pinhole ? std::numeric_limits<float>::infinity() : o.fNumber;
  gpu::ThinLens lens =
      gpu::makeThinLens(camera.position, camera.forward, camera.up, filmHalf, focalLength, fNumber, focus);
  return o.blades >= 3 ? gpu::withBladedAperture(lens, o.blades, o.bladeRotation) : lens;
}

float autofocusDistance(const Camera& camera, const GpuScene& scene) {
  gpu::Hit hit = gpu::traceClosest(sceneBuffers(scene), scene.topLevelEntry(), uint32_t(scene.planes.size()),
                                   camera.position, camera.forward, WP_FLT_MAX, 0.0f);
  return hit.instance == WP_INVALID ? 10.0f : hit.t;
}

}  // namespace wp
