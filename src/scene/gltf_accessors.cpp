// Bounds-checked reading of glTF accessors: vertex attributes and indices.
#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/scene_limits.h"

namespace wp::gltf {

namespace {

// The bytes of one accessor: `count` elements of `elementSize` bytes, `stride` apart.
struct ElementRange {
  const unsigned char* first = nullptr;
  size_t count = 0;
  size_t stride = 0;
};

const char* componentName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "an unknown component type";
  }
}

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "an unknown type";
  }
}

// Checks the accessor exists and lies inside its buffer view and buffer, and returns its
// bytes. `elementSize` comes from the type the caller has already checked.
ElementRange locate(const Context& ctx, int index, const std::string& where, size_t elementSize) {
  const tinygltf::Model& model = ctx.model;
  const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(index)];
  const std::string self = where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name);
  if (accessor.sparse.isSparse) {
    fail(ctx, self, "sparse accessors are not supported; re-export the scene without them");
  }
  if (accessor.bufferView < 0 || static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size()) {
    fail(ctx, self,
         accessor.bufferView < 0
             ? "has no buffer view (so all its values would be 0); re-export the file"
             : "buffer view " + missingIndex(accessor.bufferView, model.bufferViews.size(), "buffer views") +
                   "; re-export the file");
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(accessor.bufferView)];
  const std::string viewWhere = describe("buffer view", static_cast<size_t>(accessor.bufferView), view.name);
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
    fail(ctx, self + ": " + viewWhere,
         "buffer " + missingIndex(view.buffer, model.buffers.size(), "buffers") + "; re-export the file");
  }
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<size_t>(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
    fail(ctx, self + ": " + viewWhere,
         "bytes " + std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
             " reach past the end of buffer " + std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) +
             " bytes); the file is damaged: re-export it");
  }
  const size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
  // Written with subtractions and a division so that no huge count or offset can overflow.
  const bool fits = accessor.count == 0 ||
                    (accessor.byteOffset <= view.byteLength && elementSize <= view.byteLength - accessor.byteOffset &&
                     (accessor.count - 1) <= (view.byteLength - accessor.byteOffset - elementSize) / stride);
  if (!fits) {
    fail(ctx, self,
         std::to_string(accessor.count) + " elements from byte offset " + std::to_string(accessor.byteOffset) +
             " with stride " + std::to_string(stride) + " do not fit in " + viewWhere + " (" +
             std::to_string(view.byteLength) + " bytes); the file is damaged: re-export it");
  }
  if (accessor.count == 0) return {};
  return {buffer.data() + view.byteOffset + accessor.byteOffset, accessor.count, stride};
}

// A number the renderer can use: finite and within ±kMaxCoordinate (scene_limits.h).
bool plausible(float value) { return std::isfinite(value) && std::fabs(value) <= kMaxCoordinate; }

template <int N>
bool plausible(const glm::vec<N, float>& v) {
  for (int i = 0; i < N; ++i) {
    if (!plausible(v[i])) return false;
  }
  return true;
}

// What the message says of a value that is not plausible.
constexpr const char* kNotPlausible = "is not finite, or is beyond ±1e12";

const tinygltf::Accessor& lookUp(const Context& ctx, int index, const std::string& where, const char* role) {
  if (index < 0 || static_cast<size_t>(index) >= ctx.model.accessors.size()) {
    fail(ctx, where,
         std::string(role) + " accessor " + missingIndex(index, ctx.model.accessors.size(), "accessors") +
             "; re-export the file");
  }
  return ctx.model.accessors[static_cast<size_t>(index)];
}

// Reads a FLOAT accessor of `type` (VEC2 or VEC4, matching T) with the checks of
// readVec3Attribute; `attribute` names it in messages.
template <typename T>
std::vector<T> readFloatVectors(const Context& ctx, int index, const std::string& where, const char* attribute,
                                int type) {
  const tinygltf::Accessor& accessor = lookUp(ctx, index, where, attribute);
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || accessor.type != type) {
    fail(ctx, where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name),
         std::string(attribute) + " must be FLOAT " + typeName(type) + ", not " +
             componentName(accessor.componentType) + " " + typeName(accessor.type) +
             "; re-export the scene without mesh quantization");
  }
  const ElementRange range = locate(ctx, index, where, sizeof(T));
  std::vector<T> values(range.count);
  for (size_t i = 0; i < range.count; ++i) {
    std::memcpy(&values[i], range.first + i * range.stride, sizeof(T));
    if (!plausible(values[i])) {
      fail(ctx, where, "vertex " + std::to_string(i) + " of the " + attribute + " accessor " + std::to_string(index) +
                           " " + kNotPlausible + "; re-export the file");
    }
  }
  return values;
}

}  // namespace

std::vector<glm::vec3> readVec3Attribute(const Context& ctx, int index, const std::string& where,
                                         const char* attribute) {
  const tinygltf::Accessor& accessor = lookUp(ctx, index, where, attribute);
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || accessor.type != TINYGLTF_TYPE_VEC3) {
    fail(ctx, where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name),
         std::string(attribute) + " must be FLOAT VEC3, not " + componentName(accessor.componentType) + " " +
             typeName(accessor.type) + "; re-export the scene without mesh quantization");
  }
  const ElementRange range = locate(ctx, index, where, sizeof(glm::vec3));
  std::vector<glm::vec3> positions(range.count);
  for (size_t i = 0; i < range.count; ++i) {
    std::memcpy(&positions[i], range.first + i * range.stride, sizeof(glm::vec3));
    const glm::vec3& p = positions[i];
    if (!plausible(p)) {
      fail(ctx, where,
           "vertex " + std::to_string(i) + " of the " + attribute + " accessor " + std::to_string(index) + " " +
               kNotPlausible + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) +
               "); re-export the file");
    }
  }
  return positions;
}

std::vector<glm::vec2> readTexCoords(const Context& ctx, int index, const std::string& where) {
  return readFloatVectors<glm::vec2>(ctx, index, where, "TEXCOORD_0", TINYGLTF_TYPE_VEC2);
}

std::vector<glm::vec4> readTangents(const Context& ctx, int index, const std::string& where) {
  return readFloatVectors<glm::vec4>(ctx, index, where, "TANGENT", TINYGLTF_TYPE_VEC4);
}

std::vector<glm::vec4> readColors(const Context& ctx, int index, const std::string& where) {
  const tinygltf::Accessor& accessor = lookUp(ctx, index, where, "COLOR_0");
  const int type = accessor.componentType;
  const bool knownType = type == TINYGLTF_COMPONENT_TYPE_FLOAT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                         type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const int components = accessor.type == TINYGLTF_TYPE_VEC3 ? 3 : accessor.type == TINYGLTF_TYPE_VEC4 ? 4 : 0;
  if (!knownType || components == 0 || (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized)) {
    fail(ctx, where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name),
         std::string("COLOR_0 must be VEC3 or VEC4 of FLOAT or normalized UNSIGNED_BYTE or UNSIGNED_SHORT, not ") +
             componentName(type) + " " + typeName(accessor.type) + "; re-export the file");
  }
  const size_t componentSize = type == TINYGLTF_COMPONENT_TYPE_FLOAT ? 4 : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2 : 1;
  const ElementRange range = locate(ctx, index, where, componentSize * components);
  std::vector<glm::vec4> colors(range.count, glm::vec4(1.0f));
  for (size_t i = 0; i < range.count; ++i) {
    const unsigned char* element = range.first + i * range.stride;
    for (int c = 0; c < components; ++c) {
      float value = 0.0f;
      if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        std::memcpy(&value, element + 4 * c, 4);
      } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t v = 0;
        std::memcpy(&v, element + 2 * c, 2);
        value = float(v) / 65535.0f;
      } else {
        value = float(element[c]) / 255.0f;
      }
      if (!std::isfinite(value)) {
        fail(ctx, where, "vertex " + std::to_string(i) + " of the COLOR_0 accessor " + std::to_string(index) +
                             " is not finite; re-export the file");
      }
      colors[i][c] = std::clamp(value, 0.0f, 1.0f);
    }
  }
  return colors;
}

FloatElements readFloats(const Context& ctx, int index, const std::string& where, const char* role,
                         bool allowNormalized) {
  const tinygltf::Accessor& accessor = lookUp(ctx, index, where, role);
  const int type = accessor.componentType;
  const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
  const bool matrix = accessor.type == TINYGLTF_TYPE_MAT2 || accessor.type == TINYGLTF_TYPE_MAT3 ||
                      accessor.type == TINYGLTF_TYPE_MAT4;
  const bool normalized = allowNormalized && !matrix && accessor.normalized &&
                          (type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                           type == TINYGLTF_COMPONENT_TYPE_SHORT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  if (components <= 0 || (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalized)) {
    fail(ctx, where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name),
         std::string(role) + " must be FLOAT" + (allowNormalized ? " or normalized integers" : "") + ", not " +
             componentName(type) + " " + typeName(accessor.type) + "; re-export the file");
  }
  const size_t componentSize = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(type)));
  const ElementRange range = locate(ctx, index, where, componentSize * static_cast<size_t>(components));
  FloatElements out{std::vector<float>(range.count * static_cast<size_t>(components)), static_cast<size_t>(components)};
  for (size_t i = 0; i < range.count; ++i) {
    const unsigned char* element = range.first + i * range.stride;
    for (size_t c = 0; c < out.components; ++c) {
      const unsigned char* bytes = element + c * componentSize;
      float value = 0.0f;
      // The decodings of glTF 2.0 section 3.11 (animation) for normalized integers.
      switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&value, bytes, 4); break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: value = std::max(float(static_cast<int8_t>(bytes[0])) / 127.0f, -1.0f); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: value = float(bytes[0]) / 255.0f; break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
          int16_t v = 0;
          std::memcpy(&v, bytes, 2);
          value = std::max(float(v) / 32767.0f, -1.0f);
          break;
        }
        default: {
          uint16_t v = 0;
          std::memcpy(&v, bytes, 2);
          value = float(v) / 65535.0f;
        }
      }
      if (!plausible(value)) {
        fail(ctx, where, "element " + std::to_string(i) + " of the " + role + " accessor " + std::to_string(index) +
                             " " + kNotPlausible + "; re-export the file");
      }
      out.values[i * out.components + c] = value;
    }
  }
  return out;
}

std::vector<glm::uvec4> readJoints(const Context& ctx, int index, const std::string& where) {
  const tinygltf::Accessor& accessor = lookUp(ctx, index, where, "JOINTS_0");
  const int type = accessor.componentType;
  if (accessor.type != TINYGLTF_TYPE_VEC4 ||
      (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)) {
    fail(ctx, where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name),
         std::string("JOINTS_0 must be VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT, not ") + componentName(type) + " " +
             typeName(accessor.type) + "; re-export the file");
  }
  const size_t size = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 1 : 2;
  const ElementRange range = locate(ctx, index, where, 4 * size);
  std::vector<glm::uvec4> joints(range.count);
  for (size_t i = 0; i < range.count; ++i) {
    const unsigned char* element = range.first + i * range.stride;
    for (int c = 0; c < 4; ++c) {
      uint16_t v = element[c * size];
      if (size == 2) std::memcpy(&v, element + c * 2, 2);
      joints[i][c] = v;
    }
  }
  return joints;
}

std::vector<uint32_t> readIndices(const Context& ctx, int index, const std::string& where) {
  const tinygltf::Accessor& accessor = lookUp(ctx, index, where, "indices");
  size_t size = 0;
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
    default: break;
  }
  if (size == 0 || accessor.type != TINYGLTF_TYPE_SCALAR) {
    fail(ctx, where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name),
         std::string("indices must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not ") +
             componentName(accessor.componentType) + " " + typeName(accessor.type) + "; re-export the file");
  }
  const ElementRange range = locate(ctx, index, where, size);
  std::vector<uint32_t> indices(range.count);
  for (size_t i = 0; i < range.count; ++i) {
    const unsigned char* element = range.first + i * range.stride;
    if (size == 1) {
      indices[i] = element[0];
    } else if (size == 2) {
      uint16_t value;
      std::memcpy(&value, element, 2);
      indices[i] = value;
    } else {
      std::memcpy(&indices[i], element, 4);
    }
  }
  return indices;
}

}  // namespace wp::gltf
