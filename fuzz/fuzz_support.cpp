// Scratch files and finiteness checks for the fuzz targets.
#include "fuzz_support.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "bvh/gpu_scene.h"
#include "core/error.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "scene/scene_animation.h"

namespace wp::fuzz {
namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

bool finite(float v) { return std::isfinite(v); }
template <int N, typename T>
bool finite(const glm::vec<N, T>& v) {
  for (int i = 0; i < N; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}
bool finite(const glm::mat4& m) { return finite(m[0]) && finite(m[1]) && finite(m[2]) && finite(m[3]); }

template <typename T>
void checkAll(const std::vector<T>& values, const char* what) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!finite(values[i])) finding(std::string(what) + " " + std::to_string(i) + " is not finite");
  }
}

// The vec4 fields `floatFields` of each `stride`-byte GPU struct in `data` (layout.h); with
// `xyzOnly` their w is left out, as BVH nodes keep child indices there as float bits.
void checkVec4s(const void* data, size_t bytes, const std::vector<int>& floatFields, size_t stride, const char* what,
                bool xyzOnly = false) {
  const auto* words = static_cast<const unsigned char*>(data);
  for (size_t offset = 0; offset + stride <= bytes; offset += stride) {
    for (int field : floatFields) {
      glm::vec4 v;
      std::memcpy(&v, words + offset + 16 * field, 16);
      if (xyzOnly ? !finite(glm::vec3(v)) : !finite(v)) finding(std::string(what) + " " + std::to_string(offset / stride) + " is not finite");
    }
  }
}

void append(std::vector<uint8_t>& out, const void* data, size_t size) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  out.insert(out.end(), bytes, bytes + size);
}

void appendWord(std::vector<uint8_t>& out, uint32_t word) { append(out, &word, 4); }

}  // namespace

std::vector<uint8_t> texturedQuadGlb(const uint8_t* image, size_t imageSize) {
  const float geometry[] = {-1, -1, -2, 1, -1, -2, 1, 1, -2, -1, 1, -2,  // POSITION
                            0,  0,  1,  0, 1,  1,  0, 1};                 // TEXCOORD_0
  const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::vector<uint8_t> bin;
  append(bin, geometry, sizeof(geometry));
  append(bin, indices, sizeof(indices));
  const size_t imageOffset = bin.size();
  append(bin, image, imageSize);
  while (bin.size() % 4 != 0) bin.push_back(0);
  std::string json =
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"indices\":2,\"material\":0}]}],"
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},"
      "\"emissiveTexture\":{\"index\":0},\"emissiveFactor\":[1,1,1],\"normalTexture\":{\"index\":0}}],"
      "\"textures\":[{\"source\":0}],\"images\":[{\"bufferView\":3,\"mimeType\":\"image/png\"}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
      "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
      "{\"bufferView\":2,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],"
      "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":48,\"byteLength\":32},"
      "{\"buffer\":0,\"byteOffset\":80,\"byteLength\":12},{\"buffer\":0,\"byteOffset\":" +
      std::to_string(imageOffset) + ",\"byteLength\":" + std::to_string(imageSize) + "}],\"buffers\":[{\"byteLength\":" +
      std::to_string(bin.size()) + "}]}";
  while (json.size() % 4 != 0) json += ' ';
  std::vector<uint8_t> glb;
  append(glb, "glTF", 4);
  appendWord(glb, 2);
  appendWord(glb, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  appendWord(glb, uint32_t(json.size()));
  append(glb, "JSON", 4);
  append(glb, json.data(), json.size());
  appendWord(glb, uint32_t(bin.size()));
  append(glb, "BIN\0", 4);
  append(glb, bin.data(), bin.size());
  return glb;
}

std::filesystem::path writeInput(const char* name, const uint8_t* data, size_t size) {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() / ("wavepath-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  std::filesystem::path file = dir / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return file;
}

void checkFinite(const EnvironmentMap& sky) {
  checkAll(sky.radiance, "sky texel");
  checkAll(sky.marginalCdf, "sky row cdf entry");
  checkAll(sky.conditionalCdf, "sky column cdf entry");
  if (!std::isfinite(sky.luminanceIntegral)) finding("the sky's luminance integral is not finite");
}

void checkFinite(const Scene& scene, const GpuScene& gpu) {
  for (const Mesh& mesh : scene.meshes) {
    checkAll(mesh.positions, "vertex position");
    checkAll(mesh.normals, "vertex normal");
    checkAll(mesh.uvs, "vertex uv");
    checkAll(mesh.tangents, "vertex tangent");
  }
  for (const Material& m : scene.materials) {
    if (!finite(m.baseColor) || !finite(m.emission) || !finite(m.alpha) || !finite(m.metallic) ||
        !finite(m.roughness) || !finite(m.ior) || !finite(m.transmission) || !finite(m.attenuationColor) ||
        !finite(m.attenuationDistance) || !finite(m.normalScale)) {
      finding("material '" + m.name + "' has a number that is not finite");
    }
  }
  for (const MeshInstance& instance : scene.instances) {
    if (!finite(instance.objectToWorld)) finding("an instance transform is not finite");
  }
  const Camera& c = scene.camera;
  if (!finite(c.position) || !finite(c.forward) || !finite(c.up) || !finite(c.yfov) || !finite(c.aspectRatio)) {
    finding("the camera is not finite");
  }
  checkFinite(scene.sky);
  checkVec4s(gpu.nodes.data(), gpu.nodes.size() * sizeof(gpu::BvhNode), {0, 1, 2, 3}, sizeof(gpu::BvhNode), "BVH node",
             true);
  checkVec4s(gpu.triangles.data(), gpu.triangles.size() * sizeof(gpu::GpuTriangle), {0, 1, 2},
             sizeof(gpu::GpuTriangle), "triangle");
  checkVec4s(gpu.instances.data(), gpu.instances.size() * sizeof(gpu::GpuInstance), {0, 1, 2},
             sizeof(gpu::GpuInstance), "instance");
  checkVec4s(gpu.materials.data(), gpu.materials.size() * sizeof(gpu::GpuMaterial), {0, 1, 2, 3, 5},
             sizeof(gpu::GpuMaterial), "material");
  checkVec4s(gpu.lights.data(), gpu.lights.size() * sizeof(gpu::GpuLight), {0, 1, 2, 3}, sizeof(gpu::GpuLight),
             "light");
}

void loadAndCheck(const std::filesystem::path& file) {
  try {
    Scene scene = loadScene(file);
    if (scene.animation) scene = poseSceneOverShutter(scene, 0.5, 0.01);
    checkFinite(scene, packScene(scene));
  } catch (const Error&) {
    // One line of bad input: what the loader should say.
  }
}

}  // namespace wp::fuzz
