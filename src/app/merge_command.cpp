// `wavepath merge`: combines the EXR parts of a frame split by --samples and --region into
// the frame, as an EXR (with its variance and record) or a PNG (as the parts' render would
// have made it).
#include <cstdio>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/error.h"
#include "image/image_io.h"
#include "render/part_merge.h"

namespace wp {

CLI::App* addMergeCommand(CLI::App& app, MergeOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "merge", "Combine EXR parts of one frame (rendered with --samples and/or --region) into the frame");
  cmd->add_option("parts", o.parts, "EXR files written by 'wavepath render' with --samples or --region")
      ->required();
  cmd->add_option("-o,--output", o.output, "The merged frame: .exr (linear, with variance) or .png")->required();
  return cmd;
}

int runMerge(const MergeOptions& o) {
  checkOutputPath(o.output);
  std::vector<FramePart> parts;
  for (const std::string& name : o.parts) parts.push_back({name, readExr(name)});
  RadianceImage frame = mergeParts(parts);
  DisplaySettings display = frame.record->display;
  if (frame.record->autoExposure) display.exposure = autoExposure(frame);
  writeImage(o.output, frame, display);
  const RenderRecord& r = *frame.record;
  std::printf("%s: %ux%u, %u spp merged from %zu parts\n", o.output.c_str(), r.frameWidth, r.frameHeight,
              r.samplesPerPixel, parts.size());
  return 0;
}

}  // namespace wp
