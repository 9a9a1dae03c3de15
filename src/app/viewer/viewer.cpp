// `wavepath view`'s frame loop: input, settings panel, animation playback, progressive path
// tracing within a time budget per frame, and display through the presenter.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include "app/backend_factory.h"
#include "app/commands.h"
#include "app/viewer/animation_clock.h"
#include "app/viewer/camera_controller.h"
#include "app/viewer/input_tracker.h"
#include "app/viewer/presenter.h"
#include "app/viewer/settings_panel.h"
#include "app/viewer/window.h"
#include "core/error.h"
#include "core/log.h"
#include "image/image_io.h"
#include "render/camera_lens.h"
#include "render/wavefront.h"
#include "scene/scene_animation.h"

namespace wp {
namespace {

using Clock = std::chrono::steady_clock;

InputTracker& trackerOf(GLFWwindow* window) { return *static_cast<InputTracker*>(glfwGetWindowUserPointer(window)); }

// Events go to the camera unless ImGui uses them (a slider being dragged, the cursor over the
// panel); releases always do, so no key stays held.
void onKey(GLFWwindow* w, int key, int, int action, int) {
  if (action == GLFW_RELEASE || !ImGui::GetIO().WantCaptureKeyboard) trackerOf(w).onKey(key, action);
}
void onMouseButton(GLFWwindow* w, int button, int action, int) {
  if (action == GLFW_RELEASE || !ImGui::GetIO().WantCaptureMouse) trackerOf(w).onMouseButton(button, action);
}
void onCursor(GLFWwindow* w, double x, double y) { trackerOf(w).onCursor(x, y); }
void onScroll(GLFWwindow* w, double, double dy) {
  if (!ImGui::GetIO().WantCaptureMouse) trackerOf(w).onScroll(dy);
}
void onFocus(GLFWwindow* w, int focused) {
  if (!focused) trackerOf(w).releaseAll();
}

// Dear ImGui's context and GLFW backend, installed after our callbacks (it chains to them).
struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's directory
    ImGui_ImplGlfw_InitForVulkan(window, true);
  }
  ~ImGuiSession() {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

class ViewerLoop {
public:
  ViewerLoop(ViewOptions& v, PreparedScene& p, Window& window, Backend& backend, Presenter& presenter)
      : v_(v), loaded_(p.loaded), scene_(p.scene), uploader_(p.uploader), gpuScene_(p.uploader.gpuScene()),
        window_(window), backend_(backend), presenter_(presenter),
        settings_(v.render.settings), optics_(p.scene.camera.optics),
        controller_(p.scene.camera, 0.5f * autofocusDistance(p.scene.camera, gpuScene_)),
        renderer_(backend, p.scene, gpuScene_, sizedSettings()) {
    controls_.settings = &settings_;
    controls_.optics = &optics_;
    controls_.display = &v_.render.camera;
    controls_.russianRouletteStart = settings_.russianRouletteStart;
    showPanel_ = !v.hidePanel;
    if (loaded_.animation && loaded_.animation->duration > 0.0) {
      clock_.emplace(loaded_.animation->duration, v.render.time.value_or(0.0));
      clock_->setLoop(v.loop);
      if (v.play) clock_->play();
      posedTime_ = clock_->time();
      restPose_ = !v.render.time;
      shutter_ = shutterSeconds(v.render, loaded_);
      controls_.clock = &*clock_;
    } else if (v.play) {
      note(v.render.scene + " has no animation: --play has nothing to play");
    }
  }

  int run() {
    window_.show();
    auto last = Clock::now();
    while (!glfwWindowShouldClose(window_.handle)) {
      glfwPollEvents();
      auto now = Clock::now();
      double seconds = std::chrono::duration<double>(now - last).count();
      last = now;
      if (frames_ > 0) {
        frameMs_.push_back(seconds * 1e3);
        // What the frame spent besides path tracing (readback, tone curve, panel, present),
        // smoothed over a few frames since readbacks come only every few; converged frames
        // (no pass, then a wait for events) say nothing about it.
        if (last_.passes > 0) {
          overheadSeconds_ += 0.2 * (std::max(seconds - last_.seconds, 0.0) - overheadSeconds_);
        }
      }
      if (frame(seconds)) break;
    }
    report();
    return 0;
  }

private:
  // Settings with the image size of the window's framebuffer.
  RenderSettings sizedSettings() {
    window_.framebufferSize(settings_.width, settings_.height);
    settings_.width = std::max(settings_.width, 1u);
    settings_.height = std::max(settings_.height, 1u);
    return settings_;
  }

  uint32_t sampleTarget() const {
    return v_.sampleLimit ? settings_.samplesPerPixel : std::numeric_limits<uint32_t>::max();
  }

  // The one place a change reaches the renderer: camera, settings, image size, and with
  // `reloadScene` a new pose of the scene (in scene_ and gpuScene_).
  void restart(bool reloadScene) {
    Camera camera = controller_.camera();
    camera.optics = optics_;
    scene_.camera = camera;
    scene_.camera.aspectRatio = 0.0f;  // the window decides the aspect ratio
    renderer_.restart(scene_, gpuScene_, sizedSettings(), reloadScene);
  }

  // Keeps the optics the panel set only when the lens they make is valid (focus beyond the
  // focal length), focusing on what the image centre sees when the focus is unset.
  void checkOptics() {
    Camera camera = controller_.camera();
    camera.optics = optics_;
    try {
      applyCameraFlags(CameraFlags{}, camera, gpuScene_);
      optics_ = camera.optics;
      lastGoodOptics_ = optics_;
    } catch (const Error&) {
      optics_ = lastGoodOptics_;
    }
  }

  // One displayed frame; returns true when a scripted run is done.
  bool frame(double seconds) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    FrameInput input = takeInput(seconds);
    bool changed = applyInput(input);
    trace();
    bool done = scriptDone();
    // While the animation plays, each pose is shown (and saved) once every pixel has a
    // sample, never partly traced (a slow device skips times instead; see followClock).
    bool playing = clock_ && clock_->playing();
    bool hold = playing && renderer_.samplesPerPixelDone() == 0;
    refreshImage(changed || done || input.screenshot || playing || renderer_.samplesPerPixelDone() >= sampleTarget(),
                 hold);
    DisplaySettings display = updatePixels();
    ImGui::Render();
    auto presentStart = Clock::now();
    std::vector<uint32_t> capture;
    uint32_t captureW = 0, captureH = 0;
    bool capturing = done && !v_.windowCapture.empty();
    presenter_.present(pixels_, image_.width, image_.height, capturing ? &capture : nullptr, &captureW, &captureH);
    presentMs_.push_back(std::chrono::duration<double, std::milli>(Clock::now() - presentStart).count());
    if (input.screenshot) saveScreenshot(display);
    if (done) finish(display, capture, captureW, captureH);
    if (last_.passes == 0) {
      // Converged: sleep until the user does something. A scripted run sleeps a frame
      // budget, so that its frames stand for time as a user's would and input sent to the
      // window (tests/view_test.cpp) arrives within them, however fast the device.
      glfwWaitEventsTimeout(v_.frames == 0 ? 0.1 : v_.frameBudgetMs * 1e-3);
    }
    return done;
  }

  // Applies the panel, playback, the camera input and the window size; returns whether the
  // view changed (and the accumulation restarted).
  bool applyInput(const FrameInput& input) {
    bool changed = showPanel_ && drawSettingsPanel(panelInfo(), controls_);
    if (changed) checkOptics();
    if (clock_) {
      if (input.togglePlayback) clock_->toggle();
      clock_->advance(input.camera.seconds);
    }
    bool reposed = followClock();
    float pivot = input.camera.toggleOrbit ? autofocusDistance(scene_.camera, gpuScene_) : 0.0f;
    changed |= controller_.update(input.camera, pivot);
    uint32_t w = 0, h = 0;
    window_.framebufferSize(w, h);
    changed |= w > 0 && h > 0 && (w != settings_.width || h != settings_.height);
    changed |= reposed;
    if (changed) restart(reposed);
    return changed;
  }

  // Poses the scene at the clock's time when the clock moved since the last pose, over the
  // camera's shutter as `render --time` does (so motion blur shows), and updates its GPU form
  // the way an image sequence does. Returns whether it posed; the caller restarts. While
  // playing, the shown pose first gets a sample in every pixel (and is displayed): where that
  // takes longer than a frame, playback skips the times in between.
  bool followClock() {
    if (!clock_ || clock_->time() == posedTime_) return false;
    if (clock_->playing() && renderer_.samplesPerPixelDone() == 0) return false;
    posedTime_ = clock_->time();
    restPose_ = false;
    Scene posed = poseSceneOverShutter(loaded_, posedTime_, shutter_);
    uploader_.gpuSceneOf(posed);  // updates gpuScene_ in place
    controller_.setHome(posed.camera);
    scene_ = std::move(posed);
    return true;
  }

  // Path traces for this frame's share of the budget. The budget is the whole frame's: path
  // tracing gets what the rest leaves, but at least a quarter of it so the image still
  // refines when the rest alone exceeds the budget.
  void trace() {
    double budget = v_.frameBudgetMs * 1e-3;
    last_ = renderer_.renderFor(std::max(budget - overheadSeconds_, 0.25 * budget), sampleTarget());
    totals_.samples += last_.samples;
    totals_.extensionRays += last_.extensionRays;
    totals_.shadowRays += last_.shadowRays;
    totals_.seconds += last_.seconds;
    renderMs_.push_back(last_.seconds * 1e3);
    ++frames_;
  }

  // Remakes the shown pixels when the image or the display settings changed; returns the
  // display settings in use.
  DisplaySettings updatePixels() {
    DisplaySettings display = displaySettings(v_.render.camera, optics_, image_);
    display.exposure *= std::exp2(controls_.exposureStops);
    if (imageFresh_ || !sameDisplay(display, shownDisplay_)) {
      auto start = Clock::now();
      pixels_ = displayPixels(image_, display);
      toneMs_.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      shownDisplay_ = display;
      imageFresh_ = false;
    }
    return display;
  }

  // Reads the image back when passes ran since the last time and either `now` or enough
  // path tracing went by, unless `hold` keeps the last image. The readback costs a fixed
  // time per frame (at 1280x720 on lavapipe several times the frame budget), so while the
  // view stays still it happens once the path tracing since the last one took twice as long
  // as it did: it then costs at most a third of the time, and the window stays responsive.
  void refreshImage(bool now, bool hold) {
    tracedSinceRefresh_ += last_.seconds;
    unseenPasses_ |= last_.passes > 0;
    bool due = tracedSinceRefresh_ >= 2.0 * readbackSeconds_;
    if (!image_.mean.empty() && (hold || !(unseenPasses_ && (now || due)))) {
      return;
    }
    auto start = Clock::now();
    image_ = renderer_.image();
    readbackSeconds_ = std::chrono::duration<double>(Clock::now() - start).count();
    readbackMs_.push_back(readbackSeconds_ * 1e3);
    tracedSinceRefresh_ = 0.0;
    unseenPasses_ = false;
    imageFresh_ = true;
  }

  static bool sameDisplay(const DisplaySettings& a, const DisplaySettings& b) {
    return a.exposure == b.exposure && a.toneMapper == b.toneMapper && a.transfer == b.transfer && a.gamma == b.gamma;
  }

  FrameInput takeInput(double seconds) {
    FrameInput input = trackerOf(window_.handle).takeFrame(seconds);
    if (input.togglePanel) showPanel_ = !showPanel_;
    if (input.camera.reset) {
      optics_ = lastGoodOptics_ = homeOptics_;
    }
    return input;
  }

  // A scripted run ends after --frames frames, once the image has --spp samples. While the
  // animation plays it waits for the end (then goes on to --spp); a looping one has no end
  // and would restart the image every frame, so there the frames alone count.
  bool scriptDone() const {
    if (v_.frames == 0 || frames_ < v_.frames) return false;
    if (clock_ && clock_->playing()) return clock_->loop();
    return renderer_.samplesPerPixelDone() >= (v_.sampleLimit ? settings_.samplesPerPixel : 0u);
  }

  PanelInfo panelInfo() const {
    PanelInfo info;
    info.backend = v_.render.backend;
    info.computeDevice = backend_.deviceName();
    info.displayDevice = presenter_.deviceName();
    info.width = settings_.width;
    info.height = settings_.height;
    info.samples = renderer_.samplesPerPixelDone();
    info.sampleTarget = v_.sampleLimit ? settings_.samplesPerPixel : 0;
    if (last_.seconds > 0.0) {
      info.samplesPerSecond = double(last_.samples) / last_.seconds;
      info.raysPerSecond = double(last_.extensionRays + last_.shadowRays) / last_.seconds;
    }
    info.frameMs = frameMs_.empty() ? 0.0 : frameMs_.back();
    info.passesPerFrame = last_.passes;
    info.stageMs = last_.kernelMs;
    info.cameraMode = controller_.mode() == CameraMode::Fly ? "fly" : "orbit";
    info.restPose = restPose_;
    return info;
  }

  void saveScreenshot(const DisplaySettings& display) {
    std::string stem = std::filesystem::path(v_.render.scene).stem().string() + "-" + std::to_string(++shots_);
    writeImage(stem + ".png", image_, display);
    writeImage(stem + ".exr", image_);
    std::printf("saved %s.png (display) and %s.exr (radiance)\n", stem.c_str(), stem.c_str());
  }

  void finish(const DisplaySettings& display, const std::vector<uint32_t>& capture, uint32_t w, uint32_t h) {
    if (!v_.screenshot.empty()) writeImage(v_.screenshot, image_, display);
    if (!v_.windowCapture.empty()) writePng(v_.windowCapture, w, h, capture);
  }

  void report() const {
    double rays = double(totals_.extensionRays + totals_.shadowRays);
    double t = std::max(totals_.seconds, 1e-9);
    std::printf("view: %u frames at %ux%u, median frame %.1f ms (budget %.0f ms), %u spp, %.3f M samples/s, "
                "%.2f Mrays/s on %s, shown on %s\n",
                frames_, settings_.width, settings_.height, median(frameMs_), v_.frameBudgetMs,
                renderer_.samplesPerPixelDone(), double(totals_.samples) / t * 1e-6, rays / t * 1e-6,
                backend_.deviceName().c_str(), presenter_.deviceName().c_str());
    std::printf("view: median ms: path tracing %.1f and present %.1f per frame; readback %.1f in %zu frames, tone "
                "mapping %.1f in %zu\n",
                median(renderMs_), median(presentMs_), median(readbackMs_), readbackMs_.size(), median(toneMs_),
                toneMs_.size());
  }

  ViewOptions& v_;
  const Scene& loaded_;  // what every pose is made from
  Scene& scene_;         // the shown pose; its camera is the controller's
  PoseUploader& uploader_;
  const GpuScene& gpuScene_;  // the uploader's, updated in place per pose
  Window& window_;
  Backend& backend_;
  Presenter& presenter_;
  RenderSettings settings_;
  CameraOptics optics_;
  CameraOptics homeOptics_ = optics_;
  CameraOptics lastGoodOptics_ = optics_;
  CameraController controller_;
  WavefrontRenderer renderer_;
  PanelControls controls_;
  std::optional<AnimationClock> clock_;  // only for a scene with an animation to play
  double posedTime_ = 0.0;  // the clock's time when scene_ was last posed
  bool restPose_ = false;   // scene_ is the file's rest pose (no --time, not yet played)
  double shutter_ = 0.0;    // seconds the camera sees each pose over (motion blur)
  bool showPanel_ = true;
  RadianceImage image_;  // the last image read back
  bool imageFresh_ = false;  // read back since pixels_ were made
  bool unseenPasses_ = false;
  double tracedSinceRefresh_ = 0.0;
  double readbackSeconds_ = 0.0;
  std::vector<uint32_t> pixels_;  // image_ as shown
  DisplaySettings shownDisplay_;
  RenderStats last_;
  RenderStats totals_;
  std::vector<double> frameMs_;
  double overheadSeconds_ = 0.0;
  // Where the time goes, for the exit report: per frame, and per readback and tone mapping.
  std::vector<double> renderMs_, readbackMs_, toneMs_, presentMs_;
  uint32_t frames_ = 0;
  uint32_t shots_ = 0;
};

}  // namespace

int runView(ViewOptions v) {
  bool validate = validationRequested(v.render);
  if ((!v.screenshot.empty() || !v.windowCapture.empty()) && v.frames == 0) {
    throw Error("--screenshot and --window-capture save at the end of a scripted run; add --frames N");
  }
  if (!v.screenshot.empty()) checkOutputPath(v.screenshot);
  if (!v.windowCapture.empty()) {
    checkOutputPath(v.windowCapture);
    if (std::filesystem::path(v.windowCapture).extension() != ".png") {
      throw Error("--window-capture '" + v.windowCapture + "' must end in .png; the window is an 8-bit image");
    }
  }
  // The window system first: without one the user learns it before any scene or GPU work.
  requireWindowSystem();
  PreparedScene prepared = prepareScene(v.render);
  Window window(v.render.settings.width, v.render.settings.height,
                "wavepath view " + std::filesystem::path(v.render.scene).filename().string());
  v.render.backend = chooseBackendName(v.render.backend);
  BackendChoice choice{v.render.backend, v.render.device, validate, v.render.clDispatch};
  std::unique_ptr<Backend> backend = createBackend(choice);
  InputTracker tracker;
  glfwSetWindowUserPointer(window.handle, &tracker);
  glfwSetKeyCallback(window.handle, onKey);
  glfwSetMouseButtonCallback(window.handle, onMouseButton);
  glfwSetCursorPosCallback(window.handle, onCursor);
  glfwSetScrollCallback(window.handle, onScroll);
  glfwSetWindowFocusCallback(window.handle, onFocus);
  ImGuiSession imgui(window.handle);
  Presenter presenter(window.handle, validate);
  ViewerLoop loop(v, prepared, window, *backend, presenter);
  int code = loop.run();
  checkValidation(choice);
  return code;
}

}  // namespace wp
