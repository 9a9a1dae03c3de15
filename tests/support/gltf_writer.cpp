// Minimal glTF writer for test scenes.
#include "support/gltf_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace wp::test {
std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= bytes[i + 2];
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

namespace {

template <typename T>
size_t append(std::vector<uint8_t>& buffer, const std::vector<T>& data) {
  size_t offset = buffer.size();
  buffer.resize(offset + data.size() * sizeof(T));
  std::memcpy(buffer.data() + offset, data.data(), data.size() * sizeof(T));
  return offset;
}

}  // namespace

std::filesystem::path writeGltf(const TestScene& scene, const std::filesystem::path& file) {
  std::vector<uint8_t> buffer;
  std::ostringstream views, accessors, meshes, nodes, materials;
  // Each accessor has its own buffer view, at the same index.
  size_t next = 0;
  auto addView = [&](size_t offset, size_t length) {
    views << (next ? "," : "") << "{\"buffer\":0,\"byteOffset\":" << offset << ",\"byteLength\":" << length << "}";
    accessors << (next ? "," : "");
    return next++;
  };
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const TestMesh& mesh = scene.meshes[m];
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    size_t position = addView(append(buffer, mesh.positions), mesh.positions.size() * 12);
    accessors << "{\"bufferView\":" << position << ",\"componentType\":5126,\"count\":" << mesh.positions.size()
              << ",\"type\":\"VEC3\",\"min\":[" << lo.x << "," << lo.y << "," << lo.z << "],\"max\":[" << hi.x << ","
              << hi.y << "," << hi.z << "]}";
    size_t index = addView(append(buffer, mesh.indices), mesh.indices.size() * 4);
    accessors << "{\"bufferView\":" << index << ",\"componentType\":5125,\"count\":" << mesh.indices.size()
              << ",\"type\":\"SCALAR\"}";
    std::string attributes = "\"POSITION\":" + std::to_string(position);
    if (!mesh.normals.empty()) {
      size_t normal = addView(append(buffer, mesh.normals), mesh.normals.size() * 12);
      accessors << "{\"bufferView\":" << normal << ",\"componentType\":5126,\"count\":" << mesh.normals.size()
                << ",\"type\":\"VEC3\"}";
      attributes += ",\"NORMAL\":" + std::to_string(normal);
    }
    const char* sep = m ? "," : "";
    meshes << sep << "{\"primitives\":[{\"attributes\":{" << attributes << "},\"indices\":" << index
           << ",\"material\":" << mesh.material << "}]}";
    nodes << sep << "{\"mesh\":" << m << ",\"translation\":[" << mesh.translation.x << "," << mesh.translation.y
          << "," << mesh.translation.z << "]}";
  }
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const TestMaterial& mat = scene.materials[i];
    float strength = std::max({mat.emission.x, mat.emission.y, mat.emission.z});
    glm::vec3 factor = strength > 0.0f ? mat.emission / strength : glm::vec3(0.0f);
    materials << (i ? "," : "") << "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[" << mat.baseColor.x << ","
              << mat.baseColor.y << "," << mat.baseColor.z << ",1],\"metallicFactor\":" << mat.metallic
              << ",\"roughnessFactor\":" << mat.roughness << "},\"emissiveFactor\":[" << factor.x << "," << factor.y
              << "," << factor.z << "],\"doubleSided\":" << (mat.doubleSided ? "true" : "false");
    if (mat.lambert) {
      materials << ",\"extras\":{\"wavepath\":{\"bsdf\":\"lambert\"}}";
    }
    std::ostringstream extensions;
    if (strength > 0.0f) {
      extensions << ",\"KHR_materials_emissive_strength\":{\"emissiveStrength\":" << strength << "}";
    }
    if (mat.ior != 1.5f) {
      extensions << ",\"KHR_materials_ior\":{\"ior\":" << mat.ior << "}";
    }
    if (mat.transmission > 0.0f) {
      extensions << ",\"KHR_materials_transmission\":{\"transmissionFactor\":" << mat.transmission << "}";
    }
    if (mat.attenuationDistance > 0.0f) {
      extensions << ",\"KHR_materials_volume\":{\"attenuationDistance\":" << mat.attenuationDistance
                 << ",\"attenuationColor\":[" << mat.attenuationColor.x << "," << mat.attenuationColor.y << ","
                 << mat.attenuationColor.z << "]}";
    }
    if (!mat.moreExtensions.empty()) {
      extensions << "," << mat.moreExtensions;
    }
    if (!extensions.str().empty()) {
      materials << ",\"extensions\":{" << extensions.str().substr(1) << "}";
    }
    materials << "}";
  }
  float half = glm::radians(scene.camera.yawDegrees) * 0.5f;
  size_t cameraNode = scene.meshes.size();
  size_t rootCount = scene.withCamera ? cameraNode + 1 : cameraNode;
  std::ostringstream json;
  json.precision(9);
  json << "{\"asset\":{\"version\":\"2.0\"},\"extensionsUsed\":[\"KHR_materials_emissive_strength\","
       << "\"KHR_materials_ior\",\"KHR_materials_transmission\",\"KHR_materials_volume\",\"KHR_materials_specular\","
       << "\"KHR_materials_sheen\",\"KHR_materials_clearcoat\",\"KHR_materials_unlit\"],"
       << "\"scene\":0,\"scenes\":[{\"nodes\":[";
  for (size_t i = 0; i < rootCount; ++i) {
    json << (i ? "," : "") << i;
  }
  json << "]}],\"nodes\":[" << nodes.str();
  if (scene.withCamera) {
    json << (cameraNode ? "," : "") << "{\"camera\":0,\"translation\":[" << scene.camera.position.x << ","
         << scene.camera.position.y << "," << scene.camera.position.z << "],\"rotation\":[0," << std::sin(half)
         << ",0," << std::cos(half) << "]}],\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":"
         << scene.camera.yfovRadians << ",\"znear\":0.001}}],";
  } else {
    json << "],";
  }
  json << "\"meshes\":[" << meshes.str() << "],\"materials\":[" << materials.str()
       << "],\"accessors\":[" << accessors.str() << "],\"bufferViews\":[" << views.str()
       << "],\"buffers\":[{\"byteLength\":" << buffer.size()
       << ",\"uri\":\"data:application/octet-stream;base64," << base64(buffer) << "\"}]}";
  std::ofstream(file) << json.str();
  return file;
}

TestMesh icosphere(float radius, int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  TestMesh mesh;
  mesh.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  mesh.indices = {0, 11, 5, 0, 5,  1,  0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
                  3, 9,  4, 3, 4,  2,  3, 2, 6, 3, 6,  8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = midpoints.try_emplace(key, uint32_t(mesh.positions.size()));
      if (inserted) {
        mesh.positions.push_back((mesh.positions[a] + mesh.positions[b]) * 0.5f);
      }
      return it->second;
    };
    std::vector<uint32_t> refined;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
      uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
      uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      refined.insert(refined.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    mesh.indices = refined;
  }
  for (glm::vec3& p : mesh.positions) {
    p = glm::normalize(p) * radius;
  }
  return mesh;
}

}  // namespace wp::test
