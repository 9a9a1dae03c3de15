// Buffer limits of a device, the testing cap, and the messages when something does not fit.
#include "render/device_limits.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"

namespace wp {

DeviceLimits withBufferCap(DeviceLimits limits) {
  const char* cap = std::getenv("WAVEPATH_MAX_BUFFER_BYTES");
  if (cap == nullptr || *cap == '\0') return limits;
  char* end = nullptr;
  const unsigned long long bytes = std::strtoull(cap, &end, 10);
  if (*end != '\0' || bytes < 1024) {
    throw Error(std::string("WAVEPATH_MAX_BUFFER_BYTES is '") + cap + "'; set it to a number of bytes of 1024 or more, "
                "or unset it");
  }
  for (ByteLimit* limit : {&limits.writable, &limits.sceneArray}) {
    if (bytes < limit->bytes) *limit = {bytes, "WAVEPATH_MAX_BUFFER_BYTES"};
  }
  return limits;
}

void checkFits(const DeviceLimits& device, const std::string& what, uint64_t bytes, const ByteLimit& limit,
               const std::string& advice) {
  if (bytes <= limit.bytes) return;
  throw Error(what + ": " + byteSize(bytes) + ", more than the " + byteSize(limit.bytes) + " " + device.device +
              " allows (" + limit.name + "); " + advice);
}

uint64_t checkSceneFits(const DeviceLimits& device, const std::array<SceneArray, kSceneBindings.size()>& arrays) {
  uint64_t total = 0;
  for (const SceneArray& array : arrays) {
    checkFits(device, std::string("the scene's ") + array.name, array.bytes, device.sceneArray,
              "render a smaller scene (fewer triangles, smaller textures or sky), or pick another --device or --backend");
    total += array.bytes;
  }
  checkFits(device, "the scene", total, device.memory,
            "render a smaller scene (fewer triangles, smaller textures or sky), or pick another --device or --backend");
  return total;
}

void checkPathStateFits(const DeviceLimits& device, uint64_t rayQueueBytes, uint64_t accumulationPixels,
                        uint64_t totalBytes) {
  checkFits(device, "the ray queues", rayQueueBytes, device.writable, "lower --max-paths");
  // The renderer splits an image into tiles that fit; only a single row can be too wide.
  checkFits(device, "the accumulation of " + std::to_string(accumulationPixels) + " pixels",
            accumulationPixels * kAccumulationBytesPerPixel, device.writable, "lower --width");
  checkFits(device, "the scene, the paths in flight and the image", totalBytes, device.memory,
            "lower --max-paths or --width, or render a smaller scene");
}

std::string byteSize(uint64_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  double value = double(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 4) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof(text), unit == 0 ? "%.0f %s" : "%.3g %s", value, units[unit]);
  return text;
}

}  // namespace wp
