// The viewer's camera control as pure logic: one frame's input in, the scene camera out.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace wp {

// What the user did during one displayed frame, already decoded from keys and mouse
// (InputTracker does that from window events).
struct CameraInput {
  glm::vec3 move{0.0f};       // held movement keys: +x right, +y up, +z forward (each -1, 0 or 1)
  glm::vec2 mouseDelta{0.0f};  // cursor motion in pixels while the look/orbit button was held
  float scroll = 0.0f;         // wheel steps, positive away from the user
  double seconds = 0.0;        // how long the frame lasted (movement is per second)
  bool reset = false;          // back to the scene's camera
  bool toggleOrbit = false;    // switch between fly and orbit
};

enum class CameraMode { Fly, Orbit };

// Fly: movement keys translate along the view axes, the mouse turns the view about the
// scene camera's up axis (yaw) and the right axis (pitch), the wheel scales the speed.
// Orbit: the mouse turns the camera around a pivot it keeps looking at, the wheel moves it
// closer or farther, movement keys pan camera and pivot together.
class CameraController {
public:
  // `home` is the scene's camera (also what reset returns to); `speed` is the initial fly
  // speed in scene units per second.
  CameraController(const Camera& home, float speed);

  // Applies one frame of input; returns whether the camera changed (which restarts the
  // accumulation). Entering orbit mode pivots about the point `pivotDistance` ahead.
  bool update(const CameraInput& input, float pivotDistance);

  // The scene's camera moved (it sits on an animated node): reset returns to `home` from now
  // on, and a view the user has not moved since the start or the last reset follows it.
  void setHome(const Camera& home);

  const Camera& camera() const { return camera_; }
  CameraMode mode() const { return mode_; }
  float speed() const { return speed_; }
  glm::vec3 pivot() const { return pivot_; }

  // Radians the view turns per pixel of mouse motion.
  static constexpr float kTurnPerPixel = 0.004f;
  // Factor of speed (fly) or of 1 / pivot distance (orbit) per wheel step.
  static constexpr float kWheelStep = 1.2f;

private:
  // Turns the view direction by yaw about the up axis and pitch about the right axis,
  // keeping it at least ~1 degree away from straight up or down so the frame stays defined.
  glm::vec3 turn(glm::vec3 direction, float yaw, float pitch) const;
  void setForward(glm::vec3 forward);

  Camera home_;
  Camera camera_;
  glm::vec3 worldUp_;
  float homeSpeed_;
  float speed_;
  CameraMode mode_ = CameraMode::Fly;
  bool atHome_ = true;  // the user has not moved the view since the start or the last reset
  glm::vec3 pivot_{0.0f};
};

}  // namespace wp
