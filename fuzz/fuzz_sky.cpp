// libFuzzer target: any bytes as a sky image, .hdr or .exr by the build's WP_FUZZ_SKY_EXTENSION,
// read and turned into a sampling distribution as `--sky` does, and checked for non-finite numbers.
#include "core/error.h"
#include "fuzz_support.h"
#include "scene/environment_map.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    wp::fuzz::checkFinite(wp::loadEnvironmentMap(wp::fuzz::writeInput("sky" WP_FUZZ_SKY_EXTENSION, data, size)));
  } catch (const wp::Error&) {
    // One line of bad input: what the reader should say.
  }
  return 0;
}
