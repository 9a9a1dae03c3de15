// Loading a glTF 2.0 file (.gltf or .glb) into a wavepath scene.
//
// wavepath shapes in node extras (a stable schema; the README quotes it):
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
//   Physical camera settings in a camera's extras (all optional; the README quotes them):
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

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/log.h"
#include "scene/gltf_camera_extras.h"
#include "scene/gltf_context.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_extras.h"
#include "scene/gltf_file.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_mesh.h"
#include "scene/gltf_nodes.h"
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

bool hasArea(const Mesh& mesh, size_t triangle) {
  const glm::vec3& a = mesh.positions[mesh.indices[3 * triangle]];
  const glm::vec3& b = mesh.positions[mesh.indices[3 * triangle + 1]];
  const glm::vec3& c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return glm::length(glm::cross(b - a, c - a)) > 0.0f;
}

class SceneBuilder {
public:
  SceneBuilder(const gltf::Context& ctx, bool defaultSky)
      : ctx_(ctx), defaultSky_(defaultSky), sceneMeshOf_(ctx.model.meshes.size(), kNotConverted) {}

  Scene build() {
    scene_.materials = gltf::convertMaterials(ctx_, scene_.textures);
    defaultMaterial_ = static_cast<uint32_t>(scene_.materials.size());
    gltf::walkDefaultScene(ctx_, [this](size_t node, const glm::mat4& world) { visit(node, world); });
    if (scene_.instances.empty() && scene_.spheres.empty() && scene_.planes.empty()) {
      gltf::fail(ctx_, "",
                 "nothing to render: the default scene has no triangles, spheres or planes; add a triangle mesh or a "
                 "wavepath shape");
    }
    if (usesDefaultMaterial()) scene_.materials.push_back(gltf::defaultMaterial());
    if (!scene_.hasCamera) {
      scene_.camera = frameScene(scene_);
      note(ctx_.file + " has no camera: looking at the whole scene from +z with a 45 degree vertical field of view");
    }
    if (defaultSky_ && !hasEmitters()) {
      scene_.sky = makeEnvironmentMap(1, 1, {glm::vec3(1.0f)});
      note(ctx_.file + " has no emissive triangles: lighting it with a constant white sky");
    }
    return std::move(scene_);
  }

private:
  void visit(size_t index, const glm::mat4& world) {
    const tinygltf::Node& node = ctx_.model.nodes[index];
    const std::string where = gltf::describe("node", index, node.name);
    if (node.mesh != -1) addInstance(where, node.mesh, world);
    if (node.camera != -1) addCamera(where, node.camera, world);
    if (const std::optional<gltf::ShapeSpec> shape = gltf::readShape(ctx_, index)) addShape(where, *shape, world);
  }

  void addInstance(const std::string& where, int gltfMesh, const glm::mat4& world) {
    const size_t meshCount = ctx_.model.meshes.size();
    if (gltfMesh < 0 || static_cast<size_t>(gltfMesh) >= meshCount) {
      gltf::fail(ctx_, where, "mesh " + gltf::missingIndex(gltfMesh, meshCount, "meshes") + "; re-export the file");
    }
    if (!isInvertible(world)) return skipSingular(where, "mesh");
    int& sceneMesh = sceneMeshOf_[static_cast<size_t>(gltfMesh)];
    if (sceneMesh == kNotConverted) {
      Mesh mesh = gltf::convertMesh(ctx_, static_cast<size_t>(gltfMesh), defaultMaterial_);
      sceneMesh = mesh.triangleCount() == 0 ? kNoTriangles : static_cast<int>(scene_.meshes.size());
      if (sceneMesh != kNoTriangles) scene_.meshes.push_back(std::move(mesh));
    }
    if (sceneMesh != kNoTriangles) scene_.instances.push_back({static_cast<uint32_t>(sceneMesh), world});
  }

  void addCamera(const std::string& nodeWhere, int index, const glm::mat4& world) {
    const size_t cameraCount = ctx_.model.cameras.size();
    if (index < 0 || static_cast<size_t>(index) >= cameraCount) {
      gltf::fail(ctx_, nodeWhere, "camera " + gltf::missingIndex(index, cameraCount, "cameras") + "; re-export the file");
    }
    if (scene_.hasCamera) return;  // the first perspective camera of the walk wins
    const tinygltf::Camera& camera = ctx_.model.cameras[static_cast<size_t>(index)];
    const std::string where = nodeWhere + ": " + gltf::describe("camera", static_cast<size_t>(index), camera.name);
    if (camera.type != "perspective") {
      const std::string type = gltf::oneLine(camera.type);
      return gltf::warnAt(ctx_, where, "'" + type + "' cameras are not supported; skipped");
    }
    const double yfov = camera.perspective.yfov;
    const double aspectRatio = camera.perspective.aspectRatio;
    if (!(yfov > 0.0 && yfov < std::numbers::pi)) {
      gltf::fail(ctx_, where, "yfov must be between 0 and pi radians; fix the camera");
    }
    if (!(aspectRatio >= 0.0) || !std::isfinite(aspectRatio)) {
      gltf::fail(ctx_, where, "aspectRatio must be a number > 0; fix the camera");
    }
    const std::optional<Camera> result =
        cameraFromNode(world, static_cast<float>(yfov), static_cast<float>(aspectRatio));
    if (!result) {
      gltf::fail(ctx_, where, "the node's transform collapses the view or up direction; fix the node's scale");
    }
    scene_.camera = *result;
    scene_.camera.optics = gltf::readCameraOptics(ctx_, static_cast<size_t>(index));
    scene_.hasCamera = true;
  }

  void addShape(const std::string& where, const gltf::ShapeSpec& shape, const glm::mat4& world) {
    const uint32_t material = shape.material == -1 ? defaultMaterial_ : static_cast<uint32_t>(shape.material);
    const bool sphere = shape.kind == gltf::ShapeSpec::Kind::Sphere;
    if (!isInvertible(world)) return skipSingular(where, sphere ? "sphere" : "plane");
    if (sphere) {
      const glm::mat4 objectToWorld = glm::scale(world, glm::vec3(static_cast<float>(shape.radius)));
      if (!isInvertible(objectToWorld)) return skipSingular(where, "sphere");
      scene_.spheres.push_back({objectToWorld, material});
    } else {
      const glm::vec3 normal = glm::normalize(glm::transpose(glm::inverse(glm::mat3(world))) * glm::vec3(0, 1, 0));
      scene_.planes.push_back({normal, glm::dot(normal, glm::vec3(world[3])), material});
    }
  }

  void skipSingular(const std::string& where, const char* what) {
    gltf::warnAt(ctx_, where, std::string("its transform is singular (a scale of 0?), so its ") + what + " is skipped");
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

  // Emissive triangles with area, in a mesh that has an instance, or emissive shapes: an
  // emissive sphere or plane lights the scene too, so it must not get the white sky.
  bool hasEmitters() const {
    const auto emissive = [this](uint32_t m) { return scene_.materials[m].isEmissive(); };
    std::vector<bool> meshEmits(scene_.meshes.size(), false);
    for (size_t i = 0; i < scene_.meshes.size(); ++i) {
      const Mesh& mesh = scene_.meshes[i];
      for (size_t t = 0; t < mesh.triangleCount() && !meshEmits[i]; ++t) {
        meshEmits[i] = emissive(mesh.materials[t]) && hasArea(mesh, t);
      }
    }
    for (const MeshInstance& instance : scene_.instances) {
      if (meshEmits[instance.mesh]) return true;
    }
    for (const Sphere& sphere : scene_.spheres) {
      if (emissive(sphere.material)) return true;
    }
    for (const Plane& plane : scene_.planes) {
      if (emissive(plane.material)) return true;
    }
    return false;
  }

  const gltf::Context& ctx_;
  const bool defaultSky_;
  Scene scene_;
  uint32_t defaultMaterial_ = 0;
  std::vector<int> sceneMeshOf_;  // glTF mesh -> index in scene_.meshes, kNotConverted or kNoTriangles
};

}  // namespace

Scene loadScene(const std::filesystem::path& file, bool defaultSky) {
  const tinygltf::Model model = gltf::parseGltfFile(file);
  const gltf::Context ctx{file.string(), model};
  gltf::checkExtensions(ctx);
  return SceneBuilder(ctx, defaultSky).build();
}

}  // namespace wp
