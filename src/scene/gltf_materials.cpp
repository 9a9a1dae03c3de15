// glTF materials to wavepath materials.
#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "scene/gltf_textures.h"
#include "scene/scene_limits.h"

namespace wp::gltf {

namespace {

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";
constexpr const char* kIor = "KHR_materials_ior";
constexpr const char* kTransmission = "KHR_materials_transmission";
constexpr const char* kVolume = "KHR_materials_volume";
constexpr const char* kSpecular = "KHR_materials_specular";
constexpr const char* kSheen = "KHR_materials_sheen";
constexpr const char* kClearcoat = "KHR_materials_clearcoat";
constexpr const char* kUnlit = "KHR_materials_unlit";

bool allFinite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// The extension's object on `material`, or an empty value when it is absent.
const tinygltf::Value& extensionOf(const tinygltf::Material& material, const char* name) {
  static const tinygltf::Value none;
  const auto it = material.extensions.find(name);
  return it == material.extensions.end() || !it->second.IsObject() ? none : it->second;
}

// `extension.key` as a number in [lo, hi] (`range` says so to the user), `fallback` where absent.
double readNumber(const Context& ctx, const tinygltf::Material& material, const char* extension, const char* key,
                  double fallback, double lo, double hi, const char* range, const std::string& where) {
  const tinygltf::Value& object = extensionOf(material, extension);
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& value = object.Get(key);
  const double number = value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
  if (!(number >= lo && number <= hi)) {
    fail(ctx, where,
         std::string(extension) + "." + key + " must be a number " + range + "; fix the material");
  }
  return number;
}

// `extension.key` as 3 numbers in [0, hi], `fallback` where absent.
glm::vec3 readColor(const Context& ctx, const tinygltf::Material& material, const char* extension, const char* key,
                    glm::vec3 fallback, float hi, const std::string& where) {
  const tinygltf::Value& object = extensionOf(material, extension);
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& value = object.Get(key);
  glm::vec3 color(-1.0f);
  if (value.IsArray() && value.ArrayLen() == 3) {
    for (int c = 0; c < 3; ++c) {
      if (value.Get(c).IsNumber()) color[c] = static_cast<float>(value.Get(c).GetNumberAsDouble());
    }
  }
  if (!(glm::all(glm::greaterThanEqual(color, glm::vec3(0.0f))) && glm::all(glm::lessThanEqual(color, glm::vec3(hi))))) {
    fail(ctx, where,
         std::string(extension) + "." + key + " must be 3 numbers in [0, " + (hi == 1.0f ? "1" : "100") +
             "]; fix the material");
  }
  return color;
}

// A material's extras.wavepath, both keys optional:
//   "bsdf": "lambert" makes it ideal diffuse, which glTF cannot say (its dielectric always has
//       a specular layer); the Cornell box is Lambertian like its reference.
//   "diffuse": "lambert" (glTF's own, the default) or "disney": the base under glTF's
//       specular layer; "disney" is the seed report's normalized Disney diffuse.
Material::Bsdf readBsdf(const Context& ctx, const tinygltf::Material& material, const std::string& where) {
  if (!material.extras.Has("wavepath")) return Material::Bsdf::Gltf;
  const tinygltf::Value& extras = material.extras.Get("wavepath");
  const auto text = [&](const char* key) {
    return extras.IsObject() && extras.Has(key) && extras.Get(key).IsString() ? extras.Get(key).Get<std::string>()
                                                                             : std::string("?");
  };
  const bool hasBsdf = extras.IsObject() && extras.Has("bsdf");
  const bool hasDiffuse = extras.IsObject() && extras.Has("diffuse");
  const size_t keys = extras.IsObject() ? extras.Keys().size() : 0;
  const bool valid = extras.IsObject() && keys == size_t(hasBsdf) + size_t(hasDiffuse) &&
                     (!hasBsdf || text("bsdf") == "lambert") &&
                     (!hasDiffuse || text("diffuse") == "lambert" || text("diffuse") == "disney") &&
                     !(hasBsdf && hasDiffuse);
  if (!valid) {
    fail(ctx, where,
         "a material's extras.wavepath must be {\"bsdf\": \"lambert\"} or {\"diffuse\": \"lambert\" or \"disney\"}; "
         "fix the material's extras");
  }
  if (hasBsdf) return Material::Bsdf::Lambert;
  return hasDiffuse && text("diffuse") == "disney" ? Material::Bsdf::GltfDisneyDiffuse : Material::Bsdf::Gltf;
}

// glTF alphaMode and alphaCutoff (which only MASK reads).
void readAlpha(const Context& ctx, const tinygltf::Material& material, const std::string& where, Material& out) {
  const std::string& mode = material.alphaMode;
  if (mode == "MASK") {
    out.alphaMode = Material::AlphaMode::Mask;
  } else if (mode == "BLEND") {
    out.alphaMode = Material::AlphaMode::Blend;
  } else if (mode != "OPAQUE" && !mode.empty()) {
    fail(ctx, where, "alphaMode '" + oneLine(mode.substr(0, 40)) + "' is not OPAQUE, MASK or BLEND; fix the material");
  }
  if (!(material.alphaCutoff >= 0.0 && std::isfinite(material.alphaCutoff))) {
    fail(ctx, where, "alphaCutoff must be a finite number >= 0; fix the material");
  }
  out.alphaCutoff = static_cast<float>(material.alphaCutoff);
}

// The factors of KHR_materials_specular, _sheen and _clearcoat (glTF's defaults where absent:
// white specular, no sheen, no coat). specularColorFactor may exceed 1 (the extension lets
// it tint F0 above the IOR's); F0 is clamped to 1 where it is used (bsdf_models.h).
void readLayers(const Context& ctx, const tinygltf::Material& material, const std::string& where, Material& out) {
  const auto number = [&](const char* extension, const char* key, double fallback) {
    return static_cast<float>(readNumber(ctx, material, extension, key, fallback, 0.0, 1.0, "in [0, 1]", where));
  };
  out.specularWeight = number(kSpecular, "specularFactor", 1.0);
  out.specularColor = readColor(ctx, material, kSpecular, "specularColorFactor", glm::vec3(1.0f), 100.0f, where);
  out.sheenColor = readColor(ctx, material, kSheen, "sheenColorFactor", glm::vec3(0.0f), 1.0f, where);
  out.sheenRoughness = number(kSheen, "sheenRoughnessFactor", 0.0);
  out.clearcoat = number(kClearcoat, "clearcoatFactor", 0.0);
  out.clearcoatRoughness = number(kClearcoat, "clearcoatRoughnessFactor", 0.0);
}

Material convert(const Context& ctx, const tinygltf::Material& material, size_t index) {
  const std::string where = describe("material", index, material.name);
  const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  const std::vector<double>& base = pbr.baseColorFactor;
  const std::vector<double>& emissive = material.emissiveFactor;
  if (base.size() != 4 || emissive.size() != 3 || !allFinite(base) || !allFinite(emissive) ||
      !std::isfinite(pbr.metallicFactor) || !std::isfinite(pbr.roughnessFactor)) {
    fail(ctx, where,
         "baseColorFactor needs 4 finite numbers, emissiveFactor 3, metallicFactor and roughnessFactor one; fix the "
         "material");
  }
  Material out;
  out.name = material.name;
  out.bsdf = readBsdf(ctx, material, where);
  // glTF limits the factors to [0, 1]; an albedo above 1 would create energy.
  out.baseColor = glm::clamp(glm::vec3(base[0], base[1], base[2]), 0.0f, 1.0f);
  out.alpha = std::clamp(static_cast<float>(base[3]), 0.0f, 1.0f);
  readAlpha(ctx, material, where, out);
  out.metallic = std::clamp(static_cast<float>(pbr.metallicFactor), 0.0f, 1.0f);
  out.roughness = std::clamp(static_cast<float>(pbr.roughnessFactor), 0.0f, 1.0f);
  // KHR_materials_ior allows 0 for "no refraction"; wavepath's glass needs an index >= 1.
  out.ior = static_cast<float>(readNumber(ctx, material, kIor, "ior", 1.5, 1.0, 10.0, "in [1, 10]", where));
  out.transmission =
      static_cast<float>(readNumber(ctx, material, kTransmission, "transmissionFactor", 0.0, 0.0, 1.0, "in [0, 1]", where));
  out.attenuationColor = readColor(ctx, material, kVolume, "attenuationColor", glm::vec3(1.0f), 1.0f, where);
  out.attenuationDistance = static_cast<float>(readNumber(ctx, material, kVolume, "attenuationDistance",
                                                          std::numeric_limits<float>::max(), 1e-30,
                                                          std::numeric_limits<float>::max(), "> 0", where));
  const double strength = readNumber(ctx, material, kEmissiveStrength, "emissiveStrength", 1.0, 0.0,
                                     std::numeric_limits<double>::max(), ">= 0", where);
  const glm::dvec3 emission = glm::max(glm::dvec3(emissive[0], emissive[1], emissive[2]), 0.0) * strength;
  const double brightest = std::max({emission.r, emission.g, emission.b});
  if (!(brightest <= kMaxRadiance)) {
    char text[80];
    std::snprintf(text, sizeof(text), "emission %g (emissiveFactor times emissiveStrength) is above %g", brightest,
                  kMaxRadiance);
    fail(ctx, where, std::string(text) + ", brighter than any real emitter; fix the material");
  }
  out.emission = glm::vec3(emission);
  out.doubleSided = material.doubleSided;
  readLayers(ctx, material, where, out);
  if (material.extensions.count(kUnlit) > 0) out.bsdf = Material::Bsdf::Unlit;
  return out;
}

// The texture an extension's textureInfo `key` names, added to `table`; -1 where absent.
// It is read as a core textureInfo is (its texCoord and KHR_texture_transform); `ignored` is
// set for one on a TEXCOORD set other than 0 and 1. A textureInfo that is not an object with an
// integer index is an error.
int readExtensionTexture(const Context& ctx, const tinygltf::Material& material, const char* extension, const char* key, bool srgb,
                         const std::string& where, TextureTable& table, bool& ignored) {
  const tinygltf::Value& object = extensionOf(material, extension);
  if (!object.Has(key)) return -1;
  const tinygltf::Value& info = object.Get(key);
  if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt()) {
    fail(ctx, where, std::string(extension) + "." + key + " needs an integer \"index\"; fix the material");
  }
  int texCoord = 0;
  if (info.Has("texCoord")) {
    if (!info.Get("texCoord").IsInt()) {
      fail(ctx, where, std::string(extension) + "." + key + ".texCoord must be an integer; fix the material");
    }
    texCoord = info.Get("texCoord").GetNumberAsInt();
  }
  tinygltf::ExtensionMap extensions;  // KHR_texture_transform, as a core textureInfo has them
  if (info.Has("extensions") && info.Get("extensions").IsObject()) {
    const tinygltf::Value& own = info.Get("extensions");
    for (const std::string& name : own.Keys()) extensions[name] = own.Get(name);
  }
  const int added = table.add(info.Get("index").GetNumberAsInt(), texCoord, extensions, srgb, where);
  ignored = ignored || added < 0;
  return added;
}

// The layered extensions' textures; returns whether one is on a TEXCOORD set wavepath lacks.
bool readLayerTextures(const Context& ctx, const tinygltf::Material& material, const std::string& where, TextureTable& table,
                       Material& out) {
  bool ignored = false;
  const auto texture = [&](const char* extension, const char* key, bool srgb) {
    return readExtensionTexture(ctx, material, extension, key, srgb, where, table, ignored);
  };
  out.specularTexture = texture(kSpecular, "specularTexture", false);
  out.specularColorTexture = texture(kSpecular, "specularColorTexture", true);
  out.sheenColorTexture = texture(kSheen, "sheenColorTexture", true);
  out.sheenRoughnessTexture = texture(kSheen, "sheenRoughnessTexture", false);
  out.clearcoatTexture = texture(kClearcoat, "clearcoatTexture", false);
  out.clearcoatRoughnessTexture = texture(kClearcoat, "clearcoatRoughnessTexture", false);
  out.clearcoatNormalTexture = texture(kClearcoat, "clearcoatNormalTexture", false);
  const tinygltf::Value& coat = extensionOf(material, kClearcoat);
  if (out.clearcoatNormalTexture >= 0 && coat.Get("clearcoatNormalTexture").Has("scale")) {
    const tinygltf::Value& scale = coat.Get("clearcoatNormalTexture").Get("scale");
    out.clearcoatNormalScale = scale.IsNumber() && std::isfinite(scale.GetNumberAsDouble())
                                   ? static_cast<float>(scale.GetNumberAsDouble())
                                   : 1.0f;
  }
  return ignored;
}

// Reads the base colour, metallic-roughness, normal and emissive textures into `table`, each
// with its texCoord and KHR_texture_transform; returns whether the material has textures
// that wavepath leaves out (on TEXCOORD_2 or later). The occlusion texture is not read and
// not warned about: it approximates, for rasterizers, the occlusion a path tracer computes.
bool readTextures(const Context& ctx, const tinygltf::Material& material, const std::string& where,
                  TextureTable& table, Material& out) {
  bool ignored = false;
  // The slot's index in `table` (-1: none), noting a texture it had to leave out.
  const auto slot = [&](const auto& info, bool srgb) {
    if (info.index < 0) return -1;
    const int added = table.add(info, srgb, where);
    ignored = ignored || added < 0;
    return added;
  };
  const tinygltf::NormalTextureInfo& normal = material.normalTexture;
  out.normalTexture = slot(normal, false);
  if (out.normalTexture >= 0) out.normalScale = std::isfinite(normal.scale) ? static_cast<float>(normal.scale) : 1.0f;
  out.baseColorTexture = slot(material.pbrMetallicRoughness.baseColorTexture, true);
  out.metallicRoughnessTexture = slot(material.pbrMetallicRoughness.metallicRoughnessTexture, false);
  out.emissiveTexture = slot(material.emissiveTexture, true);
  return readLayerTextures(ctx, material, where, table, out) || ignored;
}

}  // namespace

std::vector<Material> convertMaterials(const Context& ctx, std::vector<Texture>& textures) {
  std::vector<Material> materials;
  TextureTable table(ctx, textures);
  size_t ignoring = 0;
  for (size_t i = 0; i < ctx.model.materials.size(); ++i) {
    const tinygltf::Material& material = ctx.model.materials[i];
    materials.push_back(convert(ctx, material, i));
    ignoring += readTextures(ctx, material, describe("material", i, material.name), table, materials.back()) ? 1 : 0;
  }
  if (ignoring > 0) {
    warnAt(ctx, "", std::to_string(ignoring) + " of " + std::to_string(materials.size()) +
                        " materials have textures on TEXCOORD_2 or later, which wavepath "
                        "ignores: those render with their constant factors");
  }
  return materials;
}

Material defaultMaterial() {
  Material material;
  material.name = "default";
  return material;
}

}  // namespace wp::gltf
