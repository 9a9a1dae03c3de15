// The viewer's Dear ImGui panel: what the renderer is doing, and the settings a user may change.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "app/camera_options.h"
#include "app/viewer/animation_clock.h"
#include "render/backend.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace wp {

// Read-only figures the panel shows.
struct PanelInfo {
  std::string backend;
  std::string computeDevice;
  std::string displayDevice;
  uint32_t width = 0, height = 0;
  uint32_t samples = 0;        // samples per pixel so far
  uint32_t sampleTarget = 0;   // 0: no limit
  double samplesPerSecond = 0.0;
  double raysPerSecond = 0.0;  // extension plus shadow rays
  double frameMs = 0.0;
  uint32_t passesPerFrame = 0;
  std::array<double, kKernelCount> stageMs{};  // GPU ms per stage in the last frame
  const char* cameraMode = "fly";
  bool restPose = false;  // an animated scene still in its rest pose (no time chosen yet)
};

// What the panel edits. Exposure stops and the tone curve change only the display; the
// animation clock is the caller's to follow; the rest restarts the accumulation.
struct PanelControls {
  RenderSettings* settings = nullptr;
  CameraOptics* optics = nullptr;
  CameraFlags* display = nullptr;  // toneMapper and autoExposure
  float exposureStops = 0.0f;      // on top of the flags' exposure: x 2^stops
  bool russianRoulette = true;     // off: settings->russianRouletteStart past every bounce
  uint32_t russianRouletteStart = 3;
  AnimationClock* clock = nullptr;  // null: the scene has no animation (no controls shown)
};

// Draws the panel into the current ImGui frame. Returns true when a setting that changes the
// rendered image changed (the caller restarts the accumulation).
bool drawSettingsPanel(const PanelInfo& info, PanelControls& controls);

}  // namespace wp
