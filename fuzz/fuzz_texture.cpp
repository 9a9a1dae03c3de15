// libFuzzer target: any bytes as the one image of a textured quad in a .glb (base colour,
// emissive and normal texture), decoded as wavepath decodes PNG and JPEG textures.
#include <vector>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;  // a buffer view must not be empty; that case is the glTF target's
  const std::vector<uint8_t> glb = wp::fuzz::texturedQuadGlb(data, size);
  wp::fuzz::loadAndCheck(wp::fuzz::writeInput("textured.glb", glb.data(), glb.size()));
  return 0;
}
