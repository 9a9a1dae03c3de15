// `wavepath view`: the flags of the windowed viewer (the frame loop is in viewer/viewer.cpp).
#include <CLI/CLI.hpp>

#include "app/commands.h"

namespace wp {

CLI::App* addViewCommand(CLI::App& app, ViewOptions& v) {
  CLI::App* cmd = app.add_subcommand(
      "view", "Show a glTF scene in a window, refining sample by sample; move the camera and change settings");
  // Passes are sized to the frame budget (WavefrontRenderer::renderFor); this only caps them,
  // and the memory they hold (~50 MB), lower than render's default: a frame traces a few
  // tens of thousands of paths on a CPU device. --max-paths raises it for a fast GPU.
  v.render.settings.maxPaths = 1u << 18;
  v.render.settings.width = 640;
  v.render.settings.height = 360;
  addSceneFlags(*cmd, v.render);
  cmd->add_option("--frames", v.frames, "Scripted run: show this many frames (and reach --spp if given), then exit")
      ->check(CLI::Range(1u, 1u << 24));
  cmd->add_option("--screenshot", v.screenshot,
                  "Scripted run: at exit write the image (.png: as displayed; .exr: radiance with variance)");
  cmd->add_option("--window-capture", v.windowCapture, "Scripted run: at exit write the whole window, panel included (.png)");
  cmd->add_option("--frame-budget", v.frameBudgetMs,
                  "Time per displayed frame in ms; path tracing gets what readback and display leave (at least a "
                  "quarter, and one pass)")
      ->check(CLI::Range(1.0f, 10000.0f));
  cmd->add_flag("--play", v.play,
                "Start playing the animation (from --time); a scripted run waits for its end, then reaches --spp");
  cmd->add_flag("--loop", v.loop, "Play the animation in a loop (the panel's loop box)");
  cmd->add_flag("--hide-panel", v.hidePanel, "Start with the settings panel hidden (F1 toggles it)");
  return cmd;
}

}  // namespace wp
