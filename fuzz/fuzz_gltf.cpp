// libFuzzer target: any bytes as a .gltf or .glb file, loaded as `wavepath render` loads it,
// posed, packed for the GPU and checked for non-finite numbers.
#include <cstring>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  wp::fuzz::loadAndCheck(wp::fuzz::writeInput(binary ? "scene.glb" : "scene.gltf", data, size));
  return 0;
}
