// What a rendered image holds (frame size, samples, region, seed, scene), kept in its EXR
// header so that parts of one frame rendered apart can be checked and merged.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/display_settings.h"

namespace wp {

// The format of the record; a reader refuses a newer one rather than misread it.
inline constexpr int kRenderRecordFormat = 1;

struct RenderRecord {
  uint32_t frameWidth = 0, frameHeight = 0;  // the whole image the part belongs to
  uint32_t samplesPerPixel = 0;              // of the whole image
  uint32_t firstSample = 0, lastSample = 0;  // the samples each pixel holds (inclusive)
  // The pixels held: columns [x0, x1), rows [y0, y1) of the frame; the image is
  // (x1 - x0) x (y1 - y0).
  uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  uint32_t seed = 0;
  std::string sceneHash;  // renderIdentity's hash: scene, camera and settings (render/render_identity.h)
  std::string settings;   // the settings that decide a pixel's samples, as flags
  // How the frame's PNG is made; with autoExposure the exposure comes from the whole frame.
  DisplaySettings display;
  bool autoExposure = false;

  uint32_t sampleCount() const { return lastSample - firstSample + 1; }
};

// One named, typed header attribute as OpenEXR stores it (little-endian value bytes).
struct HeaderAttribute {
  std::string name;
  std::string type;  // OpenEXR's: "int", "string", "v2i", "box2i"
  std::vector<unsigned char> value;
};

// The record as EXR header attributes named wavepath.*: format (int), frame (v2i),
// spp (int), samples (v2i, first and last), region (box2i, inclusive as EXR boxes are),
// seed, sceneHash, settings and display ("exposure E|auto tone T transfer F gamma G"),
// strings.
std::vector<HeaderAttribute> recordAttributes(const RenderRecord& record);

// The record in `attributes`, or none when they hold no wavepath.format. Throws wp::Error
// (naming `file`) when the record is of a newer format or damaged.
std::optional<RenderRecord> recordFromAttributes(const std::vector<HeaderAttribute>& attributes,
                                                 const std::string& file);

}  // namespace wp
