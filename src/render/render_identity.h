// What decides the samples of a pixel, so that renders made apart (a checkpoint and the
// render that resumes it, the parts of a frame split over machines) can be checked to be
// pieces of one render.
#pragma once

#include <string>

#include "render/settings.h"
#include "shaders/common/layout.h"

namespace wp {

struct GpuScene;

struct RenderIdentity {
  // 16 hex digits of XXH3-64 over what the stages are given: the packed scene (geometry,
  // materials, lights, textures, sky) and the render parameters (camera, sky settings, image
  // size, seed, integrator switches), but not the region, the sample range or the paths
  // in flight, which change which samples are traced but not what any sample is.
  std::string sceneHash;
  // The same settings as flags, to say which one differs: "--width 512 --height 512 ...".
  std::string settings;
};

RenderIdentity renderIdentity(const GpuScene& scene, const gpu::RenderParams& params, const RenderSettings& settings);

// Empty when `there` and `here` are the same render; else what differs, as a phrase:
// "--max-depth is 8 there, 4 here", or "the scene, camera or sky differs" when only the
// hash does.
std::string identityDifference(const RenderIdentity& there, const RenderIdentity& here);

}  // namespace wp
