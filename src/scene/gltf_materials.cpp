// glTF materials to wavepath materials.
#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace wp::gltf {

namespace {

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

bool allFinite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

float emissiveStrength(const Context& ctx, const tinygltf::Material& material, const std::string& where) {
  const auto it = material.extensions.find(kEmissiveStrength);
  if (it == material.extensions.end() || !it->second.IsObject() || !it->second.Has("emissiveStrength")) {
    return 1.0f;  // the extension's default
  }
  const tinygltf::Value& value = it->second.Get("emissiveStrength");
  const double strength = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
  if (!std::isfinite(strength) || strength < 0.0) {
    fail(ctx, where, std::string(kEmissiveStrength) + ".emissiveStrength must be a number >= 0; fix the material");
  }
  return static_cast<float>(strength);
}

Material convert(const Context& ctx, const tinygltf::Material& material, size_t index) {
  const std::string where = describe("material", index, material.name);
  const std::vector<double>& base = material.pbrMetallicRoughness.baseColorFactor;
  const std::vector<double>& emissive = material.emissiveFactor;
  if (base.size() != 4 || emissive.size() != 3 || !allFinite(base) || !allFinite(emissive)) {
    fail(ctx, where, "baseColorFactor needs 4 finite numbers and emissiveFactor 3; fix the material");
  }
  Material out;
  out.name = material.name;
  // glTF limits the factors to [0, 1]; an albedo above 1 would create energy.
  out.baseColor = glm::clamp(glm::vec3(base[0], base[1], base[2]), 0.0f, 1.0f);
  out.alpha = std::clamp(static_cast<float>(base[3]), 0.0f, 1.0f);
  out.emission = glm::max(glm::vec3(emissive[0], emissive[1], emissive[2]), 0.0f) *
                 emissiveStrength(ctx, material, where);
  out.doubleSided = material.doubleSided;
  return out;
}

bool hasTexture(const tinygltf::Material& material) {
  return material.pbrMetallicRoughness.baseColorTexture.index >= 0 || material.emissiveTexture.index >= 0 ||
         material.normalTexture.index >= 0 || material.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0;
}

}  // namespace

std::vector<Material> convertMaterials(const Context& ctx) {
  std::vector<Material> materials;
  size_t textured = 0;
  for (size_t i = 0; i < ctx.model.materials.size(); ++i) {
    materials.push_back(convert(ctx, ctx.model.materials[i], i));
    textured += hasTexture(ctx.model.materials[i]) ? 1 : 0;
  }
  if (textured > 0) {
    warnAt(ctx, "", std::to_string(textured) + " of " + std::to_string(materials.size()) +
                        " materials have textures, which wavepath ignores for now: they render with their "
                        "constant factors");
  }
  return materials;
}

Material defaultMaterial() {
  Material material;
  material.name = "default";
  return material;
}

}  // namespace wp::gltf
