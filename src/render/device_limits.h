// What a device allows its buffers, checked before anything is allocated, with one-line
// errors saying what needs how much and what the device allows.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "render/backend.h"

namespace wp {

// One limit: how many bytes, and the name the device's documentation gives it.
struct ByteLimit {
  uint64_t bytes = 0;
  std::string name;  // e.g. "maxStorageBufferRange", "CL_DEVICE_MAX_MEM_ALLOC_SIZE"
};

struct DeviceLimits {
  std::string device;   // how messages name it: "Vulkan device 'llvmpipe ...'"
  ByteLimit writable;   // one buffer the stages write: the path queues, the accumulation
  ByteLimit sceneArray; // one read-only scene array (Vulkan: a texel buffer of 16-byte texels)
  ByteLimit memory;     // all buffers together
};

// `limits` with both per-buffer limits lowered to WAVEPATH_MAX_BUFFER_BYTES when that is set:
// a testing aid that runs the code for devices with small limits (a split image, a scene too
// large) on a small image. Throws wp::Error when it is set but is not a whole number >= 1024.
DeviceLimits withBufferCap(DeviceLimits limits);

// Throws wp::Error unless `bytes` fit in `limit`: "<what>: 2.44 GiB, more than the 2 GiB
// <device> allows (<limit name>); <advice>".
void checkFits(const DeviceLimits& device, const std::string& what, uint64_t bytes, const ByteLimit& limit,
               const std::string& advice);

// Checks every array of a packed scene against the per-array limit and all of them
// together against the device's memory, before anything is allocated; returns their total
// bytes. Throws wp::Error naming the first array (or the whole scene) that does not fit.
uint64_t checkSceneFits(const DeviceLimits& device, const std::array<SceneArray, kSceneBindings.size()>& arrays);

// Checks the ray queues and the accumulation of `accumulationPixels` against the
// writable-buffer limit, and `totalBytes` (the scene, the path state and the accumulation)
// against the memory.
void checkPathStateFits(const DeviceLimits& device, uint64_t rayQueueBytes, uint64_t accumulationPixels,
                        uint64_t totalBytes);

// A size to three digits in the largest unit that keeps it at 1 or more: "12.5 MiB".
std::string byteSize(uint64_t bytes);

}  // namespace wp
