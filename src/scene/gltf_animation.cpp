// Reading and validating glTF animations, skins and morph target counts.
#include "scene/gltf_animation.h"

#include <string>

#include "scene/gltf_accessors.h"

namespace wp::gltf {

namespace {

std::string animationWhere(const tinygltf::Animation& animation, size_t index) {
  return describe("animation", index, animation.name);
}

AnimationSampler readSampler(const Context& ctx, const tinygltf::AnimationSampler& gltfSampler,
                             const std::string& where) {
  AnimationSampler sampler;
  if (gltfSampler.interpolation == "STEP") {
    sampler.interpolation = Interpolation::Step;
  } else if (gltfSampler.interpolation == "CUBICSPLINE") {
    sampler.interpolation = Interpolation::CubicSpline;
  } else if (gltfSampler.interpolation == "LINEAR" || gltfSampler.interpolation.empty()) {
    sampler.interpolation = Interpolation::Linear;
  } else {
    fail(ctx, where,
         "interpolation '" + oneLine(gltfSampler.interpolation) +
             "' is not LINEAR, STEP or CUBICSPLINE; fix the sampler");
  }
  const FloatElements input = readFloats(ctx, gltfSampler.input, where, "sampler input", false);
  if (input.components != 1 || input.values.empty()) {
    fail(ctx, where, "the input must be a non-empty SCALAR accessor of times; re-export the file");
  }
  for (size_t k = 1; k < input.values.size(); ++k) {
    if (!(input.values[k] > input.values[k - 1])) {
      fail(ctx, where,
           "input times are not strictly increasing (keyframe " + std::to_string(k) + " at " +
               std::to_string(input.values[k]) + " s follows " + std::to_string(input.values[k - 1]) +
               " s); sort or deduplicate the keyframes");
    }
  }
  sampler.input = input.values;
  const FloatElements output = readFloats(ctx, gltfSampler.output, where, "sampler output", true);
  sampler.output = output.values;
  sampler.width = output.components;
  return sampler;
}

// Checks that the sampler has one value (three with CUBICSPLINE tangents) of `width` floats
// per keyframe, and records the width the channel reads it with.
void fitWidth(const Context& ctx, AnimationSampler& sampler, size_t width, const std::string& where) {
  const size_t perKeyframe = sampler.interpolation == Interpolation::CubicSpline ? 3 : 1;
  const size_t expected = sampler.input.size() * perKeyframe * width;
  if (sampler.output.size() != expected) {
    fail(ctx, where,
         "the output has " + std::to_string(sampler.output.size()) + " numbers but " +
             std::to_string(sampler.input.size()) + " keyframes" + (perKeyframe == 3 ? " (x3 for CUBICSPLINE)" : "") +
             " of " + std::to_string(width) + " numbers need " + std::to_string(expected) +
             "; re-export the animation");
  }
  sampler.width = width;
}

void readChannel(const Context& ctx, Animation& animation, const tinygltf::AnimationChannel& gltfChannel,
                 std::vector<bool>& widthFixed, const std::vector<size_t>& morphTargets, const std::string& where) {
  const tinygltf::Model& model = ctx.model;
  const int node = gltfChannel.target_node;
  if (node < 0 || static_cast<size_t>(node) >= model.nodes.size()) {
    fail(ctx, where,
         "its target node " + missingIndex(node, model.nodes.size(), "nodes") + "; fix the channel's target");
  }
  if (gltfChannel.sampler < 0 || static_cast<size_t>(gltfChannel.sampler) >= animation.samplers.size()) {
    fail(ctx, where,
         "sampler " + missingIndex(gltfChannel.sampler, animation.samplers.size(), "samplers in this animation") +
             "; fix the channel");
  }
  AnimationChannel channel{static_cast<uint32_t>(gltfChannel.sampler), static_cast<uint32_t>(node)};
  size_t width = 3;
  const std::string& path = gltfChannel.target_path;
  if (path == "translation") {
    channel.path = AnimationPath::Translation;
  } else if (path == "rotation") {
    channel.path = AnimationPath::Rotation;
    width = 4;
  } else if (path == "scale") {
    channel.path = AnimationPath::Scale;
  } else if (path == "weights") {
    channel.path = AnimationPath::Weights;
    width = morphTargets[static_cast<size_t>(node)];
    if (width == 0) {
      fail(ctx, where,
           "it animates the morph weights of " + describe("node", static_cast<size_t>(node), model.nodes[node].name) +
               ", whose mesh has no morph targets; fix the channel's target");
    }
  } else {
    return warnAt(ctx, where, "path '" + oneLine(path) + "' is not animated by wavepath; skipped");
  }
  if (channel.path != AnimationPath::Weights && !model.nodes[static_cast<size_t>(node)].matrix.empty()) {
    fail(ctx, where,
         "it animates " + describe("node", static_cast<size_t>(node), model.nodes[node].name) +
             ", which has a matrix, but glTF animates only nodes given by translation, rotation and scale; "
             "re-export the node with TRS");
  }
  AnimationSampler& sampler = animation.samplers[channel.sampler];
  const std::string samplerWhere = where + ": sampler " + std::to_string(channel.sampler);
  if (widthFixed[channel.sampler] && sampler.width != width) {
    fail(ctx, samplerWhere, "channels read it as values of different sizes; give each path its own sampler");
  }
  fitWidth(ctx, sampler, width, samplerWhere);
  widthFixed[channel.sampler] = true;
  animation.channels.push_back(channel);
}

}  // namespace

size_t morphTargetCount(const Context& ctx, size_t index) {
  const tinygltf::Mesh& mesh = ctx.model.meshes[index];
  const std::string where = describe("mesh", index, mesh.name);
  size_t count = 0;
  bool first = true;
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    if (primitive.mode < TINYGLTF_MODE_TRIANGLES) continue;  // skipped by the mesh conversion
    if (!first && primitive.targets.size() != count) {
      fail(ctx, where,
           "primitive " + std::to_string(p) + " has " + std::to_string(primitive.targets.size()) +
               " morph targets but an earlier one " + std::to_string(count) +
               "; glTF needs the same count in every primitive: re-export the mesh");
    }
    count = primitive.targets.size();
    first = false;
  }
  if (!mesh.weights.empty() && mesh.weights.size() != count) {
    fail(ctx, where,
         "it has " + std::to_string(mesh.weights.size()) + " default weights but " + std::to_string(count) +
             " morph targets; give one weight per target");
  }
  return count;
}

std::vector<Animation> readAnimations(const Context& ctx, const std::vector<size_t>& morphTargets) {
  std::vector<Animation> animations;
  for (size_t a = 0; a < ctx.model.animations.size(); ++a) {
    const tinygltf::Animation& gltfAnimation = ctx.model.animations[a];
    const std::string where = animationWhere(gltfAnimation, a);
    Animation animation;
    animation.name = gltfAnimation.name;
    for (size_t s = 0; s < gltfAnimation.samplers.size(); ++s) {
      const std::string samplerWhere = where + ": sampler " + std::to_string(s);
      animation.samplers.push_back(readSampler(ctx, gltfAnimation.samplers[s], samplerWhere));
    }
    std::vector<bool> widthFixed(animation.samplers.size(), false);
    for (size_t c = 0; c < gltfAnimation.channels.size(); ++c) {
      readChannel(ctx, animation, gltfAnimation.channels[c], widthFixed, morphTargets,
                  where + ": channel " + std::to_string(c));
    }
    animations.push_back(std::move(animation));
  }
  return animations;
}

Skin readSkin(const Context& ctx, size_t index) {
  const tinygltf::Skin& gltfSkin = ctx.model.skins[index];
  const std::string where = describe("skin", index, gltfSkin.name);
  Skin skin;
  for (int joint : gltfSkin.joints) {
    if (joint < 0 || static_cast<size_t>(joint) >= ctx.model.nodes.size()) {
      fail(ctx, where, "joint node " + missingIndex(joint, ctx.model.nodes.size(), "nodes") + "; fix the skin");
    }
    skin.joints.push_back(static_cast<uint32_t>(joint));
  }
  skin.inverseBind.assign(skin.joints.size(), glm::mat4(1.0f));
  if (gltfSkin.inverseBindMatrices >= 0) {
    const FloatElements m = readFloats(ctx, gltfSkin.inverseBindMatrices, where, "inverseBindMatrices", false);
    if (m.components != 16 || m.values.size() / 16 < skin.joints.size()) {
      fail(ctx, where,
           "inverseBindMatrices must be MAT4 with one matrix per joint (" + std::to_string(skin.joints.size()) +
               "); re-export the skin");
    }
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      for (int i = 0; i < 16; ++i) skin.inverseBind[j][i / 4][i % 4] = m.values[16 * j + size_t(i)];  // column-major
    }
  }
  return skin;
}

}  // namespace wp::gltf
