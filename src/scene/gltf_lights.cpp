// KHR_lights_punctual: the file's lights, and which node places which.
#include "scene/gltf_lights.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "core/log.h"
#include "scene/scene_limits.h"

namespace wp::gltf {

namespace {

constexpr const char* kExtension = "KHR_lights_punctual";

// Blender's importer and exporter: 683 lm per W, the luminous efficacy of 555 nm light.
constexpr double kLumensPerWatt = 683.0;

PunctualLight convert(const Context& ctx, const tinygltf::Light& light, size_t index) {
  const std::string where = describe("light", index, light.name);
  PunctualLight out;
  out.name = light.name;
  if (light.type == "point") {
    out.kind = PunctualLight::Kind::Point;
  } else if (light.type == "spot") {
    out.kind = PunctualLight::Kind::Spot;
  } else if (light.type == "directional") {
    out.kind = PunctualLight::Kind::Directional;
  } else {
    fail(ctx, where, "type '" + oneLine(light.type) + "' is not point, spot or directional; fix the light");
  }
  const std::vector<double> color = light.color.empty() ? std::vector<double>{1.0, 1.0, 1.0} : light.color;
  if (color.size() != 3 || !(color[0] >= 0.0 && color[1] >= 0.0 && color[2] >= 0.0) ||
      !(std::isfinite(color[0]) && std::isfinite(color[1]) && std::isfinite(color[2]))) {
    fail(ctx, where, "color must be 3 finite numbers >= 0; fix the light");
  }
  if (!(light.intensity >= 0.0) || !std::isfinite(light.intensity)) {
    fail(ctx, where, "intensity must be a finite number >= 0 (candela, or lux for a directional light); fix the light");
  }
  const double watts = light.intensity / kLumensPerWatt;
  // The same bound as emission and skies (scene_limits.h), on W/sr or W/m^2.
  if (std::max({color[0], color[1], color[2]}) * watts > kMaxRadiance) {
    fail(ctx, where, "its intensity times its color is above " + std::to_string(int64_t(kMaxRadiance * kLumensPerWatt)) +
                         " candela (or lux), brighter than any real lamp; lower it");
  }
  out.intensity = glm::vec3(float(color[0] * watts), float(color[1] * watts), float(color[2] * watts));
  if (out.kind == PunctualLight::Kind::Spot) {
    const double inner = light.spot.innerConeAngle;
    const double outer = light.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= std::numbers::pi / 2)) {
      fail(ctx, where,
           "spot cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2 radians; fix the light");
    }
    out.innerConeAngle = float(inner);
    out.outerConeAngle = float(outer);
  }
  return out;
}

}  // namespace

std::vector<PunctualLight> readLights(const Context& ctx) {
  std::vector<PunctualLight> lights;
  bool hasRange = false;
  for (size_t i = 0; i < ctx.model.lights.size(); ++i) {
    lights.push_back(convert(ctx, ctx.model.lights[i], i));
    hasRange = hasRange || ctx.model.lights[i].range > 0.0;
  }
  if (hasRange) {
    note(ctx.file + ": the lights' range is ignored: it is a rasterizer's cut-off, and a light falls off with the "
                    "square of the distance anyway");
  }
  return lights;
}

std::optional<size_t> nodeLight(const Context& ctx, size_t node) {
  const tinygltf::ExtensionMap& extensions = ctx.model.nodes[node].extensions;
  const auto found = extensions.find(kExtension);
  if (found == extensions.end()) return std::nullopt;
  const tinygltf::Value& value = found->second;
  const tinygltf::Value light = value.IsObject() && value.Has("light") ? value.Get("light") : tinygltf::Value();
  const size_t count = ctx.model.lights.size();
  if (!light.IsInt() || light.Get<int>() < 0 || size_t(light.Get<int>()) >= count) {
    const long long index = light.IsInt() ? light.Get<int>() : -1;
    fail(ctx, describe("node", node, ctx.model.nodes[node].name),
         std::string(kExtension) + ".light " + missingIndex(index, count, "lights") + "; re-export the file");
  }
  return size_t(light.Get<int>());
}

}  // namespace wp::gltf
