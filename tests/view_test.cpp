// `wavepath view` end to end, run by ctest under Xvfb (xvfb-run) on lavapipe with the
// validation layer: a scripted run's screenshot against `wavepath render`, the window
// capture, the OpenCL backend in the window, animation playback, and the error without a
// window system.
#include <gtest/gtest.h>

#include <stb_image.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

std::filesystem::path cornellBox() { return sourceDirectory() / "assets" / "cornell-box.gltf"; }

// A scene, its size, samples and seed, as both commands take them.
std::vector<std::string> sceneFlags(const std::string& backend) {
  return {cornellBox().string(), "--width", "96", "--height", "96", "--spp", "6", "--seed", "7", "--backend", backend};
}

RunResult view(const std::string& backend, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"view"};
  for (const std::string& a : sceneFlags(backend)) args.push_back(a);
  args.insert(args.end(), extra.begin(), extra.end());
  RunResult r = runWavepath(args, {}, 300);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  return r;
}

void render(const std::string& backend, const std::filesystem::path& out) {
  std::vector<std::string> args = {"render"};
  for (const std::string& a : sceneFlags(backend)) args.push_back(a);
  args.insert(args.end(), {"-o", out.string()});
  RunResult r = runWavepath(args, {}, 300);
  ASSERT_EQ(r.exitCode, 0) << r.err;
}

struct Rgb8 {
  int width = 0, height = 0;
  std::vector<unsigned char> bytes;
};

// Pixels whose mean radiance or variance differ at all.
size_t differingPixels(const RadianceImage& a, const RadianceImage& b) {
  EXPECT_EQ(a.mean.size(), b.mean.size());
  size_t differing = 0;
  for (size_t i = 0; i < std::min(a.mean.size(), b.mean.size()); ++i) {
    differing += a.mean[i] != b.mean[i] || a.variance[i] != b.variance[i];
  }
  return differing;
}

Rgb8 readPng(const std::filesystem::path& path) {
  Rgb8 image;
  int channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  EXPECT_NE(pixels, nullptr) << path;
  if (pixels != nullptr) {
    image.bytes.assign(pixels, pixels + size_t(image.width) * image.height * 3);
    stbi_image_free(pixels);
  }
  return image;
}

// The viewer stops at --spp and traces the same paths (seeded by pixel, sample and seed) as
// render, only split into smaller passes; docs/testing.md promises bit-identical images across
// pass splits, so the radiance and its variance must match exactly, not just statistically.
void expectSameRadiance(const std::string& backend) {
  std::filesystem::path dir = scratchDirectory("view-" + backend);
  RunResult r = view(backend, {"--frames", "2", "--frame-budget", "5", "--screenshot", (dir / "view.exr").string()});
  render(backend, dir / "render.exr");
  RadianceImage a = readExr(dir / "view.exr"), b = readExr(dir / "render.exr");
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_EQ(differingPixels(a, b), 0u) << "of " << a.mean.size() << " pixels";
  // The scripted run reports its frames and speed at exit.
  EXPECT_NE(r.out.find("view: "), std::string::npos) << r.out;
}

TEST(View, ScriptedRunMatchesRenderOnVulkan) { expectSameRadiance("vulkan"); }

TEST(View, ScriptedRunMatchesRenderOnOpenCl) { expectSameRadiance("opencl"); }

TEST(View, DisplayScreenshotEqualsRendersPng) {
  std::filesystem::path dir = scratchDirectory("view-png");
  view("vulkan", {"--frames", "1", "--screenshot", (dir / "view.png").string(), "--tonemap", "aces"});
  std::vector<std::string> args = {"render"};
  for (const std::string& a : sceneFlags("vulkan")) args.push_back(a);
  args.insert(args.end(), {"-o", (dir / "render.png").string(), "--tonemap", "aces"});
  ASSERT_EQ(runWavepath(args).exitCode, 0);
  Rgb8 a = readPng(dir / "view.png"), b = readPng(dir / "render.png");
  EXPECT_EQ(a.width, 96);
  EXPECT_EQ(a.height, 96);
  EXPECT_TRUE(a.bytes == b.bytes);  // same radiance (above) through the same packDisplay
}

// What the window shows: without the panel exactly the display image (the copy into the
// swapchain keeps every byte, BGRA or RGBA), with it the panel covers part of it.
TEST(View, WindowCaptureShowsTheImageAndThePanel) {
  std::filesystem::path dir = scratchDirectory("view-capture");
  view("vulkan", {"--frames", "2", "--screenshot", (dir / "image.png").string(), "--window-capture",
                  (dir / "bare.png").string(), "--hide-panel"});
  Rgb8 image = readPng(dir / "image.png"), bare = readPng(dir / "bare.png");
  EXPECT_EQ(bare.width, 96);
  EXPECT_EQ(bare.height, 96);
  EXPECT_TRUE(bare.bytes == image.bytes);

  view("vulkan", {"--frames", "2", "--window-capture", (dir / "panel.png").string()});
  Rgb8 panel = readPng(dir / "panel.png");
  ASSERT_EQ(panel.bytes.size(), image.bytes.size());
  size_t differing = 0;
  for (size_t i = 0; i < panel.bytes.size(); i += 3) {
    differing += std::memcmp(&panel.bytes[i], &image.bytes[i], 3) != 0;
  }
  // The panel's title bar alone spans the window's width (96 px) and ~19 px height.
  EXPECT_GT(differing, 96u * 10u);
}

// Runs `wavepath view` with `flags` in the background and, once its window is mapped, acts
// on it as a user would (x_window_input `action`), then waits for the scripted run to end.
// Returns the viewer's stderr; fails the test on a non-zero exit.
std::string viewWithWindowInput(const std::vector<std::string>& flags, const std::string& action,
                                const std::filesystem::path& dir) {
  std::string command = std::string("WAVEPATH_VALIDATION=1 ") + WAVEPATH_EXE + " view";
  for (const std::string& f : flags) command += " '" + f + "'";
  command += " 2>'" + (dir / "err.txt").string() + "' & pid=$!; for i in $(seq 40); do sleep 0.25; " X_WINDOW_INPUT
             " " + action + " && break; done; wait $pid";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;  // the viewer's exit code (wait's)
  std::ifstream err(dir / "err.txt");
  return std::string((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
}

// The window is resized from outside (as a user dragging its border) while a scripted run
// goes on: the image follows the window, and the capture has the window's new size.
TEST(View, ImageFollowsAResizedWindow) {
  std::filesystem::path dir = scratchDirectory("view-resize");
  std::filesystem::path image = dir / "image.png", window = dir / "window.png";
  std::string err = viewWithWindowInput({cornellBox().string(), "--width", "96", "--height", "96", "--frames", "300",
                                         "--frame-budget", "5", "--screenshot", image.string(), "--window-capture",
                                         window.string()},
                                        "resize 'wavepath view' 160 120", dir);
  Rgb8 a = readPng(image), b = readPng(window);
  EXPECT_EQ(a.width, 160);
  EXPECT_EQ(a.height, 120);
  EXPECT_EQ(b.width, 160);
  EXPECT_EQ(b.height, 120);
  EXPECT_EQ(err.find("validation"), std::string::npos) << err;
}

// W held in the real window moves the camera: the final image (the target spp of the moved
// view, since the move restarts the accumulation) is no longer the scene camera's render.
// Unmoved, the two are equal bit for bit (ScriptedRunMatchesRender*), so any differing
// pixel is the move; a forward move of a few tenths of the box changes most of them. The run
// lasts 1000 frames: once the image has its samples a frame costs next to nothing, and on a
// loaded machine the window can take seconds to be found and the key to arrive, which 100
// and 300 frames were sometimes over before.
TEST(View, HeldKeyInTheWindowMovesTheCamera) {
  std::filesystem::path dir = scratchDirectory("view-key");
  std::vector<std::string> flags = sceneFlags("vulkan");
  flags.insert(flags.end(), {"--frames", "1000", "--frame-budget", "20", "--screenshot", (dir / "view.exr").string()});
  std::string err = viewWithWindowInput(flags, "key 'wavepath view' w 600", dir);
  EXPECT_EQ(err.find("validation"), std::string::npos) << err;
  render("vulkan", dir / "render.exr");
  RadianceImage moved = readExr(dir / "view.exr"), home = readExr(dir / "render.exr");
  EXPECT_GT(differingPixels(moved, home), moved.mean.size() / 2);
}

// tests/data/anim_trs.gltf (2 s: a moving, a turning and a growing object and a camera that
// steps up at 1 s) through `command` at 48x48, 4 spp, with `flags`, the image to `out`.
RunResult runAnimated(const std::string& command, std::vector<std::string> flags, const std::filesystem::path& out) {
  std::vector<std::string> args = {command, (sourceDirectory() / "tests" / "data" / "anim_trs.gltf").string(),
                                   "--width", "48", "--height", "48", "--spp", "4", "--seed", "5"};
  flags.insert(flags.end(), {command == "view" ? "--screenshot" : "-o", out.string()});
  args.insert(args.end(), flags.begin(), flags.end());
  RunResult r = runWavepath(args, {}, 300);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  return r;
}

// The viewer opens an animated scene on the --time pose over the shutter interval (moving
// objects blurred), packed as render packs it: the same image bit for bit.
TEST(View, AnimatedSceneAtATimeMatchesRender) {
  std::filesystem::path dir = scratchDirectory("view-anim-time");
  const std::vector<std::string> at = {"--time", "0.5", "--shutter", "0.25"};
  std::vector<std::string> viewFlags = at;
  viewFlags.insert(viewFlags.end(), {"--frames", "2", "--frame-budget", "5"});
  runAnimated("view", viewFlags, dir / "view.exr");
  runAnimated("render", at, dir / "render.exr");
  EXPECT_EQ(differingPixels(readExr(dir / "view.exr"), readExr(dir / "render.exr")), 0u);
}

// --play from 0.5 s: each frame re-poses the scene at the wall-clock time over the shutter
// and updates it on the GPU; without --loop playback stops at the end (2 s), where the
// scripted run then reaches --spp. So the image is exactly render's at 2 s, posed and packed
// from scratch (the camera followed its step at 1 s; no motion is left to blur), and not the
// 0.5 s pose it opened on.
void expectPlaybackToEndOnTheLastPose(const std::string& backend) {
  std::filesystem::path dir = scratchDirectory("view-anim-play-" + backend);
  const std::vector<std::string> common = {"--shutter", "0.25", "--backend", backend};
  auto flags = [&](std::vector<std::string> f) {
    f.insert(f.end(), common.begin(), common.end());
    return f;
  };
  runAnimated("view", flags({"--time", "0.5", "--play", "--frames", "2", "--frame-budget", "5"}), dir / "played.exr");
  runAnimated("render", flags({"--time", "2"}), dir / "end.exr");
  runAnimated("render", flags({"--time", "0.5"}), dir / "start.exr");
  RadianceImage played = readExr(dir / "played.exr");
  EXPECT_EQ(differingPixels(played, readExr(dir / "end.exr")), 0u);
  EXPECT_GT(differingPixels(played, readExr(dir / "start.exr")), 0u);
}

// With --loop playback has no end: the scripted run ends after its frames.
TEST(View, PlaybackRunsToTheEndOfTheAnimationOnVulkan) {
  expectPlaybackToEndOnTheLastPose("vulkan");
  RunResult looped = runAnimated("view", {"--play", "--loop", "--frames", "5"}, scratchDirectory("view-loop") / "x.exr");
  EXPECT_NE(looped.out.find("view: 5 frames"), std::string::npos) << looped.out;
}

TEST(View, PlaybackRunsToTheEndOfTheAnimationOnOpenCl) { expectPlaybackToEndOnTheLastPose("opencl"); }

TEST(View, WithoutAWindowSystemPointsToRender) {
  std::vector<std::string> args = {"view", cornellBox().string(), "--frames", "1"};
  RunResult r = runWavepath(args, {"DISPLAY="}, 60);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(r.err.rfind("wavepath: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("wavepath render"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(View, ScreenshotNeedsAScriptedRunAndTheCaptureAPng) {
  RunResult r = runWavepath({"view", cornellBox().string(), "--screenshot", "x.png"}, {}, 60);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
  std::filesystem::path capture = scratchDirectory("view-bad-capture") / "window.exr";
  r = runWavepath({"view", cornellBox().string(), "--frames", "1", "--window-capture", capture.string()}, {}, 60);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("must end in .png"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(capture));
}

}  // namespace
}  // namespace wp::test
