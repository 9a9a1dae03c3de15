// The check of a file's extensionsRequired and extensionsUsed against what wavepath supports.
#include "scene/gltf_extensions.h"

#include <algorithm>
#include <string>
#include <vector>

namespace wp::gltf {

namespace {

bool isSupported(const std::string& name) {
  return std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), name) != kSupportedExtensions.end();
}

// The unsupported entries of `names`, each once, in file order.
std::vector<std::string> unsupported(const std::vector<std::string>& names) {
  std::vector<std::string> found;
  for (const std::string& name : names) {
    if (!isSupported(name) && std::find(found.begin(), found.end(), name) == found.end()) found.push_back(name);
  }
  return found;
}

std::string commaList(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

}  // namespace

void checkExtensions(const Context& ctx) {
  const std::vector<std::string> required = unsupported(ctx.model.extensionsRequired);
  if (!required.empty()) {
    const bool one = required.size() == 1;
    fail(ctx, "",
         std::string(one ? "requires extension " : "requires extensions ") + commaList(required) +
             ", which wavepath does not support; re-export the scene without " + (one ? "it" : "them"));
  }
  const std::vector<std::string> used = unsupported(ctx.model.extensionsUsed);
  if (!used.empty()) {
    warnAt(ctx, "", std::string(used.size() == 1 ? "extension " : "extensions ") + commaList(used) +
                        " ignored, the image may differ from other viewers");
  }
}

}  // namespace wp::gltf
