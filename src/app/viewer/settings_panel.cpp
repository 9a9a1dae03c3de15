// The settings panel: statistics, integrator switches, exposure, tone curve, depth of field, animation.
#include "app/viewer/settings_panel.h"

#include <algorithm>
#include <limits>

#include <imgui.h>

namespace wp {
namespace {

void drawAnimationControls(AnimationClock& clock, bool restPose) {
  ImGui::Separator();
  if (ImGui::Button(clock.playing() ? "pause" : "play")) {
    clock.toggle();
  }
  ImGui::SameLine();
  bool loop = clock.loop();
  if (ImGui::Checkbox("loop", &loop)) {
    clock.setLoop(loop);
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  float speed = float(clock.speed());
  // Clamped even when typed in (Ctrl+click): the clock needs a speed above 0.
  if (ImGui::SliderFloat("speed", &speed, 0.1f, 4.0f, "%.2fx",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
    clock.setSpeed(speed);
  }
  float time = float(clock.time());
  if (ImGui::SliderFloat("time", &time, 0.0f, float(clock.duration()), restPose ? "rest pose" : "%.3f s")) {
    clock.scrub(time);
  }
}

}  // namespace

bool drawSettingsPanel(const PanelInfo& info, PanelControls& c) {
  bool restart = false;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("wavepath", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("%s: %s", info.backend.c_str(), info.computeDevice.c_str());
  ImGui::Text("display: %s", info.displayDevice.c_str());
  ImGui::Text("%ux%u, camera: %s", info.width, info.height, info.cameraMode);
  if (info.sampleTarget > 0) {
    ImGui::Text("samples: %u / %u", info.samples, info.sampleTarget);
  } else {
    ImGui::Text("samples: %u", info.samples);
  }
  ImGui::Text("%.3f M samples/s, %.2f Mrays/s", info.samplesPerSecond * 1e-6, info.raysPerSecond * 1e-6);
  ImGui::Text("frame %.1f ms, %u passes", info.frameMs, info.passesPerFrame);
  if (ImGui::TreeNodeEx("GPU ms per stage (last frame)", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (int k = 0; k < kKernelCount; ++k) {
      ImGui::Text("%-10s %7.2f", kernelName(Kernel(k)), info.stageMs[k]);
    }
    ImGui::TreePop();
  }

  ImGui::Separator();
  RenderSettings& s = *c.settings;
  int depth = int(s.maxBounces);
  if (ImGui::SliderInt("max depth", &depth, 0, 32)) {
    s.maxBounces = uint32_t(depth);
    restart = true;
  }
  static const char* const modes[] = {"MIS", "NEE only", "BSDF only"};
  int mode = int(s.mode);
  if (ImGui::Combo("integrator", &mode, modes, 3)) {
    s.mode = IntegratorMode(mode);
    restart = true;
  }
  int rrStart = int(c.russianRouletteStart);
  bool rrChanged = ImGui::Checkbox("Russian roulette", &c.russianRoulette);
  if (c.russianRoulette) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80);
    rrChanged |= ImGui::SliderInt("from bounce", &rrStart, 0, 16);
  }
  if (rrChanged) {
    c.russianRouletteStart = uint32_t(rrStart);
    // Off: a start no bounce reaches, so every path runs to max depth.
    s.russianRouletteStart = c.russianRoulette ? c.russianRouletteStart : std::numeric_limits<uint32_t>::max();
    restart = true;
  }
  // Biased (--filter-glossy; Blender's default is 1): fewer fireflies from glossy highlights.
  restart |= ImGui::SliderFloat("filter glossy", &s.filterGlossy, 0.0f, 10.0f, s.filterGlossy > 0.0f ? "%.2f" : "off",
                                ImGuiSliderFlags_AlwaysClamp);

  ImGui::Separator();
  ImGui::SliderFloat("exposure (stops)", &c.exposureStops, -10.0f, 10.0f, "%+.1f");
  ImGui::Checkbox("auto exposure", &c.display->autoExposure);
  static const char* const curves[] = {"clamp", "reinhard", "filmic", "aces"};
  int curve = int(std::find(curves, curves + 4, c.display->toneMapper) - curves) % 4;
  if (ImGui::Combo("tone curve", &curve, curves, 4)) {
    c.display->toneMapper = curves[curve];
  }

  ImGui::Separator();
  CameraOptics& o = *c.optics;
  // f-number 0 is a pinhole (no depth of field).
  restart |= ImGui::SliderFloat("f-number", &o.fNumber, 0.0f, 32.0f, o.fNumber > 0.0f ? "f/%.1f" : "pinhole");
  if (o.fNumber > 0.0f) {
    restart |= ImGui::SliderFloat("focus distance", &o.focusDistance, 0.05f, 100.0f, "%.2f",
                                  ImGuiSliderFlags_Logarithmic);
  }
  if (c.clock) {
    drawAnimationControls(*c.clock, info.restPose);
  }
  ImGui::TextDisabled(c.clock ? "WASD/QE move, drag look, Tab orbit, R reset, P save, Space play"
                              : "WASD/QE move, drag look, Tab orbit, R reset, P save");
  ImGui::End();
  return restart;
}

}  // namespace wp
