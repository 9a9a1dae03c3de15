// The feature passes an EXR can hold besides the radiance (albedo, normal, depth), and the
// choice of them that --passes makes.
#pragma once

#include <filesystem>
#include <string>

#include "image/image_io.h"

namespace wp {

// Which feature passes go into the EXR.
struct PassSelection {
  bool albedo = true;
  bool normal = true;
  bool depth = true;
};

// What `wavepath render --passes list` prints: each pass, its EXR channels and what it holds.
std::string passListText();

// The passes a comma-separated list names ("albedo,normal", "all", "none"). Throws a
// wp::Error saying which names there are when a name is none of them.
PassSelection parsePasses(const std::string& text);

// Whether a render written to `output` records feature passes (RenderSettings::featurePasses):
// an EXR that keeps some of them does; a PNG, which has none, does not.
bool outputKeepsFeaturePasses(const std::filesystem::path& output, const PassSelection& selection);

// Empties the passes of `image` that `selection` leaves out.
void keepSelectedPasses(RadianceImage& image, const PassSelection& selection);

}  // namespace wp
