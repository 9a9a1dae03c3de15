// The names of the feature passes and the --passes list that selects them.
#include "image/feature_passes.h"

#include <sstream>

#include "core/error.h"

namespace wp {

std::string passListText() {
  return "albedo   albedo.R, albedo.G, albedo.B   base colour of the first surface that is not a perfect mirror or "
         "glass (seen through those), the sky's radiance clamped to 1 where the path leaves the scene\n"
         "normal   normal.X, normal.Y, normal.Z   world-space shading normal of that surface, facing the camera's "
         "side; 0 for the sky\n"
         "depth    depth.Z                        distance of the camera ray's first hit along the camera's axis; "
         "1e10 for the sky\n"
         "(each the mean over the pixel's samples; --passes all, the default, or none)\n";
}

PassSelection parsePasses(const std::string& text) {
  if (text == "all") return {};
  PassSelection selection{false, false, false};
  if (text == "none") return selection;
  std::istringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "albedo") {
      selection.albedo = true;
    } else if (name == "normal") {
      selection.normal = true;
    } else if (name == "depth") {
      selection.depth = true;
    } else {
      throw Error("'" + name + "' is not a feature pass; give a comma-separated list of albedo, normal and depth, "
                  "or all, none, list");
    }
  }
  return selection;
}

bool outputKeepsFeaturePasses(const std::filesystem::path& output, const PassSelection& selection) {
  return isExrPath(output) && (selection.albedo || selection.normal || selection.depth);
}

void keepSelectedPasses(RadianceImage& image, const PassSelection& selection) {
  if (!selection.albedo) image.albedo.clear();
  if (!selection.normal) image.normal.clear();
  if (!selection.depth) image.depth.clear();
}

}  // namespace wp
