// A frame split into parts: --samples and --region read into the settings, and the record
// of what a part holds.
#include "app/frame_parts.h"

#include <charconv>

#include "app/frame_sequence.h"
#include "core/error.h"

namespace wp {

std::string partText(const RenderSettings& s) {
  std::string text;
  if (s.firstSample != 0 || s.sampleEnd() != s.samplesPerPixel)
    text += "samples " + std::to_string(s.firstSample) + ".." + std::to_string(s.sampleEnd() - 1) + " of ";
  const PixelRegion r = s.pixelRegion();
  if (!(r == PixelRegion{0, 0, s.width, s.height}))
    text += "region " + std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," +
            std::to_string(r.y1) + " of ";
  return text;
}

RenderRecord renderRecord(const RenderSettings& s, const RenderIdentity& identity, const DisplaySettings& display,
                          bool autoExposure) {
  RenderRecord r;
  r.frameWidth = s.width;
  r.frameHeight = s.height;
  r.samplesPerPixel = s.samplesPerPixel;
  r.firstSample = s.firstSample;
  r.lastSample = s.sampleEnd() - 1;
  const PixelRegion region = s.pixelRegion();
  r.x0 = region.x0;
  r.y0 = region.y0;
  r.x1 = region.x1;
  r.y1 = region.y1;
  r.seed = s.seed;
  r.sceneHash = identity.sceneHash;
  r.settings = identity.settings;
  r.display = display;
  r.autoExposure = autoExposure;
  return r;
}

PixelRegion parseRegion(const std::string& text) {
  PixelRegion r;
  uint32_t* fields[] = {&r.x0, &r.y0, &r.x1, &r.y1};
  size_t at = 0;
  for (int i = 0; i < 4; ++i) {
    const size_t comma = i < 3 ? text.find(',', at) : text.size();
    const std::string field = comma == std::string::npos ? "" : text.substr(at, comma - at);
    const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), *fields[i]);
    if (field.empty() || ec != std::errc() || ptr != field.data() + field.size())
      throw Error("'" + text + "' is not four whole numbers X0,Y0,X1,Y1; give a crop such as --region 0,0,256,128");
    at = comma + 1;
  }
  return r;
}

void applyPartFlags(RenderSettings& s, const std::string& samples, const std::string& region) {
  if (!samples.empty()) {
    const FrameRange range = parseFrameRange(samples, "--samples 0..15");
    if (range.last >= s.samplesPerPixel)
      throw FlagError("--samples " + samples + " goes past the " + std::to_string(s.samplesPerPixel) +
                      " samples of --spp (numbered 0 to " + std::to_string(s.samplesPerPixel - 1) + ")");
    s.firstSample = range.first;
    s.endSample = range.last + 1;
  }
  if (!region.empty()) {
    const PixelRegion r = parseRegion(region);
    if (r.x0 >= r.x1 || r.y0 >= r.y1 || r.x1 > s.width || r.y1 > s.height)
      throw FlagError("--region " + region + " is not a crop of the " + std::to_string(s.width) + "x" +
                      std::to_string(s.height) + " image; give X0 < X1 <= width and Y0 < Y1 <= height (X1, Y1 "
                      "exclusive)");
    s.region = r;
  }
}

}  // namespace wp
