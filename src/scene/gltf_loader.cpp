// Loading a glTF 2.0 file (.gltf or .glb) into a wavepath scene.
//
// wavepath shapes in node extras (a stable schema; docs/scenes.md quotes it):
//
//   "extras": {"wavepath": {"shape": "sphere", "radius": 0.5, "material": 2}}
//       A sphere centred at the node origin, with the given radius in node-local units
//       (objectToWorld = nodeWorld * scale(radius); a non-uniform node scale makes an
//       ellipsoid). radius is required and must be a number > 0.
//
//   "extras": {"wavepath": {"shape": "plane", "material": 0}}
//       The infinite plane through the node origin whose normal is the node-local +Y axis
//       (transformed by the inverse transpose of the node's world matrix and normalised).
//       Its front side is the side +Y points to.
//
//   Physical camera settings in a camera's extras (all optional; docs/camera-and-sky.md quotes them):
//   "cameras": [{"type": "perspective", ..., "extras": {"wavepath": {"fStop": 2.8,
//       "focusDistance": 1.5, "focalLength": 50, "blades": 6, "bladeRotation": 0,
//       "sensorWidth": 36, "sensorHeight": 24, "shutter": 0.01, "iso": 100}}}]
//       focusDistance in scene units (metres), focalLength and the sensor in millimetres,
//       shutter in seconds, bladeRotation in radians. Without fStop the camera is a pinhole.
//
//   "material" indexes the file's materials array; without it the shape gets the glTF
//   default material (white, one-sided). The node's mesh, camera and children, if any, are
//   loaded as usual alongside the shape. Unknown shapes, a radius that is not a number > 0,
//   and material indices outside the array are errors.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/log.h"
#include "scene/default_lighting.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_camera_extras.h"
#include "scene/gltf_cameras.h"
#include "scene/gltf_compression.h"
#include "scene/gltf_context.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_extras.h"
#include "scene/gltf_file.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_mesh.h"
#include "scene/gltf_variants.h"
#include "scene/gltf_nodes.h"
#include "scene/scene_animation.h"
#include "scene/scene_camera.h"

namespace wp {

namespace {

constexpr int kNotConverted = -1;
constexpr int kNoTriangles = -2;

// Instances, spheres and planes are skipped at a singular transform: they have no area
// to render, and the renderer inverts the transforms.
bool isInvertible(const glm::mat4& world) {
  const double det = glm::determinant(glm::dmat3(glm::mat3(world)));
  return det != 0.0 && std::isfinite(det);
}

class SceneBuilder {
public:
  SceneBuilder(const gltf::Context& ctx, const LoadOptions& options)
      : ctx_(ctx), options_(options), sceneMeshOf_(ctx.model.meshes.size(), kNotConverted),
        animatedNode_(ctx.model.nodes.size(), false) {}

  Scene build() {
    scene_.materials = gltf::convertMaterials(ctx_, scene_.textures);
    defaultMaterial_ = static_cast<uint32_t>(scene_.materials.size());
    fileLights_ = gltf::readLights(ctx_);
    readAnimationData();
    const std::optional<size_t> sceneIndex = gltf::sceneToWalk(ctx_, options_.scene);
    gltf::walkScene(ctx_, sceneIndex, [this](size_t node, const glm::mat4& world) { visit(node, world); });
    if (animation_) {
      scene_.animation = animation_;
      // Skins and the default morph weights shape the rest pose too.
      scene_ = poseScene(scene_, std::nullopt);
    }
    if (scene_.instances.empty() && scene_.spheres.empty() && scene_.planes.empty()) {
      const std::string which = options_.scene ? "scene " + std::to_string(*options_.scene) : "the default scene";
      gltf::fail(ctx_, "",
                 "nothing to render: " + which + " has no triangles, spheres or planes; add a triangle mesh or a "
                 "wavepath shape" + (ctx_.model.scenes.size() > 1 ? ", or pick another scene with --scene N" : ""));
    }
    if (!options_.camera.empty() && !scene_.hasCamera) {
      gltf::fail(ctx_, "", "--camera " + gltf::oneLine(options_.camera) + " names no camera of " +
                               (sceneIndex ? "scene " + std::to_string(*sceneIndex) : std::string("the file")) + " (" +
                               gltf::cameraList(ctx_) + "); give a camera's index or name");
    }
    if (usesDefaultMaterial()) scene_.materials.push_back(gltf::defaultMaterial());
    warnAboutShapeAlpha();
    if (!scene_.hasCamera) scene_.camera = frameScene(scene_);
    if (options_.defaultSky) {
      const DefaultLighting lighting = chooseDefaultLighting(scene_, ctx_.file);
      if (lighting.whiteSky) scene_.sky = makeEnvironmentMap(1, 1, {glm::vec3(kDefaultSkyRadiance)});
      note(lighting.note);
    }
    return std::move(scene_);
  }

private:
  // Keeps the animations, the node hierarchy and the morph target counts when the file
  // animates or deforms anything; otherwise the scene stays static and cheap to copy.
  void readAnimationData() {
    const tinygltf::Model& model = ctx_.model;
    for (size_t m = 0; m < model.meshes.size(); ++m) morphTargets_.push_back(gltf::morphTargetCount(ctx_, m));
    const bool morphs = std::any_of(morphTargets_.begin(), morphTargets_.end(), [](size_t n) { return n > 0; });
    if (model.animations.empty() && model.skins.empty() && !morphs) return;
    auto animation = std::make_shared<SceneAnimation>();
    std::vector<size_t> nodeTargets(model.nodes.size(), 0);
    for (size_t n = 0; n < model.nodes.size(); ++n) {
      const int mesh = model.nodes[n].mesh;
      if (mesh >= 0 && static_cast<size_t>(mesh) < morphTargets_.size()) nodeTargets[n] = morphTargets_[mesh];
    }
    animation->animations = gltf::readAnimations(ctx_, nodeTargets);
    animation->duration = animationDuration(animation->animations);
    for (const Animation& a : animation->animations) {
      for (const AnimationChannel& channel : a.channels) {
        if (channel.path != AnimationPath::Weights) animatedNode_[channel.node] = true;
      }
    }
    for (size_t n = 0; n < model.nodes.size(); ++n) animation->nodes.push_back(restNode(n, nodeTargets[n]));
    for (size_t n = 0; n < model.nodes.size(); ++n) {
      for (int child : model.nodes[n].children) {
        // Out-of-range children are reported by the walk.
        if (child >= 0 && static_cast<size_t>(child) < model.nodes.size()) animation->nodes[child].parent = int(n);
      }
    }
    for (size_t s = 0; s < model.skins.size(); ++s) animation->skins.push_back(gltf::readSkin(ctx_, s));
    animation_ = std::move(animation);
  }

  AnimatedNode restNode(size_t index, size_t morphTargets) const {
    const tinygltf::Node& node = ctx_.model.nodes[index];
    AnimatedNode rest;
    rest.hasMatrix = !node.matrix.empty();
    // Lengths, finiteness and the rotation's length are checked by the walk; a node outside
    // the default scene is never posed.
    if (rest.hasMatrix && node.matrix.size() == 16) {
      for (int i = 0; i < 16; ++i) rest.matrix[i / 4][i % 4] = node.matrix[static_cast<size_t>(i)];
    }
    const std::vector<double>& t = node.translation;
    if (t.size() == 3) rest.translation = glm::dvec3(t[0], t[1], t[2]);
    if (node.rotation.size() == 4) {
      const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      if (glm::length(q) > 0.0) rest.rotation = q / glm::length(q);
    }
    if (node.scale.size() == 3) rest.scale = glm::dvec3(node.scale[0], node.scale[1], node.scale[2]);
    const bool hasMesh = node.mesh >= 0 && static_cast<size_t>(node.mesh) < ctx_.model.meshes.size();
    const std::vector<double>& weights =
        !node.weights.empty() || !hasMesh ? node.weights : ctx_.model.meshes[static_cast<size_t>(node.mesh)].weights;
    if (!node.weights.empty() && node.weights.size() != morphTargets) {
      gltf::fail(ctx_, gltf::describe("node", index, node.name),
                 "it has " + std::to_string(node.weights.size()) + " morph weights but its mesh " +
                     std::to_string(morphTargets) + " morph targets; give one weight per target");
    }
    rest.weights.assign(morphTargets, 0.0f);
    for (size_t t = 0; t < weights.size() && t < morphTargets; ++t) rest.weights[t] = static_cast<float>(weights[t]);
    return rest;
  }

  void visit(size_t index, const glm::mat4& world) {
    const tinygltf::Node& node = ctx_.model.nodes[index];
    const std::string where = gltf::describe("node", index, node.name);
    if (animation_) {
      animation_->order.push_back(static_cast<uint32_t>(index));
      const int parent = animation_->nodes[index].parent;
      if (parent >= 0 && animatedNode_[static_cast<size_t>(parent)]) animatedNode_[index] = true;
    }
    if (node.mesh != -1) addInstance(where, index, world);
    if (node.camera != -1) addCamera(where, index, world);
    if (const std::optional<size_t> light = gltf::nodeLight(ctx_, index)) addLight(where, index, *light, world);
    if (const std::optional<gltf::ShapeSpec> shape = gltf::readShape(ctx_, index)) {
      addShape(where, index, *shape, world);
    }
  }

  void addInstance(const std::string& where, size_t node, const glm::mat4& world) {
    const int gltfMesh = ctx_.model.nodes[node].mesh;
    const int skin = ctx_.model.nodes[node].skin;
    const size_t meshCount = ctx_.model.meshes.size();
    if (gltfMesh < 0 || static_cast<size_t>(gltfMesh) >= meshCount) {
      gltf::fail(ctx_, where, "mesh " + gltf::missingIndex(gltfMesh, meshCount, "meshes") + "; re-export the file");
    }
    if (skin != -1 || morphTargets_[static_cast<size_t>(gltfMesh)] > 0) return addDeformingInstance(where, node, world);
    if (!isInvertible(world)) return skipSingular(where, "mesh");
    int& sceneMesh = sceneMeshOf_[static_cast<size_t>(gltfMesh)];
    if (sceneMesh == kNotConverted) {
      Mesh mesh = gltf::convertMesh(ctx_, static_cast<size_t>(gltfMesh), defaultMaterial_);
      sceneMesh = mesh.triangleCount() == 0 ? kNoTriangles : static_cast<int>(scene_.meshes.size());
      if (sceneMesh != kNoTriangles) scene_.meshes.push_back(std::move(mesh));
    }
    if (sceneMesh == kNoTriangles) return;
    scene_.instances.push_back({static_cast<uint32_t>(sceneMesh), world, animatedNode_[node]});
    if (animation_) animation_->instanceNodes.push_back(static_cast<uint32_t>(node));
  }

  // A mesh with morph targets or a skin gets a scene mesh of its own per node, since each
  // node gives it its own weights or joints. Its vertices are set by poseScene; a skinned
  // one ignores its node's transform, so a singular one does not skip it.
  void addDeformingInstance(const std::string& where, size_t node, const glm::mat4& world) {
    const tinygltf::Node& gltfNode = ctx_.model.nodes[node];
    const size_t gltfMesh = static_cast<size_t>(gltfNode.mesh);
    if (gltfNode.skin != -1 && (gltfNode.skin < 0 || static_cast<size_t>(gltfNode.skin) >= ctx_.model.skins.size())) {
      gltf::fail(ctx_, where, "skin " + gltf::missingIndex(gltfNode.skin, ctx_.model.skins.size(), "skins") +
                                  "; re-export the file");
    }
    if (gltfNode.skin == -1 && !isInvertible(world)) return skipSingular(where, "mesh");
    DeformingMesh deforming;
    deforming.mesh = static_cast<uint32_t>(scene_.meshes.size());
    deforming.node = static_cast<uint32_t>(node);
    deforming.skin = gltfNode.skin;
    Mesh mesh = gltf::convertMesh(ctx_, gltfMesh, defaultMaterial_, &deforming.deformation, morphTargets_[gltfMesh]);
    if (mesh.triangleCount() == 0) return;
    if (gltfNode.skin != -1) {
      checkSkinWeights(where, deforming.deformation, gltfNode.skin);
    } else {
      // Without a skin on the node, glTF ignores the mesh's JOINTS_0 and WEIGHTS_0.
      deforming.deformation.joints.clear();
      deforming.deformation.jointWeights.clear();
    }
    deforming.deformation.restPositions = mesh.positions;
    deforming.deformation.restNormals = mesh.normals;
    deforming.deformation.restTangents = mesh.tangents;
    mesh.deforming = true;
    const bool animated = gltfNode.skin == -1 && animatedNode_[node];
    scene_.instances.push_back({deforming.mesh, world, animated});
    scene_.meshes.push_back(std::move(mesh));
    animation_->instanceNodes.push_back(static_cast<uint32_t>(node));
    animation_->deformingMeshes.push_back(std::move(deforming));
  }

  // Also points unweighted joint slots at joint 0, so skinning never reads past the joints.
  void checkSkinWeights(const std::string& where, MeshDeformation& d, int skin) const {
    const size_t jointCount = animation_->skins[static_cast<size_t>(skin)].joints.size();
    for (size_t v = 0; v < d.joints.size(); ++v) {
      if (d.jointWeights[v] == glm::vec4(0.0f)) {
        gltf::fail(ctx_, where,
                   "vertex " + std::to_string(v) + " of its skinned mesh has no joint weights (no WEIGHTS_0, or all "
                   "zero); weight every vertex to a joint");
      }
      for (int c = 0; c < 4; ++c) {
        if (d.jointWeights[v][c] == 0.0f) d.joints[v][c] = 0;
        if (d.joints[v][c] >= jointCount) {
          gltf::fail(ctx_, where,
                     "vertex " + std::to_string(v) + " uses joint " + std::to_string(d.joints[v][c]) + " but skin " +
                         std::to_string(skin) + " has " + std::to_string(jointCount) + " joints; re-export the skin");
        }
      }
    }
  }

  void addCamera(const std::string& nodeWhere, size_t node, const glm::mat4& world) {
    const int index = ctx_.model.nodes[node].camera;
    const size_t cameraCount = ctx_.model.cameras.size();
    if (index < 0 || static_cast<size_t>(index) >= cameraCount) {
      gltf::fail(ctx_, nodeWhere,
                 "camera " + gltf::missingIndex(index, cameraCount, "cameras") + "; re-export the file");
    }
    // The first camera of the walk wins, or the first that --camera names.
    if (scene_.hasCamera || !gltf::cameraSelected(ctx_, options_.camera, static_cast<size_t>(index), node)) return;
    scene_.camera = gltf::convertCamera(ctx_, static_cast<size_t>(index), nodeWhere, world);
    scene_.hasCamera = true;
    if (animation_) animation_->cameraNode = static_cast<int>(node);
  }

  void addShape(const std::string& where, size_t node, const gltf::ShapeSpec& shape, const glm::mat4& world) {
    const uint32_t material = shape.material == -1 ? defaultMaterial_ : static_cast<uint32_t>(shape.material);
    const bool sphere = shape.kind == gltf::ShapeSpec::Kind::Sphere;
    if (!isInvertible(world)) return skipSingular(where, sphere ? "sphere" : "plane");
    if (sphere) {
      const glm::mat4 objectToWorld = glm::scale(world, glm::vec3(static_cast<float>(shape.radius)));
      if (!isInvertible(objectToWorld)) return skipSingular(where, "sphere");
      scene_.spheres.push_back({objectToWorld, material});
      if (animation_) {
        animation_->sphereNodes.push_back(static_cast<uint32_t>(node));
        animation_->sphereRadii.push_back(static_cast<float>(shape.radius));
      }
    } else {
      const glm::vec3 normal = glm::normalize(glm::transpose(glm::inverse(glm::mat3(world))) * glm::vec3(0, 1, 0));
      scene_.planes.push_back({normal, glm::dot(normal, glm::vec3(world[3])), material});
    }
  }

  void addLight(const std::string& where, size_t node, size_t light, const glm::mat4& world) {
    if (!isInvertible(world)) return skipSingular(where, "light");
    PunctualLight placed = fileLights_[light];
    placed.lightToWorld = world;
    scene_.lights.push_back(placed);
    if (animation_) animation_->lightNodes.push_back(static_cast<uint32_t>(node));
  }

  void skipSingular(const std::string& where, const char* what) {
    gltf::warnAt(ctx_, where, std::string("its transform is singular (a scale of 0?), so its ") + what + " is skipped");
  }

  // Only triangles test coverage (shaders/common/alpha.h): the analytic shapes say so.
  void warnAboutShapeAlpha() const {
    size_t shapes = 0;
    for (const Sphere& sphere : scene_.spheres) shapes += scene_.materials[sphere.material].isAlphaTested() ? 1 : 0;
    for (const Plane& plane : scene_.planes) shapes += scene_.materials[plane.material].isAlphaTested() ? 1 : 0;
    if (shapes > 0) {
      gltf::warnAt(ctx_, "", std::to_string(shapes) +
                                 " wavepath spheres or planes have a material with alphaMode MASK or BLEND, which "
                                 "they ignore: they render opaque (only triangles are cut out or see-through)");
    }
  }

  bool usesDefaultMaterial() const {
    for (const Mesh& mesh : scene_.meshes) {
      for (uint32_t m : mesh.materials) {
        if (m == defaultMaterial_) return true;
      }
    }
    for (const Sphere& sphere : scene_.spheres) {
      if (sphere.material == defaultMaterial_) return true;
    }
    for (const Plane& plane : scene_.planes) {
      if (plane.material == defaultMaterial_) return true;
    }
    return false;
  }

  const gltf::Context& ctx_;
  const LoadOptions options_;
  Scene scene_;
  uint32_t defaultMaterial_ = 0;
  std::vector<int> sceneMeshOf_;  // glTF mesh -> index in scene_.meshes, kNotConverted or kNoTriangles
  std::vector<PunctualLight> fileLights_;  // the file's KHR_lights_punctual lights, unplaced
  std::vector<size_t> morphTargets_;  // per glTF mesh
  std::vector<bool> animatedNode_;    // per glTF node: a channel moves it or an ancestor
  std::shared_ptr<SceneAnimation> animation_;  // null for a static scene
};

}  // namespace

Scene loadScene(const std::filesystem::path& file, const LoadOptions& options) {
  // The warnings of a large file are summed up before the render (or the error) comes.
  struct FlushWarnings {
    ~FlushWarnings() { flushWarnings(); }
  } flush;
  tinygltf::Model model = gltf::parseGltfFile(file);
  gltf::Context ctx{file.string(), model};
  ctx.variant = gltf::findVariant(ctx, options.variant);
  gltf::checkExtensions(ctx);
  gltf::decodeCompressedData(ctx, model);
  return SceneBuilder(ctx, options).build();
}

}  // namespace wp
