// Packs a wp::Scene into the GPU buffers of layout.h: one bottom-level BVH per mesh shared by
// its instances, a top-level BVH over the instances, and the power-proportional light table.
#include "bvh/gpu_scene.h"
#include "bvh/gpu_scene_parts.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>

#include "bvh/bvh_builder.h"
#include "bvh/instance_motion.h"
#include "bvh/light_emission.h"
#include "core/error.h"
#include "core/log.h"
#include "scene/scene_limits.h"
#include "shaders/common/environment.h"
#include "shaders/common/traverse.h"

namespace wp {
namespace {

constexpr uint32_t kMeshLeafSize = WP_MAX_LEAF_TRIANGLES;
// One instance per top-level leaf: an instance test (transform plus a whole bottom-level
// traversal) costs far more than a node visit.
constexpr uint32_t kInstanceLeafSize = 1;

using Clock = std::chrono::steady_clock;

using gpu::luminance;

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

gpu::GpuInstance makeInstance(const glm::mat4& worldToObject, uint32_t kind, uint32_t bvhRootOrMaterial) {
  // glm matrices are column-major: row r is (m[0][r], m[1][r], m[2][r], m[3][r]).
  glm::mat4 rows = glm::transpose(worldToObject);
  return gpu::makeGpuInstance(rows[0], rows[1], rows[2], kind, bvhRootOrMaterial);
}

// Fills the lights' pmf and alias table with Vose's method, in
// double so the table reproduces the pmf to float precision. Zero total power (impossible
// for emissive triangles of positive area, unless it underflows) falls back to uniform.
void buildLightTable(std::vector<gpu::GpuLight>& lights, const std::vector<double>& power) {
  size_t n = lights.size();
  if (n == 0) {
    return;
  }
  double total = 0.0;
  for (double p : power) {
    total += p;
  }
  bool uniform = !(total > 0.0) || !std::isfinite(total);
  std::vector<double> scaled(n);
  std::vector<uint32_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    double pmf = uniform ? 1.0 / static_cast<double>(n) : power[i] / total;
    lights[i] = gpu::withPowerProbability(lights[i], static_cast<float>(pmf));
    scaled[i] = pmf * static_cast<double>(n);
    (scaled[i] < 1.0 ? small : large).push_back(static_cast<uint32_t>(i));
  }
  while (!small.empty() && !large.empty()) {
    uint32_t s = small.back();
    small.pop_back();
    uint32_t l = large.back();
    large.pop_back();
    lights[s] = gpu::withAliasEntry(lights[s], static_cast<float>(scaled[s]), l);
    scaled[l] = (scaled[l] + scaled[s]) - 1.0;
    (scaled[l] < 1.0 ? small : large).push_back(l);
  }
  // What is left has probability 1/n up to rounding: it always keeps itself.
  for (const std::vector<uint32_t>* rest : {&small, &large}) {
    for (uint32_t i : *rest) {
      lights[i] = gpu::withAliasEntry(lights[i], 1.0f, i);
    }
  }
}

using Triangle = std::array<glm::vec3, 3>;

Triangle triangleOf(const Mesh& mesh, size_t t) {
  return {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
          mesh.positions[mesh.indices[3 * t + 2]]};
}

uint32_t textureIndex(int index) { return index < 0 ? WP_INVALID : uint32_t(index); }

uint32_t gpuMaterialKind(Material::Bsdf bsdf) {
  switch (bsdf) {
    case Material::Bsdf::Lambert: return WP_MATERIAL_LAMBERT;
    case Material::Bsdf::GltfDisneyDiffuse: return WP_MATERIAL_GLTF_DISNEY_DIFFUSE;
    case Material::Bsdf::Unlit: return WP_MATERIAL_UNLIT;
    case Material::Bsdf::Gltf: break;
  }
  return WP_MATERIAL_GLTF;
}

uint32_t gpuAlphaMode(Material::AlphaMode mode) {
  switch (mode) {
    case Material::AlphaMode::Mask: return WP_ALPHA_MASK;
    case Material::AlphaMode::Blend: return WP_ALPHA_BLEND;
    case Material::AlphaMode::Opaque: break;
  }
  return WP_ALPHA_OPAQUE;
}

void packTextures(const Scene& scene, GpuScene& out) {
  for (const Texture& texture : scene.textures) {
    const glm::mat3& m = texture.uvTransform;  // column-major: m[column][row]
    out.textures.push_back(gpu::withTexCoords(
        gpu::makeGpuTexture(uint32_t(out.texels.size()), texture.width, texture.height, uint32_t(texture.wrapS),
                            uint32_t(texture.wrapT), texture.srgb, texture.nearest),
        texture.texCoord == 1, glm::vec3(m[0][0], m[1][0], m[2][0]), glm::vec3(m[0][1], m[1][1], m[2][1])));
    out.texels.insert(out.texels.end(), texture.rgba.begin(), texture.rgba.end());
  }
  // The Vulkan texel view reads four texels per RGBA32UI element.
  out.texels.resize((out.texels.size() + 3) / 4 * 4, 0u);
}

// A textured emitter whose texture is black where the estimate looked keeps this fraction of
// its factor's selection weight: the estimate may miss bright texels, and a light that can
// never be sampled would be lost to next event estimation alone.
constexpr float kMinimumTextureShare = 1e-3f;

double seconds(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Vertex normals, TEXCOORD_0 and _1, COLOR_0 and TANGENT of triangle t (zero normals, uvs
// and tangents, white, where the mesh has none).
gpu::GpuTriangleShading shadingOf(const Mesh& mesh, size_t t) {
  const uint32_t* corner = &mesh.indices[3 * t];
  auto normal = [&](int k) { return mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[corner[k]]; };
  auto uv = [&](int k) { return mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[corner[k]]; };
  auto color = [&](int k) {
    const glm::vec4 c = mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[corner[k]];
    const glm::uvec4 bytes = glm::uvec4(glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f));
    return bytes.r | (bytes.g << 8u) | (bytes.b << 16u) | (bytes.a << 24u);
  };
  auto tangent = [&](int k) { return mesh.tangents.empty() ? glm::vec4(0.0f) : mesh.tangents[corner[k]]; };
  gpu::GpuTriangleShading shading =
      gpu::makeGpuTriangleShading(normal(0), normal(1), normal(2), uv(0), uv(1), uv(2), !mesh.uvs.empty(), color(0),
                                  color(1), color(2), tangent(0), tangent(1), tangent(2));
  if (mesh.uvs1.empty()) return shading;
  return gpu::withTexCoord1(shading, mesh.uvs1[corner[0]], mesh.uvs1[corner[1]], mesh.uvs1[corner[2]]);
}

bool isInvertible(const glm::mat4& toWorld) {
  glm::mat4 toObject = glm::inverse(toWorld);
  bool invertible = glm::determinant(toWorld) != 0.0f;
  for (int col = 0; col < 4 && invertible; ++col) {
    invertible = isFinite(glm::vec3(toObject[col])) && std::isfinite(toObject[col].w);
  }
  return invertible;
}

// Instances before the top-level build: their GPU record, world bounds (over the shutter
// for moving ones), motion keys and source.
// Throws wp::Error when `bounds` (of `what`, in world space) reach beyond ±kMaxCoordinate or
// are not finite: transforms that place an object that far (a node scaled by 1e20, say)
// would overflow the traversal's arithmetic.
void checkWithinReach(const Aabb& bounds, const std::string& what) {
  const glm::vec3 lo = glm::abs(bounds.min), hi = glm::abs(bounds.max);
  const float reach = std::max({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
  if (!(reach <= kMaxCoordinate)) {
    char text[64];
    std::snprintf(text, sizeof(text), " reaches coordinate %g", double(reach));
    throw Error(what + text +
                ", beyond the ±1e12 scene units wavepath traces; fix the transforms that place it (or the animation "
                "that moves it)");
  }
}

struct InstanceCandidates {
  std::vector<gpu::GpuInstance> records;
  std::vector<Aabb> worldBounds;
  std::vector<std::string> names;  // for messages: "instance 3 of mesh 'Cube'"
  std::vector<uint32_t> mesh;  // WP_INVALID for spheres
  std::vector<glm::mat4> objectToWorld;
  std::vector<std::optional<MotionKeys>> motion;

  void add(const glm::mat4& toWorld, const std::optional<glm::mat4>& toWorldAtClose, const Aabb& objectBounds,
           uint32_t kind, uint32_t bvhRootOrMaterial, uint32_t meshIndex, const std::string& what) {
    if (!isInvertible(toWorld)) {
      warn(what + " has a singular transform (a zero scale?) and is left out");
      return;
    }
    std::optional<MotionKeys> keys;
    if (toWorldAtClose) {
      // The interpolation from one orientation to the other would pass through a singular
      // transform, where the object-space ray is undefined.
      if (!isInvertible(*toWorldAtClose) || glm::determinant(toWorld) * glm::determinant(*toWorldAtClose) <= 0.0f) {
        warn(what + " turns inside out or singular during the shutter; it is rendered still, as at shutter open");
      } else {
        keys = makeMotionKeys(toWorld, *toWorldAtClose);
      }
    }
    records.push_back(makeInstance(glm::inverse(toWorld), kind, bvhRootOrMaterial));
    worldBounds.push_back(keys ? sweptBounds(*keys, objectBounds) : transformBox(toWorld, objectBounds));
    names.push_back(what);
    mesh.push_back(meshIndex);
    objectToWorld.push_back(toWorld);
    motion.push_back(keys);
  }
};

// Appends the world-space lights of one mesh instance and their selection weights: power
// (flux, by luminance), from the triangle's mean emission (so black parts of an emissive
// texture get few samples): pi * luminance * area per emitting side.
void appendLights(const Scene& scene, const Mesh& mesh, const std::vector<pack_detail::Emitter>& emitters,
                  const glm::mat4& toWorld, std::vector<gpu::GpuLight>& lights, std::vector<double>& power) {
  for (const pack_detail::Emitter& emitter : emitters) {
    Triangle v = triangleOf(mesh, emitter.triangle);
    for (glm::vec3& p : v) {
      p = glm::vec3(toWorld * glm::vec4(p, 1.0f));
    }
    const Material& material = scene.materials[mesh.materials[emitter.triangle]];
    float area = 0.5f * glm::length(glm::cross(v[1] - v[0], v[2] - v[0]));
    lights.push_back(gpu::makeTriangleLight(v[0], v[1], v[2], area, material.emission, emitter.weight,
                                            material.doubleSided, emitter.packed,
                                            textureIndex(material.emissiveTexture)));
    power.push_back(std::numbers::pi * emitter.weight * area * (material.doubleSided ? 2.0 : 1.0));
  }
}

// The flux (by luminance) of a punctual light, its weight in the light table: a point light
// 4 pi I; a spot I times the solid angle its falloff weighs, 2 pi (1 - cos_o - 2/3 d) with
// d = cos_i - cos_o (the integral of the extension's ((cos - cos_o) / d)^2 over the cone's
// rim, as spotFalloff keeps d from vanishing); a directional light E through the scene's
// bounding disc, pi r^2 E, as the sky's power is counted.
double punctualFlux(const PunctualLight& light, double sceneRadius) {
  const double intensity = luminance(light.intensity);
  switch (light.kind) {
    case PunctualLight::Kind::Point: return 4.0 * std::numbers::pi * intensity;
    case PunctualLight::Kind::Spot: {
      const double cosOuter = std::cos(double(light.outerConeAngle));
      const double rim = std::max(std::cos(double(light.innerConeAngle)) - cosOuter, 1e-3);
      return 2.0 * std::numbers::pi * intensity * std::max(1.0 - cosOuter - 2.0 / 3.0 * rim, 0.0);
    }
    case PunctualLight::Kind::Directional: return std::numbers::pi * sceneRadius * sceneRadius * intensity;
  }
  return 0.0;
}

uint32_t gpuLightKind(PunctualLight::Kind kind) {
  switch (kind) {
    case PunctualLight::Kind::Point: return WP_LIGHT_POINT;
    case PunctualLight::Kind::Spot: return WP_LIGHT_SPOT;
    case PunctualLight::Kind::Directional: break;
  }
  return WP_LIGHT_DIRECTIONAL;
}

// Appends the scene's punctual lights after the triangles, with where they are at shutter open
// and close (lights.h interpolates between) and their flux.
void appendPunctualLights(const Scene& scene, double sceneRadius, std::vector<gpu::GpuLight>& lights,
                          std::vector<double>& power) {
  for (const PunctualLight& light : scene.lights) {
    PunctualLight closed = light;
    closed.lightToWorld = light.lightToWorldAtClose.value_or(light.lightToWorld);
    const bool spot = light.kind == PunctualLight::Kind::Spot;
    lights.push_back(gpu::makePunctualLight(gpuLightKind(light.kind), light.position(), closed.position(),
                                            light.direction(), closed.direction(),
                                            spot ? std::cos(light.outerConeAngle) : 0.0f,
                                            spot ? std::cos(light.innerConeAngle) : 1.0f, light.intensity,
                                            luminance(light.intensity)));
    power.push_back(punctualFlux(light, sceneRadius));
  }
}

// Uploads the sky (a black texel, never sampled, without one).
void packSky(const Scene& scene, GpuScene& out) {
  EnvironmentMap sky = scene.sky.width > 0 ? scene.sky : makeEnvironmentMap(1, 1, {glm::vec3(0.0f)});
  out.skyRadiance = sky.radiance;
  out.skyMarginal = sky.marginalCdf;
  out.skyConditional = sky.conditionalCdf;
  out.sky = gpu::makeEnvironment(sky.width, sky.height, scene.skyIntensity, scene.skyRotation);
}

// The radius of the sphere around the instances' bounds (1 without instances), across which
// the sky's and a directional light's power are counted.
double sceneRadius(const GpuScene& out) {
  const double radius = 0.5 * glm::length(out.boundsMax - out.boundsMin);
  return radius > 0.0 ? radius : 1.0;
}

// Sets the probability that next event estimation samples the sky rather than the light
// table: in proportion to power, the sky's through the scene's bounding sphere against the
// lights' flux.
void setSkyProbability(const Scene& scene, double lightFlux, GpuScene& out) {
  double skyPower = scene.sky.width > 0 ? environmentPower(scene.sky, scene.skyIntensity, sceneRadius(out)) : 0.0;
  double total = skyPower + lightFlux;
  out.sky.selectionProbability = total > 0.0 ? static_cast<float>(skyPower / total) : 0.0f;
}

}  // namespace

namespace pack_detail {

MeshPrimitives meshPrimitives(const Scene& scene, const Mesh& mesh) {
  MeshPrimitives prims;
  size_t n = mesh.triangleCount();
  prims.bounds.resize(n);
  prims.centroids.resize(n);
  prims.ordinal.assign(n, WP_INVALID);
  for (size_t t = 0; t < n; ++t) {
    Triangle v = triangleOf(mesh, t);
    for (const glm::vec3& p : v) {
      prims.bounds[t].grow(p);
    }
    prims.centroids[t] = (v[0] + v[1] + v[2]) * (1.0f / 3.0f);
    glm::vec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
    bool degenerate = !(glm::dot(normal, normal) > 0.0f) || !isFinite(normal);
    if (scene.materials[mesh.materials[t]].isEmissive() && !degenerate) {
      prims.ordinal[t] = static_cast<uint32_t>(prims.emitters.size());
      prims.emitters.push_back({static_cast<uint32_t>(t)});
    }
  }
  return prims;
}

Bvh buildMeshBvh(const MeshPrimitives& prims) {
  BvhBuildOptions options;
  options.maxLeafSize = kMeshLeafSize;
  options.maxDepth = WP_BVH_MAX_DEPTH;
  return buildBvh(prims.bounds, prims.centroids, options);
}

void writeTriangles(const Scene& scene, const Mesh& mesh, const Bvh& bvh, MeshPrimitives& prims,
                    uint32_t firstTriangle, GpuScene& out) {
  for (size_t i = 0; i < bvh.primIndices.size(); ++i) {
    uint32_t t = bvh.primIndices[i];
    Triangle v = triangleOf(mesh, t);
    const gpu::GpuTriangleShading shading = shadingOf(mesh, t);
    const uint32_t packed = firstTriangle + static_cast<uint32_t>(i);
    if (prims.ordinal[t] != WP_INVALID) {
      const Material& material = scene.materials[mesh.materials[t]];
      Emitter& emitter = prims.emitters[prims.ordinal[t]];
      emitter.packed = packed;
      glm::vec3 mean = meanEmission(out.textures, out.texels, shading, material.emission,
                                    textureIndex(material.emissiveTexture));
      emitter.weight = std::max(luminance(mean), kMinimumTextureShare * luminance(material.emission));
    }
    out.triangles[packed] =
        gpu::withTriangleAlphaTested(gpu::makeGpuTriangle(v[0], v[1], v[2], mesh.materials[t], prims.ordinal[t]),
                                     scene.materials[mesh.materials[t]].isAlphaTested());
    out.triangleShading[packed] = shading;
  }
}

InstanceLevelSeconds packInstances(const Scene& scene, std::span<const PackedMesh> meshes, GpuScene& out) {
  InstanceLevelSeconds time;
  auto start = Clock::now();
  InstanceCandidates candidates;
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const MeshInstance& inst = scene.instances[i];
    const GpuMeshRange& range = out.meshes[inst.mesh];
    if (range.triangleCount > 0) {
      candidates.add(inst.objectToWorld, inst.objectToWorldAtClose, meshes[inst.mesh].bounds,
                     WP_INSTANCE_MESH, range.rootNode, inst.mesh,
                     "instance " + std::to_string(i) + " of mesh '" + scene.meshes[inst.mesh].name + "'");
    }
  }
  Aabb unitCube{glm::vec3(-1.0f), glm::vec3(1.0f)};
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    candidates.add(scene.spheres[i].objectToWorld, scene.spheres[i].objectToWorldAtClose, unitCube,
                   WP_INSTANCE_SPHERE, scene.spheres[i].material, WP_INVALID,
                   "sphere " + std::to_string(i));
  }

  std::vector<glm::vec3> centers;
  Aabb sceneBounds;
  for (size_t i = 0; i < candidates.worldBounds.size(); ++i) {
    const Aabb& b = candidates.worldBounds[i];
    checkWithinReach(b, candidates.names[i]);
    centers.push_back(b.center());
    sceneBounds.grow(b);
  }
  out.boundsMin = sceneBounds.isEmpty() ? glm::vec3(0.0f) : sceneBounds.min;
  out.boundsMax = sceneBounds.isEmpty() ? glm::vec3(0.0f) : sceneBounds.max;
  BvhBuildOptions options;
  options.maxLeafSize = kInstanceLeafSize;
  options.maxDepth = WP_BVH_MAX_DEPTH;
  Bvh tlas = buildBvh(candidates.worldBounds, centers, options);
  out.tlasRoot = appendWideNodes(tlas, collapseToWide(tlas), 0, out.nodes);
  time.tlas = seconds(start);

  // Instances in top-level leaf order, each still mesh instance followed by its block of
  // lights. A moving instance's emitters are not light-sampled: the table holds world-space
  // triangles at one time, which would put the light where the path's time does not see
  // it. They stay emitters that BSDF sampling finds (MIS weight 1, light pdf 0), so the
  // image stays unbiased at the cost of the noise of unsampled lights.
  start = Clock::now();
  out.instances.clear();
  out.lights.clear();
  std::vector<double> power;
  for (uint32_t c : tlas.primIndices) {
    gpu::GpuInstance inst = candidates.records[c];
    uint32_t mesh = candidates.mesh[c];
    if (mesh != WP_INVALID && !candidates.motion[c]) {
      inst = gpu::withInstanceFirstLight(inst, static_cast<uint32_t>(out.lights.size()));
      appendLights(scene, scene.meshes[mesh], meshes[mesh].emitters, candidates.objectToWorld[c], out.lights, power);
    }
    out.instances.push_back(inst);
  }
  // Motion keys go after the placed instances (the top level's leaves), a pair per mover.
  out.placedInstances = static_cast<uint32_t>(out.instances.size());
  for (uint32_t j = 0; j < out.placedInstances; ++j) {
    if (const std::optional<MotionKeys>& keys = candidates.motion[tlas.primIndices[j]]) {
      out.instances[j] = gpu::withInstanceMotionKeys(out.instances[j], static_cast<uint32_t>(out.instances.size()));
      out.instances.push_back(keys->open);
      out.instances.push_back(keys->close);
    }
  }
  appendPunctualLights(scene, sceneRadius(out), out.lights, power);
  out.punctualLightCount = static_cast<uint32_t>(scene.lights.size());
  buildLightTable(out.lights, power);
  double lightFlux = 0.0;
  for (double p : power) {
    lightFlux += p;
  }
  setSkyProbability(scene, lightFlux, out);
  time.lights = seconds(start);
  return time;
}

GpuScene packSceneParts(const Scene& scene, std::vector<PackedMesh>& meshes) {
  GpuScene out;
  packTextures(scene, out);  // first: the light table weighs emissive textures
  double weightedSah = 0.0;
  meshes.clear();
  for (const Mesh& mesh : scene.meshes) {
    MeshPrimitives prims = meshPrimitives(scene, mesh);
    PackedMesh& packed = meshes.emplace_back();
    auto start = Clock::now();
    Bvh bvh = buildMeshBvh(prims);
    out.bvhBuildSeconds += seconds(start);
    packed.sah = sahCost(bvh);
    weightedSah += static_cast<double>(packed.sah) * static_cast<double>(mesh.triangleCount());
    if (!bvh.nodes.empty()) {
      packed.bounds = bvh.nodes[0].bounds;
    }
    GpuMeshRange& range = out.meshes.emplace_back();
    range.firstTriangle = static_cast<uint32_t>(out.triangles.size());
    range.triangleCount = static_cast<uint32_t>(mesh.triangleCount());
    WideLayout wide = collapseToWide(bvh);
    range.rootNode = appendWideNodes(bvh, wide, range.firstTriangle, out.nodes);
    out.triangles.resize(out.triangles.size() + range.triangleCount);
    out.triangleShading.resize(out.triangles.size());
    writeTriangles(scene, mesh, bvh, prims, range.firstTriangle, out);
    packed.emitters = std::move(prims.emitters);
    if (mesh.deforming) {
      packed.bvh = std::move(bvh);
      packed.wide = std::move(wide);
    }
  }
  out.triangleCount = out.triangles.size();
  out.sahCost = out.triangleCount ? weightedSah / static_cast<double>(out.triangleCount) : 0.0;

  packSky(scene, out);
  out.bvhBuildSeconds += packInstances(scene, meshes, out).tlas;

  for (const Material& material : scene.materials) {
    out.materials.push_back(
        {glm::vec4(material.baseColor, material.alpha), glm::vec4(material.emission, material.doubleSided ? 1.0f : 0.0f),
         glm::vec4(material.metallic, material.roughness, material.ior, material.transmission),
         glm::vec4(material.attenuationColor, material.attenuationDistance),
         glm::uvec4(gpuMaterialKind(material.bsdf),
                    textureIndex(material.baseColorTexture), textureIndex(material.metallicRoughnessTexture),
                    textureIndex(material.normalTexture)),
         glm::vec4(material.normalScale, 0.0f, 0.0f, 0.0f),
         glm::uvec4(textureIndex(material.emissiveTexture), 0u, 0u, 0u),
         glm::uvec4(gpuAlphaMode(material.alphaMode), std::bit_cast<uint32_t>(material.alphaCutoff), 0u, 0u),
         glm::vec4(material.specularColor, material.specularWeight),
         glm::vec4(material.sheenColor, material.sheenRoughness),
         glm::vec4(material.clearcoat, material.clearcoatRoughness, material.clearcoatNormalScale, 0.0f),
         glm::vec4(0.0f, 0.0f, 1.0f, 0.0f),
         glm::uvec4(textureIndex(material.specularTexture), textureIndex(material.specularColorTexture),
                    textureIndex(material.sheenColorTexture), textureIndex(material.sheenRoughnessTexture)),
         glm::uvec4(textureIndex(material.clearcoatTexture), textureIndex(material.clearcoatRoughnessTexture),
                    textureIndex(material.clearcoatNormalTexture), 0u)});
  }
  for (const Plane& plane : scene.planes) {
    out.planes.push_back({glm::vec4(plane.normal, plane.distance), glm::uvec4(plane.material, 0u, 0u, 0u)});
  }
  return out;
}

}  // namespace pack_detail

SceneFeatures GpuScene::features() const {
  SceneFeatures f;
  f.alphaTested = std::any_of(triangles.begin(), triangles.end(),
                              [](const gpu::GpuTriangle& t) { return gpu::triangleAlphaTested(t); });
  f.skySampled = sky.selectionProbability > 0.0f;
  f.instanced = gpu::entryCount(topLevelEntry()) == 0;
  f.planes = !planes.empty();
  f.skyMap = uint64_t(sky.width) * sky.height > 1;
  f.punctual = punctualLightCount > 0;
  // Only the materials some surface has: a material nothing uses would only cost code.
  std::vector<bool> used(materials.size(), false);
  auto use = [&](uint32_t material) {
    if (material < used.size()) used[material] = true;
  };
  for (const gpu::GpuTriangle& t : triangles) use(gpu::triangleMaterial(t));
  for (uint32_t i = 0; i < placedInstances; ++i) {
    if (gpu::instanceKind(instances[i]) != WP_INSTANCE_SPHERE) continue;
    f.spheres = true;
    use(gpu::instanceSphereMaterial(instances[i]));
  }
  for (const gpu::GpuPlane& p : planes) use(gpu::planeMaterial(p));
  uint32_t needs = 0;
  for (size_t m = 0; m < materials.size(); ++m) {
    if (!used[m]) continue;
    const uint32_t materialNeeds = gpu::materialShadeNeeds(materials[m]);
    needs |= materialNeeds;
    f.diffuse = f.diffuse || materialNeeds == 0;
    f.emissive = f.emissive || gpu::materialEmits(materials[m]);
    f.addTextureSlots(materials[m]);
  }
  return f.withNeeds(needs);
}

bool GpuScene::emissionHittable() const {
  auto emits = [](const gpu::GpuMaterial& m) { return gpu::materialEmits(m); };
  auto bright = [](const glm::vec4& texel) { return texel.x > 0.0f || texel.y > 0.0f || texel.z > 0.0f; };
  return std::any_of(materials.begin(), materials.end(), emits) ||
         (sky.intensity > 0.0f && std::any_of(skyRadiance.begin(), skyRadiance.end(), bright));
}

TraversalStackNeeds GpuScene::stackNeeds() const {
  TraversalStackNeeds needs;
  if (nodes.empty()) return needs;
  needs.topLevel = traversalStackEntries(nodes, tlasRoot);
  for (const GpuMeshRange& mesh : meshes) {
    needs.bottomLevel = std::max(needs.bottomLevel, traversalStackEntries(nodes, mesh.rootNode));
  }
  return needs;
}

SceneFeatures SceneFeatures::withNeeds(uint32_t needs) const {
  SceneFeatures f = *this;
  f.microfacet = (needs & WP_NEEDS_MICROFACET) != 0;
  f.layered = (needs & WP_NEEDS_LAYERS) != 0;
  f.transmissive = (needs & WP_NEEDS_TRANSMISSION) != 0;
  f.metallic = (needs & WP_NEEDS_METAL) != 0;
  return f;
}

void SceneFeatures::addTextureSlots(const gpu::GpuMaterial& m) {
  auto fills = [](uint32_t texture) { return texture != WP_INVALID; };
  baseColorTexture = baseColorTexture || fills(gpu::materialBaseColorTexture(m));
  metallicRoughnessTexture = metallicRoughnessTexture || fills(gpu::materialMetallicRoughnessTexture(m));
  normalTexture = normalTexture || fills(gpu::materialNormalTexture(m));
  emissiveTexture = emissiveTexture || fills(gpu::materialEmissiveTexture(m));
  const uint32_t extensionSlots[] = {gpu::materialSpecularTexture(m),       gpu::materialSpecularColorTexture(m),
                                     gpu::materialSheenColorTexture(m),     gpu::materialSheenRoughnessTexture(m),
                                     gpu::materialClearcoatTexture(m),      gpu::materialClearcoatRoughnessTexture(m),
                                     gpu::materialClearcoatNormalTexture(m)};
  extensionTextures = extensionTextures || std::any_of(std::begin(extensionSlots), std::end(extensionSlots), fills);
}

std::vector<std::pair<const char*, bool>> SceneFeatures::macros() const {
  return {{"WP_SCENE_ALPHA_TESTED", alphaTested}, {"WP_SCENE_LAYERED", layered},
          {"WP_SCENE_TRANSMISSIVE", transmissive},
          {"WP_SCENE_MICROFACET", microfacet},    {"WP_SCENE_METALLIC", metallic},
          {"WP_SCENE_EMISSIVE", emissive},        {"WP_SCENE_SKY_SAMPLED", skySampled},
          {"WP_SCENE_INSTANCED", instanced},      {"WP_SCENE_PLANES", planes},
          {"WP_SCENE_SPHERES", spheres},          {"WP_SCENE_SKY_MAP", skyMap},
          {"WP_SCENE_PUNCTUAL", punctual},        {"WP_SCENE_BASE_COLOR_TEXTURE", baseColorTexture},
          {"WP_SCENE_METALLIC_ROUGHNESS_TEXTURE", metallicRoughnessTexture},
          {"WP_SCENE_NORMAL_TEXTURE", normalTexture},
          {"WP_SCENE_EMISSIVE_TEXTURE", emissiveTexture},
          {"WP_SCENE_EXTENSION_TEXTURES", extensionTextures}};
}

SceneFeatures SceneFeatures::everything() {
  SceneFeatures f;
  f.alphaTested = true;
  f.baseColorTexture = true;
  f.metallicRoughnessTexture = true;
  f.normalTexture = true;
  f.emissiveTexture = true;
  f.extensionTextures = true;
  f.diffuse = true;
  f.emissive = true;
  f.skySampled = true;
  f.instanced = true;
  f.planes = true;
  f.spheres = true;
  f.skyMap = true;
  f.punctual = true;
  return f.withNeeds(WP_NEEDS_MICROFACET | WP_NEEDS_LAYERS | WP_NEEDS_TRANSMISSION | WP_NEEDS_METAL);
}

GpuScene packScene(const Scene& scene) {
  std::vector<pack_detail::PackedMesh> meshes;
  return pack_detail::packSceneParts(scene, meshes);
}

}  // namespace wp
