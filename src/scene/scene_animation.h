// What re-posing an animated scene needs (node hierarchy, animations, skins, morph data), and posing.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/animation.h"
#include "scene/mesh_deformation.h"
#include "scene/scene.h"

namespace wp {

// A glTF node's rest transform (a matrix, or translation, rotation and scale, which
// channels may replace) and its rest morph weights (the node's, else its mesh's).
struct AnimatedNode {
  int parent = -1;  // -1: a root
  bool hasMatrix = false;
  glm::dmat4 matrix{1.0};
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 scale{1.0};
  std::vector<float> weights;
};

struct Skin {
  std::vector<uint32_t> joints;          // glTF node indices
  std::vector<glm::mat4> inverseBind;    // one per joint
};

// A scene mesh that deforms: placed by `node`, whose morph weights it uses, skinned by
// `skin` (-1: none; a skinned mesh lives in world space, its instance transform is identity).
struct DeformingMesh {
  uint32_t mesh = 0;
  uint32_t node = 0;
  int skin = -1;
  MeshDeformation deformation;
};

// Everything the loader keeps to pose the scene at another time. Scene holds it through a
// shared pointer, so posing copies only what changes.
struct SceneAnimation {
  std::vector<Animation> animations;  // all play at once, as glTF viewers commonly do
  std::vector<AnimatedNode> nodes;    // every glTF node
  std::vector<uint32_t> order;        // the default scene's nodes, parents first
  std::vector<uint32_t> instanceNodes;  // per Scene::instances entry, the node placing it
  std::vector<uint32_t> sphereNodes;    // per Scene::spheres entry
  std::vector<float> sphereRadii;       // per Scene::spheres entry
  std::vector<uint32_t> lightNodes;     // per Scene::lights entry
  int cameraNode = -1;                  // -1: the camera does not come from a node
  std::vector<Skin> skins;
  std::vector<DeformingMesh> deformingMeshes;
  double duration = 0.0;  // the last keyframe time of all animations, seconds
};

// The scene at `seconds` (every animation sampled there, clamped to its keyframes), or in
// its rest pose (no channel applied) without a time: instance and sphere transforms, the
// camera when it sits on a node, punctual lights, and the vertices of deforming meshes. Instances, meshes
// and spheres keep their order and count, so every pose maps one to one onto the others.
// Planes keep their rest pose. A scene without animation data is returned unchanged.
Scene poseScene(const Scene& scene, std::optional<double> seconds);

// The scene as a camera sees it with its shutter open from `open` for `shutter` seconds:
// posed at `open`, and every instance, sphere and light that moves meanwhile carries its transform at
// shutter close for motion blur (objectToWorldAtClose). Deforming meshes keep their vertices
// at `open`, and the camera its place. With shutter <= 0 it is poseScene(scene, open).
Scene poseSceneOverShutter(const Scene& scene, double open, double shutter);

}  // namespace wp
