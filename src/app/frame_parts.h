// A frame split into parts: --samples and --region read into the settings, and the record
// of what a part holds.
#pragma once

#include <string>

#include "image/render_record.h"
#include "render/render_identity.h"
#include "render/settings.h"

namespace wp {

// "samples 16..31 of region 0,0,64,32 of " for what a part holds, "" for a whole render
// (the summary line's prefix).
std::string partText(const RenderSettings& settings);

// The EXR header's record of what a render with `settings` holds.
RenderRecord renderRecord(const RenderSettings& settings, const RenderIdentity& identity,
                          const DisplaySettings& display, bool autoExposure);

// Parses "X0,Y0,X1,Y1" (four whole numbers); throws a one-line wp::Error otherwise.
PixelRegion parseRegion(const std::string& text);

// Puts --samples A..B and --region X0,Y0,X1,Y1 (either may be empty) into `settings`,
// checked against its --spp and image size; throws a FlagError when they do not fit.
void applyPartFlags(RenderSettings& settings, const std::string& samples, const std::string& region);

}  // namespace wp
