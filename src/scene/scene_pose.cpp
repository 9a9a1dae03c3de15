// Posing an animated scene at a time: node transforms, then instances, spheres, camera and deforming meshes.
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "scene/scene_animation.h"
#include "scene/scene_camera.h"

namespace wp {

namespace {

glm::dvec3 toVec3(const std::vector<float>& v) { return {v[0], v[1], v[2]}; }

// Every node's local transform with the channels applied at `seconds`.
std::vector<AnimatedNode> sampleNodes(const SceneAnimation& a, std::optional<double> seconds) {
  std::vector<AnimatedNode> nodes = a.nodes;
  if (!seconds) return nodes;
  for (const Animation& animation : a.animations) {
    for (const AnimationChannel& channel : animation.channels) {
      const AnimationSampler& sampler = animation.samplers[channel.sampler];
      AnimatedNode& node = nodes[channel.node];
      switch (channel.path) {
        case AnimationPath::Translation: node.translation = toVec3(sampleValues(sampler, *seconds)); break;
        case AnimationPath::Rotation: node.rotation = sampleRotation(sampler, *seconds); break;
        case AnimationPath::Scale: node.scale = toVec3(sampleValues(sampler, *seconds)); break;
        case AnimationPath::Weights: node.weights = sampleValues(sampler, *seconds); break;
      }
    }
  }
  return nodes;
}

// World transforms in double precision, as the loader's walk computes them.
std::vector<glm::dmat4> worldTransforms(const SceneAnimation& a, const std::vector<AnimatedNode>& nodes) {
  std::vector<glm::dmat4> world(nodes.size(), glm::dmat4(1.0));
  for (uint32_t n : a.order) {
    const AnimatedNode& node = nodes[n];
    glm::dmat4 local = node.matrix;
    if (!node.hasMatrix) {
      local = glm::translate(glm::dmat4(1.0), node.translation) * glm::mat4_cast(node.rotation);
      local = glm::scale(local, node.scale);
    }
    world[n] = node.parent >= 0 ? world[static_cast<size_t>(node.parent)] * local : local;
  }
  return world;
}

}  // namespace

Scene poseScene(const Scene& scene, std::optional<double> seconds) {
  Scene posed = scene;
  if (!scene.animation) return posed;
  const SceneAnimation& a = *scene.animation;
  const std::vector<AnimatedNode> nodes = sampleNodes(a, seconds);
  const std::vector<glm::dmat4> world = worldTransforms(a, nodes);

  for (size_t i = 0; i < posed.instances.size(); ++i) {
    posed.instances[i].objectToWorld = glm::mat4(world[a.instanceNodes[i]]);
  }
  for (const DeformingMesh& deforming : a.deformingMeshes) {
    std::vector<glm::mat4> jointMatrices;
    if (deforming.skin >= 0) {
      const Skin& skin = a.skins[static_cast<size_t>(deforming.skin)];
      for (size_t j = 0; j < skin.joints.size(); ++j) {
        jointMatrices.push_back(glm::mat4(world[skin.joints[j]] * glm::dmat4(skin.inverseBind[j])));
      }
      // The joints place a skinned mesh; the transform of its own node is ignored (glTF 2.0, 3.7.3).
      for (MeshInstance& instance : posed.instances) {
        if (instance.mesh == deforming.mesh) instance.objectToWorld = glm::mat4(1.0f);
      }
    }
    deformMesh(deforming.deformation, nodes[deforming.node].weights, jointMatrices, posed.meshes[deforming.mesh]);
  }
  for (size_t i = 0; i < posed.spheres.size(); ++i) {
    posed.spheres[i].objectToWorld = glm::scale(glm::mat4(world[a.sphereNodes[i]]), glm::vec3(a.sphereRadii[i]));
  }
  for (size_t i = 0; i < posed.lights.size(); ++i) {
    posed.lights[i].lightToWorld = glm::mat4(world[a.lightNodes[i]]);
  }
  if (a.cameraNode >= 0) {
    // The lens stays the scene's; only where it is and where it looks follow the node.
    const std::optional<Camera> camera = cameraFromNode(glm::mat4(world[static_cast<size_t>(a.cameraNode)]),
                                                        scene.camera.yfov, scene.camera.aspectRatio);
    if (!camera) {
      throw Error("at " + std::to_string(seconds.value_or(0.0)) +
                  " s the camera node's transform collapses the view or up direction; fix the camera's animation");
    }
    posed.camera.position = camera->position;
    posed.camera.forward = camera->forward;
    posed.camera.up = camera->up;
  }
  return posed;
}

Scene poseSceneOverShutter(const Scene& scene, double open, double shutter) {
  Scene posed = poseScene(scene, open);
  if (!(shutter > 0.0) || !scene.animation) {
    return posed;
  }
  const Scene closed = poseScene(scene, open + shutter);
  for (size_t i = 0; i < posed.instances.size(); ++i) {
    if (closed.instances[i].objectToWorld != posed.instances[i].objectToWorld) {
      posed.instances[i].objectToWorldAtClose = closed.instances[i].objectToWorld;
    }
  }
  for (size_t i = 0; i < posed.spheres.size(); ++i) {
    if (closed.spheres[i].objectToWorld != posed.spheres[i].objectToWorld) {
      posed.spheres[i].objectToWorldAtClose = closed.spheres[i].objectToWorld;
    }
  }
  for (size_t i = 0; i < posed.lights.size(); ++i) {
    if (closed.lights[i].lightToWorld != posed.lights[i].lightToWorld) {
      posed.lights[i].lightToWorldAtClose = closed.lights[i].lightToWorld;
    }
  }
  return posed;
}

}  // namespace wp
