// The identity of a render: a hash of the scene and parameters, and the settings as flags.
#include "render/render_identity.h"

#include <xxhash.h>

#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include "bvh/gpu_scene.h"
#include "render/backend.h"

namespace wp {

namespace {

std::string settingsFlags(const RenderSettings& s) {
  const char* mode = s.mode == IntegratorMode::Mis ? "mis" : s.mode == IntegratorMode::NeeOnly ? "nee" : "bsdf";
  char clamp[32];
  std::snprintf(clamp, sizeof(clamp), "%.9g", double(s.contributionClamp));
  char adaptive[32];
  std::snprintf(adaptive, sizeof(adaptive), "%.9g", double(s.adaptiveThreshold));
  std::string flags = "--width " + std::to_string(s.width) + " --height " + std::to_string(s.height) +
                      " --max-depth " + std::to_string(s.maxBounces) + " --seed " + std::to_string(s.seed) +
                      " --sampler " + (s.sampler == SamplerKind::Sobol ? "sobol" : "independent") +
                      " --mode " + mode + " --rr-start " + std::to_string(s.russianRouletteStart) +
                      " --light-selection " +
                      (s.lightSelection == LightSelection::Power ? "power" : "solid-angle") + " --clamp " + clamp +
                      " --sky-sampling " + (s.skySampling ? "on" : "off") + " --adaptive " + adaptive +
                      " --adaptive-min-samples " + std::to_string(s.adaptiveMinSamples) +
                      // Recorded or not (a PNG's render records none), not the EXR's choice among them.
                      " --passes " + (s.featurePasses ? "all" : "none") + " --widen-roughness " +
                      (s.widenRoughness ? "on" : "off") + " --fixed-lobe-choice " +
                      (s.fixedLobeChoice ? "on" : "off");
  // Settings added later are named only when set, so that a checkpoint or a part that an
  // earlier build wrote with them off still resumes and merges.
  if (s.filterGlossy != 0.0f) {
    char filterGlossy[32];
    std::snprintf(filterGlossy, sizeof(filterGlossy), "%.9g", double(s.filterGlossy));
    flags += std::string(" --filter-glossy ") + filterGlossy;
  }
  return flags;
}

std::map<std::string, std::string> flagValues(const std::string& flags) {
  std::map<std::string, std::string> values;
  std::istringstream in(flags);
  std::string flag, value;
  while (in >> flag >> value) values[flag] = value;
  return values;
}

}  // namespace

RenderIdentity renderIdentity(const GpuScene& scene, const gpu::RenderParams& params, const RenderSettings& settings) {
  std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(), &XXH3_freeState);
  XXH3_64bits_reset(state.get());
  for (const SceneArray& array : sceneArrays(scene)) {
    XXH3_64bits_update(state.get(), &array.bytes, sizeof(array.bytes));
    XXH3_64bits_update(state.get(), array.data, array.bytes);
  }
  gpu::RenderParams hashed = params;
  hashed.pixelCount = 0;
  hashed.maxPaths = 0;
  hashed.regionX = hashed.regionY = hashed.regionWidth = hashed.regionHeight = 0;
  XXH3_64bits_update(state.get(), &hashed, sizeof(hashed));
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(XXH3_64bits_digest(state.get())));
  return {hex, settingsFlags(settings)};
}

std::string identityDifference(const RenderIdentity& there, const RenderIdentity& here) {
  if (there.settings != here.settings) {
    std::map<std::string, std::string> a = flagValues(there.settings), b = flagValues(here.settings);
    for (const auto& [flag, value] : b) {
      auto other = a.find(flag);
      if (other == a.end() || other->second != value)
        return flag + " is " + (other == a.end() ? "unset" : other->second) + " there, " + value + " here";
    }
    return "the settings differ ('" + there.settings + "' there)";
  }
  if (there.sceneHash != here.sceneHash) return "the scene, camera or sky differs (scene hash " + there.sceneHash +
                                                " there, " + here.sceneHash + " here)";
  return "";
}

}  // namespace wp
