// Bounds-checked reading of glTF accessors: vertex attributes and indices.
#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "scene/scene_limits.h"

namespace wp::gltf {

namespace {

// A sparse accessor without a buffer view starts as zeros; real files (sparse morph targets)
// need a few MiB of them.
constexpr size_t kMaxZeroFilledBytes = size_t(1) << 30;

// The bytes of one accessor: `count` elements, `stride` apart. A sparse accessor's elements
// are gathered into `dense` (which `first` then points into).
struct ElementRange {
  const unsigned char* first = nullptr;
  size_t count = 0;
  size_t stride = 0;
  std::vector<unsigned char> dense;
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

size_t componentSize(int componentType) {
  const int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(componentType));
  return size > 0 ? static_cast<size_t>(size) : 0;
}

// An UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT of `size` bytes.
uint32_t unsignedValue(const unsigned char* bytes, size_t size) {
  if (size == 1) return bytes[0];
  if (size == 2) {
    uint16_t value;
    std::memcpy(&value, bytes, 2);
    return value;
  }
  uint32_t value;
  std::memcpy(&value, bytes, 4);
  return value;
}

// The bytes [offset, offset + length) of buffer view `viewIndex`, checked to lie inside the
// view and its buffer; `self` names the accessor in messages.
const unsigned char* viewBytes(const Context& ctx, int viewIndex, size_t offset, size_t length,
                               const std::string& self, size_t* stride) {
  const tinygltf::Model& model = ctx.model;
  if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size()) {
    fail(ctx, self, "buffer view " + missingIndex(viewIndex, model.bufferViews.size(), "buffer views") +
                        "; re-export the file");
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(viewIndex)];
  const std::string viewWhere = describe("buffer view", static_cast<size_t>(viewIndex), view.name);
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
  if (offset > view.byteLength || length > view.byteLength - offset) {
    fail(ctx, self,
         "bytes " + std::to_string(offset) + " + " + std::to_string(length) + " do not fit in " + viewWhere + " (" +
             std::to_string(view.byteLength) + " bytes); the file is damaged: re-export it");
  }
  if (stride != nullptr) *stride = view.byteStride;
  return buffer.data() + view.byteOffset + offset;
}

// The `count` indices of a sparse accessor, each checked to be below `elements`.
std::vector<size_t> sparseIndices(const Context& ctx, const tinygltf::Accessor& accessor, size_t elements,
                                  const std::string& self) {
  const auto& indices = accessor.sparse.indices;
  const size_t count = static_cast<size_t>(std::max(accessor.sparse.count, 0));
  const size_t size = indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                      : indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                      : indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                        : 0;
  if (size == 0) {
    fail(ctx, self, std::string("sparse indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not ") +
                        componentName(indices.componentType) + "; re-export the file");
  }
  if (count > (std::numeric_limits<size_t>::max() / size)) fail(ctx, self, "sparse count is too large; re-export the file");
  const unsigned char* bytes =
      viewBytes(ctx, indices.bufferView, static_cast<size_t>(std::max(indices.byteOffset, 0)), count * size,
                self + " sparse indices", nullptr);
  std::vector<size_t> out(count);
  for (size_t i = 0; i < count; ++i) {
    const uint32_t value = unsignedValue(bytes + i * size, size);
    if (value >= elements) {
      fail(ctx, self, "sparse index " + std::to_string(value) + " is out of range (the accessor has " +
                          std::to_string(elements) + " elements); re-export the file");
    }
    out[i] = value;
  }
  return out;
}

// Checks the accessor lies inside its buffer view and buffer (and its sparse indices and
// values inside theirs), and returns its elements. `elementSize` comes from the type the
// caller has already checked.
ElementRange locate(const Context& ctx, int index, const std::string& where, size_t elementSize) {
  const tinygltf::Accessor& accessor = ctx.model.accessors[static_cast<size_t>(index)];
  const std::string self = where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name);
  ElementRange range;
  range.count = accessor.count;
  if (accessor.bufferView < 0 && !accessor.sparse.isSparse) {
    fail(ctx, self, "has no buffer view (so all its values would be 0); re-export the file");
  }
  if (accessor.bufferView >= 0) {
    size_t viewStride = 0;
    viewBytes(ctx, accessor.bufferView, 0, 0, self, &viewStride);
    range.stride = viewStride != 0 ? viewStride : elementSize;
    const tinygltf::BufferView& view = ctx.model.bufferViews[static_cast<size_t>(accessor.bufferView)];
    // Written with subtractions and a division so that no huge count or offset can overflow.
    const bool fits = accessor.count == 0 ||
                      (accessor.byteOffset <= view.byteLength && elementSize <= view.byteLength - accessor.byteOffset &&
                       (accessor.count - 1) <= (view.byteLength - accessor.byteOffset - elementSize) / range.stride);
    if (!fits) {
      fail(ctx, self,
           std::to_string(accessor.count) + " elements from byte offset " + std::to_string(accessor.byteOffset) +
               " with stride " + std::to_string(range.stride) + " do not fit in " +
               describe("buffer view", static_cast<size_t>(accessor.bufferView), view.name) + " (" +
               std::to_string(view.byteLength) + " bytes); the file is damaged: re-export it");
    }
    if (accessor.count == 0) return range;
    range.first = viewBytes(ctx, accessor.bufferView, 0, 0, self, nullptr) + accessor.byteOffset;
  }
  if (!accessor.sparse.isSparse) return range;

  // Sparse: the base values (or zeros), then the listed elements replaced. Without a buffer
  // view nothing in the file bounds the count, so the zeros are bounded here.
  if (accessor.bufferView < 0 && accessor.count > 0 && elementSize > kMaxZeroFilledBytes / accessor.count) {
    fail(ctx, self, std::to_string(accessor.count) +
                        " elements without a buffer view are more than wavepath fills with zeros; re-export the file");
  }
  range.dense.assign(accessor.count * elementSize, 0);
  for (size_t i = 0; range.first != nullptr && i < accessor.count; ++i) {
    std::memcpy(range.dense.data() + i * elementSize, range.first + i * range.stride, elementSize);
  }
  const std::vector<size_t> indices = sparseIndices(ctx, accessor, accessor.count, self);
  const unsigned char* values =
      viewBytes(ctx, accessor.sparse.values.bufferView, static_cast<size_t>(std::max(accessor.sparse.values.byteOffset, 0)),
                indices.size() * elementSize, self + " sparse values", nullptr);
  for (size_t i = 0; i < indices.size(); ++i) {
    std::memcpy(range.dense.data() + indices[i] * elementSize, values + i * elementSize, elementSize);
  }
  range.first = range.dense.data();
  range.stride = elementSize;
  return range;
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

// One component decoded as glTF 2.0 says: normalized integers by section 3.11's formulas
// (signed ones clamped at -1), others converted as they are (KHR_mesh_quantization).
float componentValue(const unsigned char* bytes, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float value;
      std::memcpy(&value, bytes, 4);
      return value;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float value = float(static_cast<int8_t>(bytes[0]));
      return normalized ? std::max(value / 127.0f, -1.0f) : value;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(bytes[0]) / 255.0f : float(bytes[0]);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, bytes, 2);
      return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    default: {
      uint16_t v;
      std::memcpy(&v, bytes, 2);
      return normalized ? float(v) / 65535.0f : float(v);
    }
  }
}

bool isSmallInteger(int type) {
  return type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         type == TINYGLTF_COMPONENT_TYPE_SHORT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

// Which integer encodings an attribute may use besides FLOAT.
enum class Integers { Any, SignedNormalized };

// Reads an accessor of `type` (VEC2, VEC3 or VEC4, matching T) with the checks of
// readVec3Attribute; `attribute` names it in messages.
template <typename T>
std::vector<T> readVectors(const Context& ctx, int index, const std::string& where, const char* attribute, int type,
                           Integers integers) {
  const tinygltf::Accessor& accessor = lookUp(ctx, index, where, attribute);
  const int component = accessor.componentType;
  const bool allowed =
      component == TINYGLTF_COMPONENT_TYPE_FLOAT ||
      (integers == Integers::Any && isSmallInteger(component)) ||
      (integers == Integers::SignedNormalized && accessor.normalized &&
       (component == TINYGLTF_COMPONENT_TYPE_BYTE || component == TINYGLTF_COMPONENT_TYPE_SHORT));
  if (!allowed || accessor.type != type) {
    fail(ctx, where + ": " + describe("accessor", static_cast<size_t>(index), accessor.name),
         std::string(attribute) + " must be " + typeName(type) + " of FLOAT" +
             (integers == Integers::Any ? " or 8- or 16-bit integers" : " or normalized BYTE or SHORT") + ", not " +
             componentName(component) + " " + typeName(accessor.type) + "; re-export the file");
  }
  const size_t size = componentSize(component);
  const ElementRange range = locate(ctx, index, where, size * T::length());
  std::vector<T> values(range.count);
  for (size_t i = 0; i < range.count; ++i) {
    const unsigned char* element = range.first + i * range.stride;
    for (int c = 0; c < T::length(); ++c) values[i][c] = componentValue(element + c * size, component, accessor.normalized);
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
  return readVectors<glm::vec3>(ctx, index, where, attribute, TINYGLTF_TYPE_VEC3, Integers::Any);
}

std::vector<glm::vec2> readTexCoords(const Context& ctx, int index, const std::string& where, const char* attribute) {
  return readVectors<glm::vec2>(ctx, index, where, attribute, TINYGLTF_TYPE_VEC2, Integers::Any);
}

std::vector<glm::vec4> readTangents(const Context& ctx, int index, const std::string& where) {
  return readVectors<glm::vec4>(ctx, index, where, "TANGENT", TINYGLTF_TYPE_VEC4, Integers::SignedNormalized);
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
  const size_t size = componentSize(type);
  const ElementRange range = locate(ctx, index, where, size * components);
  std::vector<glm::vec4> colors(range.count, glm::vec4(1.0f));
  for (size_t i = 0; i < range.count; ++i) {
    const unsigned char* element = range.first + i * range.stride;
    for (int c = 0; c < components; ++c) {
      const float value = componentValue(element + c * size, type, true);
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
  const size_t size = componentSize(type);
  const ElementRange range = locate(ctx, index, where, size * static_cast<size_t>(components));
  FloatElements out{std::vector<float>(range.count * static_cast<size_t>(components)), static_cast<size_t>(components)};
  for (size_t i = 0; i < range.count; ++i) {
    const unsigned char* element = range.first + i * range.stride;
    for (size_t c = 0; c < out.components; ++c) {
      const float value = componentValue(element + c * size, type, true);
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
    indices[i] = unsignedValue(range.first + i * range.stride, size);
  }
  return indices;
}

}  // namespace wp::gltf
