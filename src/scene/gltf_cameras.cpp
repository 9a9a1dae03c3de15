// glTF cameras: conversion at their node and selection by --camera.
#include "scene/gltf_cameras.h"

#include <cmath>
#include <numbers>
#include <optional>

#include "scene/gltf_camera_extras.h"
#include "scene/scene_camera.h"

namespace wp::gltf {

namespace {

bool isIndex(const std::string& text) {
  return !text.empty() && text.size() < 10 && text.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

bool cameraSelected(const Context& ctx, const std::string& selection, size_t camera, size_t node) {
  if (selection.empty()) return true;
  if (isIndex(selection)) return std::stoul(selection) == camera;
  return ctx.model.cameras[camera].name == selection || ctx.model.nodes[node].name == selection;
}

std::string cameraList(const Context& ctx) {
  if (ctx.model.cameras.empty()) return "the file has no cameras";
  std::string list = "its cameras: ";
  for (size_t i = 0; i < ctx.model.cameras.size(); ++i) {
    list += (i ? ", " : "") + describe("camera", i, ctx.model.cameras[i].name);
  }
  return list;
}

Camera convertCamera(const Context& ctx, size_t index, const std::string& nodeWhere, const glm::mat4& world) {
  const tinygltf::Camera& camera = ctx.model.cameras[index];
  const std::string where = nodeWhere + ": " + describe("camera", index, camera.name);
  Camera out;
  float yfov = kFramingYfov;
  float aspectRatio = 0.0f;
  if (camera.type == "perspective") {
    yfov = static_cast<float>(camera.perspective.yfov);
    aspectRatio = static_cast<float>(camera.perspective.aspectRatio);
    if (!(camera.perspective.yfov > 0.0 && camera.perspective.yfov < std::numbers::pi)) {
      fail(ctx, where, "yfov must be between 0 and pi radians; fix the camera");
    }
    if (!(camera.perspective.aspectRatio >= 0.0) || !std::isfinite(camera.perspective.aspectRatio)) {
      fail(ctx, where, "aspectRatio must be a number > 0; fix the camera");
    }
  } else if (camera.type == "orthographic") {
    const double xmag = std::fabs(camera.orthographic.xmag);
    const double ymag = std::fabs(camera.orthographic.ymag);
    if (!(xmag > 0.0 && ymag > 0.0) || !std::isfinite(xmag) || !std::isfinite(ymag) ||
        !std::isfinite(float(xmag / ymag)) || !(float(xmag / ymag) > 0.0f)) {
      fail(ctx, where, "xmag and ymag must be finite numbers other than 0; fix the camera");
    }
    aspectRatio = static_cast<float>(xmag / ymag);
  } else {
    fail(ctx, where, "type '" + oneLine(camera.type) + "' is neither perspective nor orthographic; fix the camera");
  }
  const std::optional<Camera> placed = cameraFromNode(world, yfov, aspectRatio);
  if (!placed) {
    fail(ctx, where, "the node's transform collapses the view or up direction; fix the node's scale");
  }
  out = *placed;
  if (camera.type == "orthographic") {
    out.orthographic = true;
    out.orthographicHalfHeight = static_cast<float>(std::fabs(camera.orthographic.ymag));
  } else {
    out.optics = readCameraOptics(ctx, index);
  }
  return out;
}

}  // namespace wp::gltf
