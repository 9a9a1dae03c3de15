// One glTF mesh (all its primitives) to one wavepath triangle mesh.
#include "scene/gltf_mesh.h"

#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "scene/gltf_accessors.h"
#include "scene/gltf_variants.h"

namespace wp::gltf {

namespace {

const char* modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
    default: return "unknown";
  }
}

// Three vertex references per triangle, in the order the glTF specification gives for each
// mode, so that counter-clockwise front faces survive the conversion of strips and fans.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& v, int mode) {
  std::vector<uint32_t> out;
  if (mode == TINYGLTF_MODE_TRIANGLES) return v;
  for (size_t i = 0; i + 2 < v.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
    } else {
      out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
    }
  }
  return out;
}

// The accessors a primitive's vertices come from; primitives with the same ones share them.
struct VertexSource {
  int position = -1;
  int normal = -1;   // -1: none
  int uv = -1;       // TEXCOORD_0, -1: none
  int uv1 = -1;      // TEXCOORD_1, -1: none
  int color = -1;    // COLOR_0, -1: none
  int tangent = -1;  // TANGENT, -1: none (also when there is no NORMAL: glTF then ignores it)
  // With morph targets or skins, the primitive: its targets and joints are read with its
  // vertices, so its vertices are shared with no other primitive. -1 otherwise.
  int primitive = -1;

  bool operator<(const VertexSource& other) const {
    return std::tie(position, normal, uv, uv1, color, tangent, primitive) <
           std::tie(other.position, other.normal, other.uv, other.uv1, other.color, other.tangent, other.primitive);
  }
};

// Where the vertices of one VertexSource lie in the mesh being built.
struct VertexRange {
  uint32_t first = 0;
  uint32_t count = 0;
};

class MeshBuilder {
public:
  MeshBuilder(const Context& ctx, size_t meshIndex, uint32_t defaultMaterial, MeshDeformation* deformation,
              size_t morphTargets)
      : ctx_(ctx), gltfMesh_(ctx.model.meshes[meshIndex]), defaultMaterial_(defaultMaterial),
        deformation_(deformation) {
    where_ = describe("mesh", meshIndex, gltfMesh_.name);
    mesh_.name = gltfMesh_.name;
    if (deformation_) deformation_->targets.resize(morphTargets);
  }

  Mesh build() {
    for (size_t p = 0; p < gltfMesh_.primitives.size(); ++p) addPrimitive(p);
    if (!skipped_.empty()) {
      warnAt(ctx_, where_, "skipped primitive" + std::string(skippedCount_ > 1 ? "s " : " ") + skipped_ +
                               ": wavepath renders triangles only");
    }
    return std::move(mesh_);
  }

private:
  void skip(size_t primitive, const std::string& why) {
    skipped_ += (skipped_.empty() ? "" : ", ") + std::to_string(primitive) + " (" + why + ")";
    ++skippedCount_;
  }

  void addPrimitive(size_t p) {
    const tinygltf::Primitive& primitive = gltfMesh_.primitives[p];
    const std::string where = where_ + " primitive " + std::to_string(p);
    const int mode = primitive.mode;
    if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN) {
      fail(ctx_, where, "mode " + std::to_string(mode) + " is not a glTF primitive mode (0 to 6); re-export the file");
    }
    if (mode < TINYGLTF_MODE_TRIANGLES) return skip(p, modeName(mode));
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) return skip(p, "no POSITION");

    const uint32_t material = materialOf(primitive, where);
    const auto normal = primitive.attributes.find("NORMAL");
    const auto uv = primitive.attributes.find("TEXCOORD_0");
    const auto uv1 = primitive.attributes.find("TEXCOORD_1");
    const auto color = primitive.attributes.find("COLOR_0");
    const auto tangent = primitive.attributes.find("TANGENT");
    const bool hasNormal = normal != primitive.attributes.end();
    const VertexSource source{position->second, hasNormal ? normal->second : -1,
                              uv == primitive.attributes.end() ? -1 : uv->second,
                              uv1 == primitive.attributes.end() ? -1 : uv1->second,
                              color == primitive.attributes.end() ? -1 : color->second,
                              hasNormal && tangent != primitive.attributes.end() ? tangent->second : -1,
                              deformation_ ? static_cast<int>(p) : -1};
    const uint32_t vertexCount = addVertices(source, where);
    if (deformation_) addDeformation(primitive, vertexCount, where);
    std::vector<uint32_t> sequence;
    if (primitive.indices == -1) {
      sequence.resize(vertexCount);
      std::iota(sequence.begin(), sequence.end(), 0u);
    } else {
      sequence = readIndices(ctx_, primitive.indices, where);
      for (uint32_t index : sequence) {
        if (index >= vertexCount) {
          fail(ctx_, where,
               "index " + std::to_string(index) + " is out of range (the POSITION accessor has " +
                   std::to_string(vertexCount) + " vertices); re-export the file");
        }
      }
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && sequence.size() % 3 != 0) {
      fail(ctx_, where,
           "a TRIANGLES primitive needs a multiple of 3 vertices, not " + std::to_string(sequence.size()) +
               "; re-export the file");
    }
    const uint32_t base = verticesOf_.at(source).first;
    for (uint32_t v : triangulate(sequence, mode)) mesh_.indices.push_back(base + v);
    mesh_.materials.resize(mesh_.indices.size() / 3, material);
  }

  uint32_t materialOf(const tinygltf::Primitive& primitive, const std::string& where) const {
    const int material = variantMaterial(ctx_, primitive, ctx_.variant, where);
    if (material == -1) return defaultMaterial_;
    if (material < 0 || static_cast<size_t>(material) >= ctx_.model.materials.size()) {
      fail(ctx_, where,
           "material " + missingIndex(material, ctx_.model.materials.size(), "materials") + "; re-export the file");
    }
    return static_cast<uint32_t>(material);
  }

  // Appends the `count` vertices' texture coordinates from `accessor` (zero where it is -1)
  // to `target`, once a primitive of the mesh has them.
  void addTexCoords(int accessor, const char* name, size_t count, const std::string& where,
                    std::vector<glm::vec2>& target) {
    if (accessor < 0 && target.empty()) return;
    std::vector<glm::vec2> uvs(count, glm::vec2(0.0f));
    if (accessor >= 0) {
      uvs = readTexCoords(ctx_, accessor, where, name);
      if (uvs.size() != count) {
        fail(ctx_, where,
             std::string(name) + " has " + std::to_string(uvs.size()) + " vertices but POSITION " +
                 std::to_string(count) + "; re-export the file");
      }
    }
    target.resize(mesh_.positions.size() - count, glm::vec2(0.0f));
    target.insert(target.end(), uvs.begin(), uvs.end());
  }

  // Appends the vertices of a POSITION (and NORMAL) accessor pair once per mesh (primitives
  // often share one vertex buffer) and returns its vertex count, as read (so checked).
  uint32_t addVertices(const VertexSource& source, const std::string& where) {
    if (const auto known = verticesOf_.find(source); known != verticesOf_.end()) return known->second.count;
    const std::vector<glm::vec3> positions = readVec3Attribute(ctx_, source.position, where, "POSITION");
    if (positions.size() > std::numeric_limits<uint32_t>::max() - mesh_.positions.size()) {
      fail(ctx_, where, "the mesh has more vertices than 32-bit indices can address; split the mesh");
    }
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    if (source.normal >= 0) {
      normals = readVec3Attribute(ctx_, source.normal, where, "NORMAL");
      if (normals.size() != positions.size()) {
        fail(ctx_, where,
             "NORMAL has " + std::to_string(normals.size()) + " vertices but POSITION " +
                 std::to_string(positions.size()) + "; re-export the file");
      }
      // Exporters leave some normals unnormalized or zero; zero ones shade flat.
      for (glm::vec3& n : normals) {
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f);
      }
      mesh_.normals.resize(mesh_.positions.size(), glm::vec3(0.0f));
    }
    const auto count = static_cast<uint32_t>(positions.size());
    verticesOf_[source] = {static_cast<uint32_t>(mesh_.positions.size()), count};
    mesh_.positions.insert(mesh_.positions.end(), positions.begin(), positions.end());
    if (source.normal >= 0 || !mesh_.normals.empty()) {
      mesh_.normals.insert(mesh_.normals.end(), normals.begin(), normals.end());
    }
    addTexCoords(source.uv, "TEXCOORD_0", positions.size(), where, mesh_.uvs);
    addTexCoords(source.uv1, "TEXCOORD_1", positions.size(), where, mesh_.uvs1);
    if (source.color >= 0 || !mesh_.colors.empty()) {
      std::vector<glm::vec4> colors(positions.size(), glm::vec4(1.0f));
      if (source.color >= 0) {
        colors = readColors(ctx_, source.color, where);
        if (colors.size() != positions.size()) {
          fail(ctx_, where,
               "COLOR_0 has " + std::to_string(colors.size()) + " vertices but POSITION " +
                   std::to_string(positions.size()) + "; re-export the file");
        }
      }
      mesh_.colors.resize(mesh_.positions.size() - positions.size(), glm::vec4(1.0f));
      mesh_.colors.insert(mesh_.colors.end(), colors.begin(), colors.end());
    }
    if (source.tangent >= 0 || !mesh_.tangents.empty()) {
      std::vector<glm::vec4> tangents(positions.size(), glm::vec4(0.0f));
      if (source.tangent >= 0) {
        tangents = readTangents(ctx_, source.tangent, where);
        if (tangents.size() != positions.size()) {
          fail(ctx_, where,
               "TANGENT has " + std::to_string(tangents.size()) + " vertices but POSITION " +
                   std::to_string(positions.size()) + "; re-export the file");
        }
        // Unit xyz and a sign of exactly +-1, as glTF requires but exporters do not always
        // write; zero ones stay zero (a triangle with three falls back to its uv gradient).
        for (glm::vec4& t : tangents) {
          const float length = glm::length(glm::vec3(t));
          t = length > 0.0f ? glm::vec4(glm::vec3(t) / length, t.w < 0.0f ? -1.0f : 1.0f) : glm::vec4(0.0f);
        }
      }
      mesh_.tangents.resize(mesh_.positions.size() - positions.size(), glm::vec4(0.0f));
      mesh_.tangents.insert(mesh_.tangents.end(), tangents.begin(), tangents.end());
    }
    return count;
  }

  // Appends the primitive's morph target deltas and skin weights for its `count` vertices.
  void addDeformation(const tinygltf::Primitive& primitive, uint32_t count, const std::string& where) {
    for (size_t t = 0; t < deformation_->targets.size(); ++t) {
      MorphTarget& target = deformation_->targets[t];
      const std::string targetWhere = where + " morph target " + std::to_string(t);
      appendDelta(primitive.targets[t], "POSITION", count, targetWhere, target.positions);
      appendDelta(primitive.targets[t], "NORMAL", count, targetWhere, target.normals);
    }
    const auto joints = primitive.attributes.find("JOINTS_0");
    const auto weights = primitive.attributes.find("WEIGHTS_0");
    std::vector<glm::uvec4> j(count, glm::uvec4(0));
    std::vector<glm::vec4> w(count, glm::vec4(0.0f));
    if (joints != primitive.attributes.end() && weights != primitive.attributes.end()) {
      j = readJoints(ctx_, joints->second, where);
      const FloatElements read = readFloats(ctx_, weights->second, where, "WEIGHTS_0", true);
      if (read.components != 4 || j.size() != count || read.values.size() != 4 * size_t(count)) {
        fail(ctx_, where, "JOINTS_0 and WEIGHTS_0 need one VEC4 per vertex (" + std::to_string(count) +
                              "); re-export the skin");
      }
      for (size_t v = 0; v < count; ++v) {
        const glm::vec4 vw(read.values[4 * v], read.values[4 * v + 1], read.values[4 * v + 2], read.values[4 * v + 3]);
        const float sum = vw.x + vw.y + vw.z + vw.w;
        // Exporters quantize weights, so their sum drifts from 1; glTF asks for a sum of 1.
        w[v] = sum > 0.0f ? vw / sum : glm::vec4(0.0f);
      }
    }
    deformation_->joints.insert(deformation_->joints.end(), j.begin(), j.end());
    deformation_->jointWeights.insert(deformation_->jointWeights.end(), w.begin(), w.end());
  }

  void appendDelta(const std::map<std::string, int>& target, const char* attribute, uint32_t count,
                   const std::string& where, std::vector<glm::vec3>& out) {
    const auto found = target.find(attribute);
    std::vector<glm::vec3> delta(count, glm::vec3(0.0f));
    if (found != target.end()) {
      delta = readVec3Attribute(ctx_, found->second, where, attribute);
      if (delta.size() != count) {
        fail(ctx_, where,
             std::string(attribute) + " has " + std::to_string(delta.size()) + " vertices but the primitive " +
                 std::to_string(count) + "; re-export the morph target");
      }
    }
    out.insert(out.end(), delta.begin(), delta.end());
  }

  const Context& ctx_;
  const tinygltf::Mesh& gltfMesh_;
  const uint32_t defaultMaterial_;
  MeshDeformation* deformation_;  // null: rigid
  std::string where_;
  Mesh mesh_;
  std::map<VertexSource, VertexRange> verticesOf_;
  std::string skipped_;
  size_t skippedCount_ = 0;
};

}  // namespace

Mesh convertMesh(const Context& ctx, size_t index, uint32_t defaultMaterial, MeshDeformation* deformation,
                 size_t morphTargets) {
  return MeshBuilder(ctx, index, defaultMaterial, deformation, morphTargets).build();
}

}  // namespace wp::gltf
