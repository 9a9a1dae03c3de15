// The HDR sky on the host: an equirectangular radiance map read from .hdr or .exr, and the
// luminance distribution that shaders/common/environment.h samples it by.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace wp {

// A lat-long sky in the frame of shaders/common/environment.h (top row: +y; middle column:
// -z), with the arrays its sampler reads: upload them as they are.
struct EnvironmentMap {
  uint32_t width = 0, height = 0;
  // width * height texels, top row first: linear rgb radiance (cd/m^2 by luminance), w = 0.
  std::vector<glm::vec4> radiance;
  // height + 1 floats rising from 0 to exactly 1: the probability of rows [0, i).
  std::vector<float> marginalCdf;
  // height rows of width + 1 floats, each rising from 0 to exactly 1: the probability of
  // columns [0, i) given the row. A row that is black throughout is uniform (never chosen).
  std::vector<float> conditionalCdf;
  // The luminance integrated over the sphere, sum of luminance * texel solid angle
  // (cd/m^2 sr, intensity 1): what the sky's power is made of.
  double luminanceIntegral = 0;
};

// A sky from `radiance` (width * height texels, top row first, linear rgb). The sampling
// density of a texel is proportional to its luminance times sin(theta) at its row's centre,
// as environment.h expects; a black map samples (nearly) uniformly over the sphere. Requires width, height >= 1 and
// radiance.size() == width * height; throws wp::Error for a texel that is not finite or is
// above kMaxRadiance (scene_limits.h). Negative
// components, which radiance cannot have but filtered or compressed images sometimes hold,
// are clamped to 0.
EnvironmentMap makeEnvironmentMap(uint32_t width, uint32_t height, const std::vector<glm::vec3>& radiance);

// Reads an equirectangular sky from a Radiance .hdr (readHdr) or an OpenEXR .exr (R, G, B
// through readExr) file and builds its distribution. Throws wp::Error, one line naming the
// file and what to do, when it is missing, of another format, unreadable, or holds a texel
// that is not finite or above kMaxRadiance (scene_limits.h).
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path);

// Throws wp::Error, naming --sky-intensity, when `intensity` times the sky's brightest texel
// is above kMaxRadiance.
void checkSkyIntensity(const EnvironmentMap& map, double intensity);

// The power the sky sends into a scene inside a sphere of radius `sceneRadius`: the flux
// through that sphere's cross-section, pi r^2 * intensity * luminanceIntegral (the estimate
// pbrt-v4's ImageInfiniteLight uses to choose between lights by power). Note that the
// triangle light table (gpu_scene.cpp) weighs by luminance * area, which is power / pi.
double environmentPower(const EnvironmentMap& map, double intensity, double sceneRadius);

}  // namespace wp
