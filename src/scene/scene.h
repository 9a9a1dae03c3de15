// The host-side scene: what the glTF loader produces and the GPU packer consumes.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/environment_map.h"

namespace wp {

struct SceneAnimation;

// A glTF metallic-roughness material (defaults as in glTF), or an ideal diffuse one.
struct Material {
  // Gltf: glTF's metallic-roughness BRDF (a Lambertian base under the dielectric's specular
  // layer); GltfDisneyDiffuse: the same with the seed report's Disney diffuse base
  // (extras.wavepath.diffuse = "disney"); Lambert: ideal diffuse of albedo baseColor
  // (extras.wavepath.bsdf = "lambert"); Unlit: KHR_materials_unlit, the base colour as
  // emission and no scattering.
  enum class Bsdf { Gltf, GltfDisneyDiffuse, Lambert, Unlit };
  // glTF alphaMode: Opaque ignores alpha; Mask cuts the surface out where alpha <
  // alphaCutoff; Blend lets a ray pass with probability 1 - alpha (shaders/common/alpha.h).
  enum class AlphaMode { Opaque, Mask, Blend };

  std::string name;
  Bsdf bsdf = Bsdf::Gltf;
  glm::vec3 baseColor{1.0f};  // linear RGB base colour
  float alpha = 1.0f;  // baseColorFactor's alpha
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  float metallic = 1.0f;
  float roughness = 1.0f;     // perceptual; alpha = roughness^2
  float ior = 1.5f;           // KHR_materials_ior
  float transmission = 0.0f;  // KHR_materials_transmission
  glm::vec3 attenuationColor{1.0f};                             // KHR_materials_volume
  float attenuationDistance = std::numeric_limits<float>::max();  // max: no absorption
  glm::vec3 emission{0.0f};  // emitted radiance: emissiveFactor * emissive_strength
  bool doubleSided = false;  // glTF doubleSided; a single-sided emitter emits on its front only
  int baseColorTexture = -1;          // index into Scene::textures (sRGB), -1: none
  int metallicRoughnessTexture = -1;  // index into Scene::textures (linear; B metallic, G roughness)
  int normalTexture = -1;             // index into Scene::textures (linear, tangent space)
  float normalScale = 1.0f;
  int emissiveTexture = -1;           // index into Scene::textures (sRGB), multiplies emission
  // The layered extensions (shaders/common/material.h); their textures are indices into
  // Scene::textures, -1: none, each multiplying its factor.
  float specularWeight = 1.0f;         // KHR_materials_specular specularFactor
  glm::vec3 specularColor{1.0f};       // specularColorFactor
  int specularTexture = -1;            // linear, alpha
  int specularColorTexture = -1;       // sRGB
  glm::vec3 sheenColor{0.0f};          // KHR_materials_sheen sheenColorFactor; 0: no sheen
  float sheenRoughness = 0.0f;         // sheenRoughnessFactor
  int sheenColorTexture = -1;          // sRGB
  int sheenRoughnessTexture = -1;      // linear, alpha
  float clearcoat = 0.0f;              // KHR_materials_clearcoat clearcoatFactor; 0: no coat
  float clearcoatRoughness = 0.0f;     // clearcoatRoughnessFactor
  int clearcoatTexture = -1;           // linear, red
  int clearcoatRoughnessTexture = -1;  // linear, green
  int clearcoatNormalTexture = -1;     // linear, tangent space
  float clearcoatNormalScale = 1.0f;

  bool isEmissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
  bool isAlphaTested() const { return alphaMode != AlphaMode::Opaque; }
};

// A triangle mesh in object space. All glTF primitives of a mesh are merged into one.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  // Unit shading normals per vertex (glTF NORMAL), or empty when no primitive has them;
  // zero for the vertices of primitives without, which then shade flat.
  std::vector<glm::vec3> normals;
  // glTF TEXCOORD_0 per vertex, or empty when no primitive has it; zero where one lacks it.
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec2> uvs1;  // TEXCOORD_1, the same way
  // glTF COLOR_0 per vertex (linear RGBA), or empty when no primitive has it; white where one lacks it.
  std::vector<glm::vec4> colors;
  // glTF TANGENT per vertex (xyz unit, w the bitangent sign, +-1), or empty when no primitive
  // has it; zero where one lacks it or has no NORMAL (glTF ignores tangents there).
  std::vector<glm::vec4> tangents;
  std::vector<uint32_t> indices;    // 3 per triangle, counter-clockwise = front face
  std::vector<uint32_t> materials;  // one material index per triangle
  // Set when an animation moves its vertices (morph targets or a skin): its BVH is then
  // refitted per frame, and it is never baked into world space with other meshes.
  bool deforming = false;

  size_t triangleCount() const { return indices.size() / 3; }
};

// A decoded image with its sampler, as one material slot uses it: RGBA8, rows from the top, r
// in the low byte, with the slot's texture coordinate set and transform.
struct Texture {
  enum class Wrap { Repeat, Clamp, Mirror };

  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint32_t> rgba;
  Wrap wrapS = Wrap::Repeat;
  Wrap wrapT = Wrap::Repeat;
  bool nearest = false;  // magFilter NEAREST; otherwise bilinear (there are no mipmaps)
  bool srgb = false;     // colour data (base colour), decoded to linear when sampled
  int texCoord = 0;      // TEXCOORD_<texCoord> (0 or 1)
  // KHR_texture_transform: the coordinates looked up are uvTransform * (u, v, 1).
  glm::mat3 uvTransform{1.0f};
};

struct MeshInstance {
  uint32_t mesh = 0;
  glm::mat4 objectToWorld{1.0f};
  // Set when an animation moves it (its node or an ancestor has a channel): it then stays an
  // instance, so a new pose rebuilds only the top-level BVH.
  bool animated = false;
  // Motion blur: where it is at shutter close, objectToWorld being where it is at shutter
  // open (in between: translation and scale linear, rotation by slerp; see motion.h). Unset:
  // it stands still. Only the transform moves: a deforming mesh's vertices are its pose at
  // shutter open.
  std::optional<glm::mat4> objectToWorldAtClose;
};

// Analytic sphere: the unit sphere at the origin mapped by objectToWorld (radius and
// centre are folded into the transform).
struct Sphere {
  glm::mat4 objectToWorld{1.0f};
  uint32_t material = 0;
  std::optional<glm::mat4> objectToWorldAtClose;  // motion blur, as for MeshInstance
};

// Infinite plane dot(normal, p) = distance, with a unit normal.
struct Plane {
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  float distance = 0.0f;
  uint32_t material = 0;
};

// A glTF KHR_lights_punctual light, placed by its node: it sits at the node's origin and
// points down the node's -Z axis (spot, directional).
struct PunctualLight {
  enum class Kind { Point, Spot, Directional };

  std::string name;
  Kind kind = Kind::Point;
  // Radiant intensity in W/sr (point, spot) or irradiance in W/m^2 (directional), the units
  // of emitted radiance times sr or m^2: the file's colour times its candela or lux over 683,
  // as Blender's importer converts them, so a file lit by lamps and emitters keeps its balance.
  glm::vec3 intensity{1.0f / 683.0f};
  float innerConeAngle = 0.0f;        // spot, radians
  float outerConeAngle = 0.7853982f;  // spot, radians (glTF's default pi / 4)
  glm::mat4 lightToWorld{1.0f};       // its node's world transform
  std::optional<glm::mat4> lightToWorldAtClose;  // motion blur, as for MeshInstance

  glm::vec3 position() const { return glm::vec3(lightToWorld[3]); }
  // Where it points (spot, directional): the node's -Z, unit (the node's scale does not count).
  glm::vec3 direction() const { return glm::normalize(-glm::vec3(lightToWorld[2])); }
};

// Physical camera settings from the glTF camera's extras or the command line; 0 means unset.
struct CameraOptics {
  float fNumber = 0.0f;        // 0: a pinhole (everything sharp)
  float focusDistance = 0.0f;  // metres along the view axis; 0: focus on what the centre sees
  float focalLength = 0.0f;    // metres; 0: chosen so the glTF field of view holds at focus
  uint32_t blades = 0;         // aperture blades; 0: a round aperture
  float bladeRotation = 0.0f;  // radians
  glm::vec2 sensorSize{0.036f, 0.024f};  // metres, full-frame 35 mm by default
  float shutter = 0.0f;        // seconds; with iso, sets a physical exposure
  float iso = 0.0f;
};

struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit
  glm::vec3 up{0.0f, 1.0f, 0.0f};        // unit, orthogonal to forward
  float yfov = 0.7853982f;               // vertical field of view in radians
  float aspectRatio = 0.0f;              // from the file; 0 = use the image's
  CameraOptics optics;
  // A glTF orthographic camera: parallel rays along `forward` from a view rectangle
  // 2 * orthographicHalfHeight tall (glTF ymag) centred on `position`, as wide as the image's
  // aspect makes it; yfov and the optics do not apply.
  bool orthographic = false;
  float orthographicHalfHeight = 0.0f;
};

struct Scene {
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Mesh> meshes;
  std::vector<MeshInstance> instances;
  std::vector<Sphere> spheres;
  std::vector<Plane> planes;
  std::vector<PunctualLight> lights;
  Camera camera;
  bool hasCamera = false;           // false: the camera was framed automatically
  // The sky seen by rays that leave the scene: an equirectangular radiance map (1x1 is a
  // constant sky; empty is black), white when the scene has no emitters. Intensity scales
  // it, rotation turns it about +y (radians).
  EnvironmentMap sky;
  float skyIntensity = 1.0f;
  float skyRotation = 0.0f;
  // Animations, skins and the node hierarchy, to pose the scene at other times with
  // poseScene (scene/scene_animation.h); null when the file has no animation, skin or morph
  // target.
  std::shared_ptr<const SceneAnimation> animation;
};

}  // namespace wp
