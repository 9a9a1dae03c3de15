// The depth-first walk over the default scene's node hierarchy, composing transforms.
#include "scene/gltf_nodes.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace wp::gltf {

namespace {

constexpr int kRoot = -1;
constexpr int kUnreached = -2;

bool isFinite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

std::string nodeName(const Context& ctx, size_t index) {
  return describe("node", index, ctx.model.nodes[index].name);
}

void checkLength(const Context& ctx, size_t index, const std::vector<double>& values, size_t length, const char* what) {
  if (!values.empty() && values.size() != length) {
    fail(ctx, nodeName(ctx, index),
         std::string(what) + " needs " + std::to_string(length) + " numbers, not " + std::to_string(values.size()) +
             "; re-export the file");
  }
}

// In double precision, so deep hierarchies and large offsets lose nothing before the
// final conversion to float.
glm::dmat4 localTransform(const Context& ctx, size_t index) {
  const tinygltf::Node& node = ctx.model.nodes[index];
  checkLength(ctx, index, node.matrix, 16, "matrix");
  checkLength(ctx, index, node.translation, 3, "translation");
  checkLength(ctx, index, node.rotation, 4, "rotation");
  checkLength(ctx, index, node.scale, 3, "scale");
  glm::dmat4 local(1.0);
  if (!node.matrix.empty()) {
    for (int i = 0; i < 16; ++i) local[i / 4][i % 4] = node.matrix[static_cast<size_t>(i)];  // column-major
  } else {
    const std::vector<double>& t = node.translation;
    const std::vector<double>& r = node.rotation;
    const std::vector<double>& s = node.scale;
    if (!t.empty()) local = glm::translate(local, glm::dvec3(t[0], t[1], t[2]));
    if (!r.empty()) {
      const glm::dquat q(r[3], r[0], r[1], r[2]);  // glTF stores x, y, z, w
      const double length = glm::length(q);
      if (!(length > 0.0) || !std::isfinite(length)) {
        fail(ctx, nodeName(ctx, index), "rotation is not a rotation quaternion (its length is 0); fix the node");
      }
      local *= glm::mat4_cast(q / length);
    }
    if (!s.empty()) local = glm::scale(local, glm::dvec3(s[0], s[1], s[2]));
  }
  return local;
}

class Walker {
public:
  Walker(const Context& ctx, const std::function<void(size_t, const glm::mat4&)>& visit)
      : ctx_(ctx), visit_(visit), onPath_(ctx.model.nodes.size(), false),
        reachedFrom_(ctx.model.nodes.size(), kUnreached) {}

  void run(const std::vector<int>& roots, const std::string& where) {
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) push(*it, kRoot, glm::dmat4(1.0), where);
    while (!stack_.empty()) {
      const Entry entry = stack_.back();
      stack_.pop_back();
      if (entry.leaving) {
        onPath_[entry.node] = false;
      } else {
        enter(entry);
      }
    }
  }

private:
  struct Entry {
    size_t node;
    int parent;  // kRoot for a root of the scene
    glm::dmat4 parentWorld;
    bool leaving;  // marks the end of the node's subtree, taking it off the current path
  };

  void push(int node, int parent, const glm::dmat4& parentWorld, const std::string& where) {
    if (node < 0 || static_cast<size_t>(node) >= ctx_.model.nodes.size()) {
      fail(ctx_, where,
           (parent == kRoot ? "node " : "child node ") + missingIndex(node, ctx_.model.nodes.size(), "nodes") +
               "; re-export the file");
    }
    stack_.push_back({static_cast<size_t>(node), parent, parentWorld, false});
  }

  void enter(const Entry& entry) {
    const size_t node = entry.node;
    if (onPath_[node]) {
      fail(ctx_, nodeName(ctx_, node),
           "it is its own ancestor, so the node hierarchy has a cycle; fix the node hierarchy");
    }
    if (reachedFrom_[node] != kUnreached) failReachedTwice(node, reachedFrom_[node], entry.parent);
    reachedFrom_[node] = entry.parent;

    const glm::dmat4 world = entry.parentWorld * localTransform(ctx_, node);
    if (!isFinite(world)) {
      fail(ctx_, nodeName(ctx_, node), "its transform is not finite; fix the node's transform");
    }
    visit_(node, glm::mat4(world));

    onPath_[node] = true;
    stack_.push_back({node, entry.parent, world, true});
    const std::vector<int>& children = ctx_.model.nodes[node].children;
    for (auto it = children.rbegin(); it != children.rend(); ++it) {
      push(*it, static_cast<int>(node), world, nodeName(ctx_, node));
    }
  }

  [[noreturn]] void failReachedTwice(size_t node, int first, int second) const {
    const auto parentName = [&](int parent) { return nodeName(ctx_, static_cast<size_t>(parent)); };
    std::string why;
    if (first != kRoot && second != kRoot) {
      why = "it is a child of both " + parentName(first) + " and " + parentName(second) +
            ", but a glTF node may have only one parent";
    } else if (first == kRoot && second == kRoot) {
      why = "the scene lists it twice";
    } else {
      why = "it is both a root of the scene and a child of " + parentName(std::max(first, second)) +
            ", but a glTF node may have only one parent";
    }
    fail(ctx_, nodeName(ctx_, node), why + "; fix the node hierarchy");
  }

  const Context& ctx_;
  const std::function<void(size_t, const glm::mat4&)>& visit_;
  std::vector<Entry> stack_;
  std::vector<bool> onPath_;
  std::vector<int> reachedFrom_;  // the parent the walk first came from, kRoot or kUnreached
};

// Nodes that are nobody's child, for files without scenes.
std::vector<int> rootNodes(const tinygltf::Model& model) {
  std::vector<bool> isChild(model.nodes.size(), false);
  for (const tinygltf::Node& node : model.nodes) {
    for (int child : node.children) {
      if (child >= 0 && static_cast<size_t>(child) < isChild.size()) isChild[static_cast<size_t>(child)] = true;
    }
  }
  std::vector<int> roots;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    if (!isChild[i]) roots.push_back(static_cast<int>(i));
  }
  return roots;
}

}  // namespace

std::optional<size_t> sceneToWalk(const Context& ctx, std::optional<size_t> chosen) {
  const tinygltf::Model& model = ctx.model;
  if (chosen) {
    if (*chosen >= model.scenes.size()) {
      fail(ctx, "", "--scene " + std::to_string(*chosen) + ": scene " +
                        missingIndex(static_cast<long long>(*chosen), model.scenes.size(), "scenes") +
                        "; scenes count from 0");
    }
    return chosen;
  }
  if (model.scenes.empty() && model.defaultScene == -1) return std::nullopt;
  const int scene = model.defaultScene == -1 ? 0 : model.defaultScene;
  if (scene < 0 || static_cast<size_t>(scene) >= model.scenes.size()) {
    fail(ctx, "", "the default scene " + missingIndex(scene, model.scenes.size(), "scenes") + "; fix \"scene\"");
  }
  return static_cast<size_t>(scene);
}

void walkScene(const Context& ctx, std::optional<size_t> scene,
               const std::function<void(size_t node, const glm::mat4& world)>& visit) {
  Walker walker(ctx, visit);
  if (!scene) {
    walker.run(rootNodes(ctx.model), "");
    return;
  }
  const tinygltf::Scene& chosen = ctx.model.scenes[*scene];
  walker.run(chosen.nodes, describe("scene", *scene, chosen.name));
}

}  // namespace wp::gltf
