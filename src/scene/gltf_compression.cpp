// Compressed mesh data decoded at load (EXT_meshopt_compression, KHR_draco_mesh_compression)
// into plain buffers, so that everything after reads them as it reads uncompressed files.
#include "scene/gltf_compression.h"

#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <draco/compression/decode.h>
#include <meshoptimizer.h>

namespace wp::gltf {

namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";
constexpr const char* kDraco = "KHR_draco_mesh_compression";

// meshoptimizer's codecs spend at least 2 bits on 16 bytes of vertex data (a 64:1 ratio,
// plus a tail of up to 4 KiB) and a byte on a triangle's 3 indices, so a view that claims
// more than this from its compressed bytes is damaged or hostile: refused before allocating.
constexpr uint64_t kMaxMeshoptRatio = 64;
constexpr uint64_t kMeshoptSlack = 65536;

// `value` as a non-negative integer, or -1 when it is not one.
int64_t asCount(const tinygltf::Value& value) {
  if (!value.IsNumber()) return -1;
  const double number = value.GetNumberAsDouble();
  return number >= 0.0 && number <= 9.0e15 && number == double(int64_t(number)) ? int64_t(number) : -1;
}

// `object.key` as a non-negative integer, or `fallback` when absent; -1 when not such a number.
int64_t readCount(const tinygltf::Value& object, const char* key, int64_t fallback) {
  return object.Has(key) ? asCount(object.Get(key)) : fallback;
}

std::string readText(const tinygltf::Value& object, const char* key, const std::string& fallback) {
  if (!object.Has(key)) return fallback;
  return object.Get(key).IsString() ? object.Get(key).Get<std::string>() : std::string("?");
}

// Appends a buffer holding `bytes` and a tightly packed view of all of it; returns the view's index.
int appendView(tinygltf::Model& model, std::vector<unsigned char> bytes) {
  tinygltf::BufferView view;
  view.buffer = static_cast<int>(model.buffers.size());
  view.byteLength = bytes.size();
  model.buffers.emplace_back().data = std::move(bytes);
  model.bufferViews.push_back(std::move(view));
  return static_cast<int>(model.bufferViews.size()) - 1;
}

// The decoded bytes of one EXT_meshopt_compression view.
std::vector<unsigned char> decodeMeshoptView(const Context& ctx, const tinygltf::Model& model,
                                             const tinygltf::BufferView& view, const tinygltf::Value& ext,
                                             const std::string& where) {
  const int64_t buffer = readCount(ext, "buffer", -1);
  const int64_t offset = readCount(ext, "byteOffset", 0);
  const int64_t length = readCount(ext, "byteLength", -1);
  const int64_t stride = readCount(ext, "byteStride", -1);
  const int64_t count = readCount(ext, "count", -1);
  const std::string mode = readText(ext, "mode", "?");
  const std::string filter = readText(ext, "filter", "NONE");
  if (buffer < 0 || offset < 0 || length < 0 || stride <= 0 || count < 0) {
    fail(ctx, where, std::string(kMeshopt) + " needs buffer, byteLength, byteStride and count as non-negative "
                     "integers (and byteStride above 0); re-export the file");
  }
  if (static_cast<size_t>(buffer) >= model.buffers.size()) {
    fail(ctx, where, std::string(kMeshopt) + " buffer " + missingIndex(buffer, model.buffers.size(), "buffers") +
                         "; re-export the file");
  }
  const std::vector<unsigned char>& data = model.buffers[static_cast<size_t>(buffer)].data;
  if (uint64_t(offset) > data.size() || uint64_t(length) > data.size() - uint64_t(offset)) {
    fail(ctx, where, std::string(kMeshopt) + " bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                         " reach past the end of buffer " + std::to_string(buffer) + " (" +
                         std::to_string(data.size()) + " bytes); the file is damaged: re-export it");
  }
  const bool attributes = mode == "ATTRIBUTES";
  const bool indices = mode == "TRIANGLES" || mode == "INDICES";
  const bool strideAllowed = attributes ? stride % 4 == 0 && stride <= 256 : stride == 2 || stride == 4;
  const bool filterAllowed = filter == "NONE" || (attributes && ((filter == "OCTAHEDRAL" && (stride == 4 || stride == 8)) ||
                                                                 (filter == "QUATERNION" && stride == 8) ||
                                                                 filter == "EXPONENTIAL"));
  if (!(attributes || indices) || !strideAllowed || !filterAllowed || (mode == "TRIANGLES" && count % 3 != 0)) {
    fail(ctx, where, std::string(kMeshopt) + " mode '" + oneLine(mode) + "' with filter '" + oneLine(filter) +
                         "', byteStride " + std::to_string(stride) + " and count " + std::to_string(count) +
                         " is not a combination the extension allows; re-export the file");
  }
  const uint64_t decodedSize = uint64_t(count) * uint64_t(stride);
  if (decodedSize != view.byteLength) {
    fail(ctx, where, std::string(kMeshopt) + " decodes to " + std::to_string(decodedSize) +
                         " bytes (count times byteStride) but the view has " + std::to_string(view.byteLength) +
                         "; re-export the file");
  }
  if (decodedSize > kMaxMeshoptRatio * uint64_t(length) + kMeshoptSlack) {
    fail(ctx, where, std::string(kMeshopt) + " claims " + std::to_string(decodedSize) + " bytes from " +
                         std::to_string(length) + ", more than its codecs can compress; the file is damaged: re-export it");
  }
  std::vector<unsigned char> out(decodedSize);
  const unsigned char* source = data.data() + offset;
  const size_t n = static_cast<size_t>(count);
  const size_t size = static_cast<size_t>(stride);
  const int status = attributes            ? meshopt_decodeVertexBuffer(out.data(), n, size, source, size_t(length))
                     : mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), n, size, source, size_t(length))
                                           : meshopt_decodeIndexSequence(out.data(), n, size, source, size_t(length));
  if (status != 0) {
    fail(ctx, where, std::string(kMeshopt) + " data does not decode (meshoptimizer error " + std::to_string(status) +
                         "); the file is damaged: re-export it");
  }
  if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), n, size);
  if (filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), n, size);
  if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), n, size);
  return out;
}

void decodeMeshoptViews(const Context& ctx, tinygltf::Model& model) {
  for (size_t v = 0; v < model.bufferViews.size(); ++v) {
    const auto ext = model.bufferViews[v].extensions.find(kMeshopt);
    if (ext == model.bufferViews[v].extensions.end()) continue;
    const std::string where = describe("buffer view", v, model.bufferViews[v].name);
    std::vector<unsigned char> decoded = decodeMeshoptView(ctx, model, model.bufferViews[v], ext->second, where);
    tinygltf::BufferView& view = model.bufferViews[v];
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteOffset = 0;
    view.extensions.erase(kMeshopt);
    model.buffers.emplace_back().data = std::move(decoded);
  }
}

// Draco's decoded values converted to the accessor's component type.
template <typename T>
void convertPoints(const draco::PointAttribute& attribute, size_t points, int components,
                   std::vector<unsigned char>& out, bool& ok) {
  out.resize(points * components * sizeof(T));
  std::vector<T> value(static_cast<size_t>(components));
  for (size_t p = 0; p < points && ok; ++p) {
    ok = attribute.ConvertValue<T>(attribute.mapped_index(draco::PointIndex(static_cast<uint32_t>(p))),
                                   static_cast<int8_t>(components), value.data());
    std::memcpy(out.data() + p * components * sizeof(T), value.data(), components * sizeof(T));
  }
}

std::vector<unsigned char> attributeBytes(const draco::PointAttribute& attribute, size_t points,
                                          const tinygltf::Accessor& accessor, bool& ok) {
  const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
  std::vector<unsigned char> out;
  ok = components > 0 && components == attribute.num_components();
  if (!ok) return out;
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: convertPoints<float>(attribute, points, components, out, ok); break;
    case TINYGLTF_COMPONENT_TYPE_BYTE: convertPoints<int8_t>(attribute, points, components, out, ok); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: convertPoints<uint8_t>(attribute, points, components, out, ok); break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: convertPoints<int16_t>(attribute, points, components, out, ok); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: convertPoints<uint16_t>(attribute, points, components, out, ok); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: convertPoints<uint32_t>(attribute, points, components, out, ok); break;
    default: ok = false;
  }
  return out;
}

class DracoDecoder {
public:
  DracoDecoder(const Context& ctx, tinygltf::Model& model) : ctx_(ctx), model_(model) {}

  void decodePrimitive(size_t mesh, size_t index) {
    tinygltf::Primitive& primitive = model_.meshes[mesh].primitives[index];
    const auto ext = primitive.extensions.find(kDraco);
    if (ext == primitive.extensions.end()) return;
    const std::string where = describe("mesh", mesh, model_.meshes[mesh].name) + " primitive " + std::to_string(index);
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
      fail(ctx_, where, std::string(kDraco) + " holds triangle lists only, but the primitive's mode is " +
                            std::to_string(primitive.mode) + "; re-export the file");
    }
    const int64_t viewIndex = readCount(ext->second, "bufferView", -1);
    if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model_.bufferViews.size()) {
      fail(ctx_, where, std::string(kDraco) + ".bufferView " +
                            missingIndex(viewIndex, model_.bufferViews.size(), "buffer views") + "; re-export the file");
    }
    const draco::Mesh& decoded = decode(static_cast<int>(viewIndex), where);
    const size_t points = decoded.num_points();
    const tinygltf::Value& attributes = ext->second.Get("attributes");
    if (!attributes.IsObject()) fail(ctx_, where, std::string(kDraco) + ".attributes must be an object; re-export the file");
    for (const std::string& name : attributes.Keys()) {
      const auto accessor = primitive.attributes.find(name);
      const int64_t id = asCount(attributes.Get(name));
      const draco::PointAttribute* attribute =
          id >= 0 && id <= UINT32_MAX ? decoded.GetAttributeByUniqueId(static_cast<uint32_t>(id)) : nullptr;
      if (accessor == primitive.attributes.end() || attribute == nullptr) {
        fail(ctx_, where, std::string(kDraco) + " attribute " + oneLine(name) +
                              (accessor == primitive.attributes.end() ? " is not among the primitive's attributes"
                                                                      : " names no attribute of the Draco data") +
                              "; re-export the file");
      }
      const tinygltf::Accessor& target = accessorAt(accessor->second, where);
      bool ok = false;
      std::vector<unsigned char> bytes = attributeBytes(*attribute, points, target, ok);
      if (!ok) {
        fail(ctx_, where, std::string(kDraco) + " attribute " + oneLine(name) + " has " +
                              std::to_string(attribute->num_components()) +
                              " components that do not convert to its accessor's type; re-export the file");
      }
      redirect(accessor->second, static_cast<int>(viewIndex), std::move(bytes), points, where);
    }
    std::vector<unsigned char> indices(decoded.num_faces() * 3 * sizeof(uint32_t));
    for (uint32_t f = 0; f < decoded.num_faces(); ++f) {
      const draco::Mesh::Face& face = decoded.face(draco::FaceIndex(f));
      for (int k = 0; k < 3; ++k) {
        const uint32_t value = face[k].value();
        std::memcpy(indices.data() + (size_t(f) * 3 + k) * 4, &value, 4);
      }
    }
    // A new accessor: parseGltfFile drops the file's (it has no buffer view, which tinygltf refuses).
    tinygltf::Accessor& indexAccessor = model_.accessors.emplace_back();
    indexAccessor.type = TINYGLTF_TYPE_SCALAR;
    indexAccessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    indexAccessor.count = size_t(decoded.num_faces()) * 3;
    indexAccessor.bufferView = appendView(model_, std::move(indices));
    primitive.indices = static_cast<int>(model_.accessors.size()) - 1;
  }

private:
  const tinygltf::Accessor& accessorAt(int index, const std::string& where) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size()) {
      fail(ctx_, where, "accessor " + missingIndex(index, model_.accessors.size(), "accessors") + "; re-export the file");
    }
    return model_.accessors[static_cast<size_t>(index)];
  }

  const draco::Mesh& decode(int viewIndex, const std::string& where) {
    if (const auto known = meshes_.find(viewIndex); known != meshes_.end()) return *known->second;
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size() ||
        view.byteOffset > model_.buffers[static_cast<size_t>(view.buffer)].data.size() ||
        view.byteLength > model_.buffers[static_cast<size_t>(view.buffer)].data.size() - view.byteOffset) {
      fail(ctx_, where, std::string(kDraco) + " buffer view " + std::to_string(viewIndex) +
                            " lies outside its buffer; the file is damaged: re-export it");
    }
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(model_.buffers[static_cast<size_t>(view.buffer)].data.data() + view.byteOffset),
                view.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&buffer);
    if (!result.ok() || result.value() == nullptr) {
      fail(ctx_, where, std::string(kDraco) + " data in buffer view " + std::to_string(viewIndex) +
                            " does not decode (" +
                            oneLine(result.ok() ? std::string("no mesh") : result.status().error_msg_string()) +
                            "); the file is damaged: re-export it");
    }
    return *(meshes_[viewIndex] = std::move(result).value());
  }

  // Points `accessor` at `bytes` (its `count` decoded elements), once per Draco view.
  void redirect(int accessor, int dracoView, std::vector<unsigned char> bytes, size_t count, const std::string& where) {
    if (const auto done = sourceOf_.find(accessor); done != sourceOf_.end()) {
      if (done->second == dracoView) return;
      fail(ctx_, where, "accessor " + std::to_string(accessor) + " is decoded from two different " + kDraco +
                            " buffer views; re-export the file");
    }
    sourceOf_[accessor] = dracoView;
    tinygltf::Accessor& target = model_.accessors[static_cast<size_t>(accessor)];
    target.bufferView = appendView(model_, std::move(bytes));
    target.byteOffset = 0;
    target.count = count;
    target.sparse.isSparse = false;
  }

  const Context& ctx_;
  tinygltf::Model& model_;
  std::map<int, std::unique_ptr<draco::Mesh>> meshes_;  // by Draco buffer view
  std::map<int, int> sourceOf_;                          // accessor -> the Draco view it was decoded from
};

}  // namespace

void decodeCompressedData(const Context& ctx, tinygltf::Model& model) {
  decodeMeshoptViews(ctx, model);
  DracoDecoder draco(ctx, model);
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) draco.decodePrimitive(m, p);
  }
}

}  // namespace wp::gltf
