// wavepath's analytic shapes, read from node extras (the schema is in gltf_loader.cpp).
#include "scene/gltf_extras.h"

#include <cmath>
#include <string>

namespace wp::gltf {

namespace {

constexpr const char* kUsage =
    "write \"extras\": {\"wavepath\": {\"shape\": \"sphere\", \"radius\": 0.5, \"material\": 0}} or "
    "{\"shape\": \"plane\", \"material\": 0}";

int readMaterial(const Context& ctx, const tinygltf::Value& shape, const std::string& where) {
  if (!shape.Has("material")) return -1;
  const tinygltf::Value& value = shape.Get("material");
  const double number = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
  const size_t count = ctx.model.materials.size();
  if (!(number >= 0.0) || number != std::floor(number) || number >= static_cast<double>(count)) {
    fail(ctx, where,
         "extras.wavepath.material must be an index of the materials array (the file has " + std::to_string(count) +
             (count == 1 ? " material" : " materials") + "); fix the node's extras");
  }
  return static_cast<int>(number);
}

double readRadius(const Context& ctx, const tinygltf::Value& shape, const std::string& where) {
  const tinygltf::Value& value = shape.Has("radius") ? shape.Get("radius") : tinygltf::Value();
  const double radius = value.IsNumber() ? value.GetNumberAsDouble() : 0.0;
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    fail(ctx, where, "a sphere's extras.wavepath.radius must be a number > 0; fix the node's extras");
  }
  return radius;
}

}  // namespace

std::optional<ShapeSpec> readShape(const Context& ctx, size_t index) {
  const tinygltf::Node& node = ctx.model.nodes[index];
  if (!node.extras.Has("wavepath")) return std::nullopt;
  const std::string where = describe("node", index, node.name);
  const tinygltf::Value& shape = node.extras.Get("wavepath");
  if (!shape.IsObject() || !shape.Has("shape") || !shape.Get("shape").IsString()) {
    fail(ctx, where, std::string("extras.wavepath needs a \"shape\"; ") + kUsage);
  }
  const std::string& kind = shape.Get("shape").Get<std::string>();
  ShapeSpec spec;
  if (kind == "sphere") {
    spec.kind = ShapeSpec::Kind::Sphere;
    spec.radius = readRadius(ctx, shape, where);
  } else if (kind == "plane") {
    spec.kind = ShapeSpec::Kind::Plane;
  } else {
    fail(ctx, where, "unknown extras.wavepath.shape '" + oneLine(kind.substr(0, 40)) + "'; " + kUsage);
  }
  spec.material = readMaterial(ctx, shape, where);
  return spec;
}

}  // namespace wp::gltf
