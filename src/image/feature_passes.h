// The feature passes an EXR can hold besides the radiance (albedo, normal, depth), and the
// choice of them that --passes makes.
#pragma once

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

// Empties the passes of `image` that `selection` leaves out.
void keepSelectedPasses(RadianceImage& image, const PassSelection& selection);

}  // namespace wp
