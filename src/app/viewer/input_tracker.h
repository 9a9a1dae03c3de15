// Turns window events (GLFW key and mouse codes) into one frame's viewer input, without a window.
#pragma once

#include <set>

#include "app/viewer/camera_controller.h"

namespace wp {

struct FrameInput {
  CameraInput camera;
  bool screenshot = false;   // save the display (PNG) and the radiance (EXR)
  bool togglePanel = false;  // show or hide the settings panel
  bool togglePlayback = false;  // play or pause the animation
};

// Keys: W/S forward and back, A/D left and right, E/Q up and down, Tab fly/orbit, R reset
// to the scene's camera, P or F12 screenshot, F1 panel, Space play/pause. Mouse: drag with the left or right button to
// look (fly) or orbit, wheel for speed (fly) or distance (orbit). Codes and actions are
// GLFW's (GLFW_KEY_*, GLFW_PRESS / GLFW_RELEASE / GLFW_REPEAT, GLFW_MOUSE_BUTTON_*).
class InputTracker {
public:
  void onKey(int key, int action);
  void onMouseButton(int button, int action);
  void onCursor(double x, double y);
  void onScroll(double steps);
  // Releases every held key and button (the window lost focus: their releases go elsewhere).
  void releaseAll();

  // The input gathered since the last call, for a frame that lasted `seconds`. Held keys
  // keep moving the camera in the next frames; presses of one-shot keys are consumed.
  FrameInput takeFrame(double seconds);

private:
  std::set<int> heldKeys_;
  int heldButtons_ = 0;
  bool hasCursor_ = false;
  double cursorX_ = 0.0, cursorY_ = 0.0;
  FrameInput pending_;
};

}  // namespace wp
