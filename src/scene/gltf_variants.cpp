// KHR_materials_variants: the material a primitive shows in a variant the user chose.
#include "scene/gltf_variants.h"

namespace wp::gltf {

namespace {

constexpr const char* kVariants = "KHR_materials_variants";

}  // namespace

int findVariant(const Context& ctx, const std::string& name) {
  if (name.empty()) return -1;
  const auto root = ctx.model.extensions.find(kVariants);
  std::string names;
  if (root != ctx.model.extensions.end() && root->second.Has("variants") && root->second.Get("variants").IsArray()) {
    const tinygltf::Value& variants = root->second.Get("variants");
    for (size_t i = 0; i < variants.ArrayLen(); ++i) {
      const tinygltf::Value& variant = variants.Get(int(i));
      const std::string variantName =
          variant.Has("name") && variant.Get("name").IsString() ? variant.Get("name").Get<std::string>() : "";
      if (variantName == name) return int(i);
      names += (names.empty() ? "" : ", ") + ("'" + variantName + "'");
    }
  }
  fail(ctx, "",
       "--variant '" + name + "' is not a KHR_materials_variants variant of the file (" +
           (names.empty() ? std::string("it has none") : "it has " + names) + "); name one of those");
}

int variantMaterial(const Context& ctx, const tinygltf::Primitive& primitive, int variant, const std::string& where) {
  const auto extension = primitive.extensions.find(kVariants);
  if (variant < 0 || extension == primitive.extensions.end() || !extension->second.Has("mappings")) {
    return primitive.material;
  }
  const tinygltf::Value& mappings = extension->second.Get("mappings");
  for (size_t m = 0; mappings.IsArray() && m < mappings.ArrayLen(); ++m) {
    const tinygltf::Value& mapping = mappings.Get(int(m));
    const tinygltf::Value& variants = mapping.Get("variants");
    for (size_t v = 0; variants.IsArray() && v < variants.ArrayLen(); ++v) {
      if (variants.Get(int(v)).IsInt() && variants.Get(int(v)).GetNumberAsInt() == variant) {
        if (!mapping.Get("material").IsInt()) {
          fail(ctx, where, std::string(kVariants) + " mapping " + std::to_string(m) +
                               " needs an integer \"material\"; fix the file");
        }
        return mapping.Get("material").GetNumberAsInt();
      }
    }
  }
  return primitive.material;
}

}  // namespace wp::gltf
