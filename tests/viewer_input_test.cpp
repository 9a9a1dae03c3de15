// The viewer's input handling without a window: GLFW key and mouse events through the
// InputTracker into the CameraController, checked against the motion they must cause.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <cmath>

#include "app/viewer/camera_controller.h"
#include "app/viewer/input_tracker.h"

namespace wp {
namespace {

// Single-precision rotations and sums of a few unit vectors: 1e-5 is far above their
// rounding (~1e-7 per operation) and far below any motion the tests expect (>= 1e-2).
constexpr float kTol = 1e-5f;

Camera homeCamera() {
  Camera c;
  c.position = {1.0f, 2.0f, 3.0f};
  c.forward = {0.0f, 0.0f, -1.0f};
  c.up = {0.0f, 1.0f, 0.0f};
  return c;
}

void expectNear(glm::vec3 a, glm::vec3 b) {
  EXPECT_NEAR(a.x, b.x, kTol);
  EXPECT_NEAR(a.y, b.y, kTol);
  EXPECT_NEAR(a.z, b.z, kTol);
}

TEST(ViewerInput, HeldKeyMovesAtTheFlySpeedForTheFrameTime) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 2.0f);
  tracker.onKey(GLFW_KEY_W, GLFW_PRESS);
  EXPECT_TRUE(controller.update(tracker.takeFrame(0.25).camera, 1.0f));
  expectNear(controller.camera().position, {1.0f, 2.0f, 2.5f});  // 2 units/s * 0.25 s ahead (-z)
  // Still held: moves again; D adds a step to the right (+x for a camera looking down -z).
  tracker.onKey(GLFW_KEY_D, GLFW_PRESS);
  controller.update(tracker.takeFrame(0.5).camera, 1.0f);
  expectNear(controller.camera().position, {2.0f, 2.0f, 1.5f});
  tracker.onKey(GLFW_KEY_W, GLFW_RELEASE);
  tracker.onKey(GLFW_KEY_D, GLFW_RELEASE);
  EXPECT_FALSE(controller.update(tracker.takeFrame(0.5).camera, 1.0f));
  expectNear(controller.camera().position, {2.0f, 2.0f, 1.5f});
}

TEST(ViewerInput, UpAndDownFollowTheSceneCamerasUpAxis) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 1.0f);
  tracker.onKey(GLFW_KEY_E, GLFW_PRESS);
  controller.update(tracker.takeFrame(1.0).camera, 1.0f);
  expectNear(controller.camera().position, {1.0f, 3.0f, 3.0f});
  tracker.onKey(GLFW_KEY_E, GLFW_RELEASE);
  tracker.onKey(GLFW_KEY_Q, GLFW_PRESS);
  controller.update(tracker.takeFrame(2.0).camera, 1.0f);
  expectNear(controller.camera().position, {1.0f, 1.0f, 3.0f});
}

TEST(ViewerInput, MouseDragTurnsTheViewByTheTurnRate) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 1.0f);
  tracker.onCursor(100.0, 100.0);
  tracker.onCursor(150.0, 100.0);  // no button held: no turn
  EXPECT_FALSE(controller.update(tracker.takeFrame(0.1).camera, 1.0f));
  tracker.onMouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS);
  tracker.onCursor(250.0, 100.0);  // 100 px right
  EXPECT_TRUE(controller.update(tracker.takeFrame(0.1).camera, 1.0f));
  float angle = 100.0f * CameraController::kTurnPerPixel;
  // Turning right from -z goes towards +x.
  expectNear(controller.camera().forward, {std::sin(angle), 0.0f, -std::cos(angle)});
  expectNear(controller.camera().up, {0.0f, 1.0f, 0.0f});
  // 50 px down looks down by 50 * rate.
  tracker.onCursor(250.0, 150.0);
  controller.update(tracker.takeFrame(0.1).camera, 1.0f);
  float pitch = 50.0f * CameraController::kTurnPerPixel;
  EXPECT_NEAR(controller.camera().forward.y, -std::sin(pitch), kTol);
  EXPECT_NEAR(glm::dot(controller.camera().forward, controller.camera().up), 0.0f, kTol);
  EXPECT_NEAR(glm::length(controller.camera().forward), 1.0f, kTol);
}

TEST(ViewerInput, PitchStopsShortOfStraightUp) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 1.0f);
  tracker.onMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS);
  tracker.onCursor(0.0, 0.0);
  tracker.onCursor(0.0, -100000.0);  // far more than a quarter turn up
  controller.update(tracker.takeFrame(0.1).camera, 1.0f);
  EXPECT_NEAR(controller.camera().forward.y, std::sin(glm::radians(89.0f)), kTol);
  EXPECT_FALSE(std::isnan(controller.camera().up.x));
}

TEST(ViewerInput, WheelScalesTheFlySpeed) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 1.0f);
  tracker.onScroll(2.0);
  controller.update(tracker.takeFrame(0.1).camera, 1.0f);
  EXPECT_NEAR(controller.speed(), CameraController::kWheelStep * CameraController::kWheelStep, kTol);
}

TEST(ViewerInput, OrbitKeepsThePivotAheadAtItsDistance) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 1.0f);
  tracker.onKey(GLFW_KEY_TAB, GLFW_PRESS);
  tracker.onKey(GLFW_KEY_TAB, GLFW_RELEASE);
  controller.update(tracker.takeFrame(0.1).camera, 4.0f);
  ASSERT_EQ(controller.mode(), CameraMode::Orbit);
  expectNear(controller.pivot(), {1.0f, 2.0f, -1.0f});  // 4 units ahead
  tracker.onMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS);
  tracker.onCursor(0.0, 0.0);
  float quarterTurnPixels = glm::radians(90.0f) / CameraController::kTurnPerPixel;
  tracker.onCursor(quarterTurnPixels, 0.0);
  controller.update(tracker.takeFrame(0.1).camera, 4.0f);
  // A quarter turn about the pivot: still 4 units away and looking at it; dragging right
  // carries the camera to the pivot's -x side, looking along +x.
  const Camera& c = controller.camera();
  EXPECT_NEAR(glm::length(controller.pivot() - c.position), 4.0f, 1e-4f);
  expectNear(c.forward, {1.0f, 0.0f, 0.0f});
  expectNear(c.position, {-3.0f, 2.0f, -1.0f});
  // The wheel moves closer by the wheel step.
  tracker.onScroll(1.0);
  controller.update(tracker.takeFrame(0.1).camera, 4.0f);
  EXPECT_NEAR(glm::length(controller.pivot() - controller.camera().position), 4.0f / CameraController::kWheelStep,
              1e-4f);
}

TEST(ViewerInput, ResetReturnsToTheScenesCamera) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 1.0f);
  tracker.onKey(GLFW_KEY_A, GLFW_PRESS);
  tracker.onMouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS);
  tracker.onCursor(0.0, 0.0);
  tracker.onCursor(30.0, 40.0);
  controller.update(tracker.takeFrame(1.0).camera, 1.0f);
  tracker.onKey(GLFW_KEY_A, GLFW_RELEASE);
  tracker.onKey(GLFW_KEY_R, GLFW_PRESS);
  EXPECT_TRUE(controller.update(tracker.takeFrame(0.1).camera, 1.0f));
  expectNear(controller.camera().position, homeCamera().position);
  expectNear(controller.camera().forward, homeCamera().forward);
  // One-shot keys fire once per press, not every frame while held.
  EXPECT_FALSE(tracker.takeFrame(0.1).camera.reset);
}

TEST(ViewerInput, LosingFocusReleasesHeldKeys) {
  InputTracker tracker;
  tracker.onKey(GLFW_KEY_W, GLFW_PRESS);
  tracker.releaseAll();
  EXPECT_EQ(tracker.takeFrame(0.1).camera.move, glm::vec3(0.0f));
}

TEST(ViewerInput, ScreenshotKeys) {
  InputTracker tracker;
  tracker.onKey(GLFW_KEY_P, GLFW_PRESS);
  EXPECT_TRUE(tracker.takeFrame(0.1).screenshot);
  EXPECT_FALSE(tracker.takeFrame(0.1).screenshot);
  tracker.onKey(GLFW_KEY_F12, GLFW_PRESS);
  EXPECT_TRUE(tracker.takeFrame(0.1).screenshot);
}

TEST(ViewerInput, SpaceTogglesPlaybackOncePerPress) {
  InputTracker tracker;
  tracker.onKey(GLFW_KEY_SPACE, GLFW_PRESS);
  tracker.onKey(GLFW_KEY_SPACE, GLFW_REPEAT);
  EXPECT_TRUE(tracker.takeFrame(0.1).togglePlayback);
  EXPECT_FALSE(tracker.takeFrame(0.1).togglePlayback);
  tracker.onKey(GLFW_KEY_SPACE, GLFW_RELEASE);
  EXPECT_FALSE(tracker.takeFrame(0.1).togglePlayback);
}

// An animated scene camera moves the home: an unmoved view follows it, a moved one stays
// where the user put it until reset, which goes to the new home.
TEST(ViewerInput, AnUnmovedViewFollowsTheAnimatedSceneCamera) {
  InputTracker tracker;
  CameraController controller(homeCamera(), 1.0f);
  Camera later = homeCamera();
  later.position = {0.0f, 1.0f, 5.0f};
  controller.setHome(later);
  expectNear(controller.camera().position, later.position);

  tracker.onKey(GLFW_KEY_D, GLFW_PRESS);
  controller.update(tracker.takeFrame(1.0).camera, 1.0f);
  tracker.onKey(GLFW_KEY_D, GLFW_RELEASE);
  expectNear(controller.camera().position, {1.0f, 1.0f, 5.0f});
  later.position = {0.0f, 2.0f, 5.0f};
  controller.setHome(later);
  expectNear(controller.camera().position, {1.0f, 1.0f, 5.0f});

  tracker.onKey(GLFW_KEY_R, GLFW_PRESS);
  controller.update(tracker.takeFrame(0.1).camera, 1.0f);
  expectNear(controller.camera().position, later.position);
  later.position = {0.0f, 3.0f, 5.0f};
  controller.setHome(later);
  expectNear(controller.camera().position, later.position);
}

}  // namespace
}  // namespace wp
