// Checkpoints and interruption around WavefrontRenderer::render.
#include "app/resumable_render.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/interrupt.h"
#include "app/progress_bar.h"
#include "core/error.h"
#include "core/log.h"

namespace wp {

namespace {

// Throws unless `saved` is a checkpoint of the render `here` describes.
void checkSameRender(const std::string& path, const Checkpoint& saved, const Checkpoint& here) {
  auto refuse = [&](const std::string& what) {
    throw Error("checkpoint '" + path + "' is of another render (" + what +
                "); resume with the flags and scene it was made with, or start afresh without --resume");
  };
  std::string difference = identityDifference(saved.identity, here.identity);
  if (!difference.empty()) refuse(difference);
  if (saved.samplesPerPixel != here.samplesPerPixel)
    refuse("--spp is " + std::to_string(saved.samplesPerPixel) + " there, " + std::to_string(here.samplesPerPixel) +
           " here");
  if (saved.firstSample != here.firstSample || saved.endSample != here.endSample)
    refuse("--samples is " + std::to_string(saved.firstSample) + ".." + std::to_string(saved.endSample - 1) +
           " there, " + std::to_string(here.firstSample) + ".." + std::to_string(here.endSample - 1) + " here");
  if (!(saved.region == here.region))
    refuse("--region differs (" + std::to_string(saved.region.x0) + "," + std::to_string(saved.region.y0) + "," +
           std::to_string(saved.region.x1) + "," + std::to_string(saved.region.y1) + " there)");
}

std::string sppText(uint64_t paths, uint64_t pixels) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", double(paths) / double(pixels));
  return text;
}

}  // namespace

void checkCheckpointFlags(const CheckpointOptions& o, const std::string& output) {
  if (o.path.empty()) return;
  std::error_code ec;
  if (std::filesystem::weakly_canonical(o.path, ec) == std::filesystem::weakly_canonical(output, ec))
    throw FlagError("--checkpoint '" + o.path + "' is the output image too; give the checkpoint a name of its own");
  const bool exists = std::filesystem::exists(o.path, ec);
  if (o.resume && !exists)
    throw FlagError("--resume: checkpoint '" + o.path + "' does not exist; leave out --resume to start afresh");
  if (!o.resume && exists)
    throw FlagError("--checkpoint '" + o.path + "' exists; add --resume to go on from it, or remove it to start afresh");
}

RenderOutcome renderResumably(WavefrontRenderer& renderer, const Checkpoint& here, const CheckpointOptions& o,
                              double timeLimitSeconds) {
  const uint64_t pixels = here.region.pixels();
  const uint64_t firstPath = pixels * here.firstSample;
  if (o.resume) {
    Checkpoint saved = readCheckpoint(o.path);
    checkSameRender(o.path, saved, here);
    if (saved.device != here.device)
      note("checkpoint '" + o.path + "' was rendered on " + saved.device + ": the image will not be bit-identical "
           "to an uninterrupted render on either device, though just as valid");
    renderer.resume(saved.accumulation, saved.pathsDone);
    note("resuming from checkpoint '" + o.path + "' at " + sppText(saved.pathsDone - firstPath, pixels) + " of " +
         std::to_string(here.endSample - here.firstSample) + " spp");
  }
  auto save = [&] {
    Checkpoint c = here;
    c.pathsDone = renderer.pathsDone();
    c.accumulation = renderer.accumulation();
    writeCheckpoint(o.path, c);
  };
  const uint64_t startPaths = renderer.pathsDone();
  ProgressBar bar;
  RenderOutcome outcome;
  double lastSave = 0.0;
  outcome.stats = renderer.render([&](const RenderStats& stats) {
    bar.update({pixels, renderer.pathsDone() - firstPath, renderer.pathsEnd() - firstPath,
                renderer.pathsDone() - startPaths, stats.seconds, timeLimitSeconds});
    if (interruptSignal() != 0) return false;
    if (!o.path.empty() && stats.seconds - lastSave >= o.everySeconds && renderer.pathsDone() < renderer.pathsEnd()) {
      save();
      lastSave = stats.seconds;
    }
    return true;
  }, timeLimitSeconds);
  bar.finish();
  outcome.interruptedBy = renderer.pathsDone() < renderer.pathsEnd() ? interruptSignal() : 0;
  if (outcome.interruptedBy != 0 && !o.path.empty()) {
    save();
    std::fprintf(stderr,
                 "wavepath: %s: stopped at %s of %u spp; checkpoint '%s' written; run the same command with --resume "
                 "to go on\n",
                 signalName(outcome.interruptedBy), sppText(renderer.pathsDone() - firstPath, pixels).c_str(),
                 here.endSample - here.firstSample, o.path.c_str());
  }
  return outcome;
}

}  // namespace wp
