// A camera for a scene whose file has none.
#include "render/automatic_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "bvh/device_buffers.h"
#include "scene/scene_camera.h"
#include "shaders/common/lights.h"
#include "shaders/common/traverse.h"

namespace wp {

namespace {

constexpr int kProbeRays = 256;
constexpr double kEnclosedShare = 0.95;
constexpr size_t kMostLightsTried = 1024;  // spread over the light table
constexpr float kBackToTheWall = 0.8f;     // how far towards the wall behind the camera stands

// The distance to the first surface along the ray, or infinity.
float freeDistance(const GpuScene& s, glm::vec3 origin, glm::vec3 direction) {
  const gpu::Hit hit = gpu::traceClosest(sceneBuffers(s), s.topLevelEntry(), uint32_t(s.planes.size()), origin,
                                         direction, WP_FLT_MAX, 0.0f);
  return hit.instance == WP_INVALID ? std::numeric_limits<float>::infinity() : hit.t;
}

// Whether nothing lies between `origin` and `light` (a triangle's centroid, a lamp's place, or
// towards where a directional light comes from).
bool lightVisible(const GpuScene& s, glm::vec3 origin, const gpu::GpuLight& light) {
  glm::vec3 direction;
  float distance = WP_FLT_MAX;
  switch (gpu::lightKind(light)) {
    case WP_LIGHT_TRIANGLE: {
      const glm::vec3 centroid =
          gpu::triangleLightVertex(light) + (gpu::triangleLightEdge1(light) + gpu::triangleLightEdge2(light)) / 3.0f;
      direction = centroid - origin;
      distance = 0.999f * glm::length(direction);
      break;
    }
    case WP_LIGHT_DIRECTIONAL: direction = -gpu::punctualDirection(light, 0.0f); break;
    default:
      direction = gpu::punctualPosition(light, 0.0f) - origin;
      distance = 0.999f * glm::length(direction);
  }
  if (!(glm::dot(direction, direction) > 0.0f)) return true;
  return !gpu::traceAny(sceneBuffers(s), s.topLevelEntry(), uint32_t(s.planes.size()), origin,
                        glm::normalize(direction), distance, 0.0f);
}

bool anyLightVisible(const GpuScene& s, glm::vec3 origin) {
  const size_t step = std::max<size_t>(1, s.lights.size() / kMostLightsTried);
  for (size_t i = 0; i < s.lights.size(); i += step) {
    if (lightVisible(s, origin, s.lights[i])) return true;
  }
  return false;
}

// Directions spread evenly over the sphere (a Fibonacci lattice).
glm::vec3 sphereDirection(int i, int n) {
  const double z = 1.0 - (2.0 * i + 1.0) / n;
  const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
  const double r = std::sqrt(1.0 - z * z);
  return glm::vec3(float(r * std::cos(phi)), float(z), float(r * std::sin(phi)));
}

std::string vectorText(glm::vec3 v) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.2g, %.2g, %.2g)", v.x, v.y, v.z);
  return text;
}

}  // namespace

AutomaticCamera chooseAutomaticCamera(const Scene& scene, const GpuScene& packed, const std::string& file) {
  const glm::vec3 centre = 0.5f * (packed.boundsMin + packed.boundsMax);
  const float radius = 0.5f * glm::length(packed.boundsMax - packed.boundsMin);
  int hits = 0;
  for (int i = 0; i < kProbeRays; ++i) {
    hits += std::isfinite(freeDistance(packed, centre, sphereDirection(i, kProbeRays))) ? 1 : 0;
  }
  const bool enclosed = double(hits) >= kEnclosedShare * kProbeRays;
  const bool litFromWithin = enclosed && scene.sky.width == 0 && anyLightVisible(packed, centre);

  AutomaticCamera result;
  if (!enclosed || !litFromWithin) {
    result.camera = frameScene(scene);
    result.note = file + " has no camera: looking at the whole scene from +z (the front of a glTF asset) with a 45 "
                         "degree vertical field of view";
    result.note += "; add a camera to the file, or pick one with --camera";
    return result;
  }
  // Inside: look along the horizontal direction with the most free space, from near the wall
  // behind, so the view takes in as much of the room as it can.
  glm::vec3 best(0.0f, 0.0f, -1.0f);
  float bestFree = -1.0f;
  for (int k = 0; k < 8; ++k) {
    const float angle = float(k) * std::numbers::pi_v<float> / 4.0f;
    const glm::vec3 d(std::sin(angle), 0.0f, -std::cos(angle));
    const float free = std::min(freeDistance(packed, centre, d), 2.0f * radius);
    if (free > bestFree + 1e-6f * radius) {
      best = d;
      bestFree = free;
    }
  }
  const float behind = std::min(freeDistance(packed, centre, -best), 2.0f * radius);
  result.inside = true;
  result.camera.position = centre - best * (kBackToTheWall * behind);
  result.camera.forward = best;
  result.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
  result.camera.yfov = kInteriorYfov;
  result.note = file + " has no camera, and its centre is enclosed and lit from within (a room?): looking from inside "
                       "along " + vectorText(best) + " with a 65 degree vertical field of view; add a camera to the "
                       "file, or pick one with --camera";
  return result;
}

}  // namespace wp
