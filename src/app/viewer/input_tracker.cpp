// Window events to viewer input: held movement keys, mouse drags, wheel and one-shot keys.
#include "app/viewer/input_tracker.h"

#include <GLFW/glfw3.h>

namespace wp {

void InputTracker::onKey(int key, int action) {
  if (action == GLFW_RELEASE) {
    heldKeys_.erase(key);
    return;
  }
  if (action == GLFW_REPEAT) {
    return;  // held keys already move every frame; repeats would only add one-shot actions
  }
  heldKeys_.insert(key);
  switch (key) {
    case GLFW_KEY_TAB: pending_.camera.toggleOrbit = !pending_.camera.toggleOrbit; break;
    case GLFW_KEY_R: pending_.camera.reset = true; break;
    case GLFW_KEY_P:
    case GLFW_KEY_F12: pending_.screenshot = true; break;
    case GLFW_KEY_F1: pending_.togglePanel = !pending_.togglePanel; break;
    case GLFW_KEY_SPACE: pending_.togglePlayback = !pending_.togglePlayback; break;
    default: break;
  }
}

void InputTracker::onMouseButton(int button, int action) {
  if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) {
    return;
  }
  int bit = 1 << button;
  heldButtons_ = action == GLFW_PRESS ? heldButtons_ | bit : heldButtons_ & ~bit;
}

void InputTracker::onCursor(double x, double y) {
  // Motion counts only while a button is held; the first position only sets the origin.
  if (hasCursor_ && heldButtons_ != 0) {
    pending_.camera.mouseDelta += glm::vec2(float(x - cursorX_), float(y - cursorY_));
  }
  cursorX_ = x;
  cursorY_ = y;
  hasCursor_ = true;
}

void InputTracker::onScroll(double steps) { pending_.camera.scroll += float(steps); }

void InputTracker::releaseAll() {
  heldKeys_.clear();
  heldButtons_ = 0;
}

FrameInput InputTracker::takeFrame(double seconds) {
  auto held = [&](int key) { return heldKeys_.count(key) ? 1.0f : 0.0f; };
  FrameInput frame = pending_;
  frame.camera.move = glm::vec3(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                                held(GLFW_KEY_W) - held(GLFW_KEY_S));
  frame.camera.seconds = seconds;
  pending_ = FrameInput{};
  return frame;
}

}  // namespace wp
