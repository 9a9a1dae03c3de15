// The check of a file's extensionsRequired and extensionsUsed against what wavepath supports.
#include "scene/gltf_extensions.h"

#include <algorithm>
#include <string>
#include <vector>

namespace wp::gltf {

namespace {

template <size_t N>
bool isIn(const std::array<std::string_view, N>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// The entries of `names` that `pick` accepts, each once, in file order.
template <typename Pick>
std::vector<std::string> select(const std::vector<std::string>& names, Pick pick) {
  std::vector<std::string> found;
  for (const std::string& name : names) {
    if (pick(name) && std::find(found.begin(), found.end(), name) == found.end()) found.push_back(name);
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
  const auto unsupported = [](const std::string& name) {
    return !isIn(kSupportedExtensions, name) && !isIn(kFallbackImageExtensions, name);
  };
  const std::vector<std::string> required = select(ctx.model.extensionsRequired, unsupported);
  if (!required.empty()) {
    const bool one = required.size() == 1;
    fail(ctx, "",
         std::string(one ? "requires extension " : "requires extensions ") + commaList(required) +
             ", which wavepath does not support; re-export the scene without " + (one ? "it" : "them"));
  }
  const std::vector<std::string> used = select(ctx.model.extensionsUsed, unsupported);
  if (!used.empty()) {
    warnAt(ctx, "", std::string(used.size() == 1 ? "extension " : "extensions ") + commaList(used) +
                        " ignored, the image may differ from other viewers");
  }
}

}  // namespace wp::gltf
