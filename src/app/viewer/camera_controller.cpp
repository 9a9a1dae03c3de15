// Fly and orbit camera control, free of any window system so it is tested directly.
#include "app/viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace wp {

namespace {

glm::vec3 rotate(glm::vec3 v, float angle, glm::vec3 axis) {
  return glm::vec3(glm::rotate(glm::mat4(1.0f), angle, axis) * glm::vec4(v, 0.0f));
}

}  // namespace

CameraController::CameraController(const Camera& home, float speed)
    : home_(home), camera_(home), worldUp_(home.up), homeSpeed_(speed), speed_(speed) {}

glm::vec3 CameraController::turn(glm::vec3 direction, float yaw, float pitch) const {
  glm::vec3 d = rotate(direction, yaw, worldUp_);
  // Pitch limited so the direction never reaches the up axis, where yaw would be undefined.
  const float limit = glm::radians(89.0f);
  float elevation = std::asin(std::clamp(glm::dot(d, worldUp_), -1.0f, 1.0f));
  float target = std::clamp(elevation + pitch, -limit, limit);
  // About cross(d, up) a positive angle raises d towards up.
  return glm::normalize(rotate(d, target - elevation, glm::normalize(glm::cross(d, worldUp_))));
}

void CameraController::setForward(glm::vec3 forward) {
  camera_.forward = glm::normalize(forward);
  glm::vec3 right = glm::normalize(glm::cross(camera_.forward, worldUp_));
  camera_.up = glm::normalize(glm::cross(right, camera_.forward));
}

void CameraController::setHome(const Camera& home) {
  home_ = home;
  if (atHome_) {
    camera_ = home;
    worldUp_ = home.up;
  }
}

bool CameraController::update(const CameraInput& in, float pivotDistance) {
  bool moved = false;  // by the user, as opposed to a reset
  if (in.reset) {
    camera_ = home_;
    worldUp_ = home_.up;
    speed_ = homeSpeed_;
    mode_ = CameraMode::Fly;
  }
  if (in.toggleOrbit) {
    mode_ = mode_ == CameraMode::Fly ? CameraMode::Orbit : CameraMode::Fly;
    if (mode_ == CameraMode::Orbit) {
      pivot_ = camera_.position + camera_.forward * pivotDistance;
    }
  }
  // Mouse right turns the view right (negative yaw about up); mouse down (screen y grows
  // downwards) looks down.
  float yaw = -in.mouseDelta.x * kTurnPerPixel;
  float pitch = -in.mouseDelta.y * kTurnPerPixel;
  if (mode_ == CameraMode::Fly) {
    if (in.scroll != 0.0f) {
      speed_ *= std::pow(kWheelStep, in.scroll);
    }
    if (yaw != 0.0f || pitch != 0.0f) {
      setForward(turn(camera_.forward, yaw, pitch));
      moved = true;
    }
  } else {
    float distance = glm::length(pivot_ - camera_.position);
    if (in.scroll != 0.0f) {
      distance /= std::pow(kWheelStep, in.scroll);
    }
    if (yaw != 0.0f || pitch != 0.0f || in.scroll != 0.0f) {
      // The view turns as in fly mode and the camera stays on the pivot's far side from it:
      // dragging right carries the camera left around the pivot, so the scene seems to turn
      // with the cursor.
      glm::vec3 forward = turn(camera_.forward, yaw, pitch);
      camera_.position = pivot_ - forward * distance;
      setForward(forward);
      moved = true;
    }
  }
  if (in.move != glm::vec3(0.0f) && in.seconds > 0.0) {
    glm::vec3 right = glm::normalize(glm::cross(camera_.forward, worldUp_));
    glm::vec3 step = (right * in.move.x + worldUp_ * in.move.y + camera_.forward * in.move.z) *
                     (speed_ * float(in.seconds));
    camera_.position += step;
    pivot_ += step;
    moved = true;
  }
  atHome_ = (atHome_ || in.reset) && !moved;
  return in.reset || moved;
}

}  // namespace wp
