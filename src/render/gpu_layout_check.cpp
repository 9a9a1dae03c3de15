// Compile-time checks that the host's view of the GPU structs matches std430 / OpenCL.
#include <cstddef>

#include "shaders/common/layout.h"

namespace wp::gpu {

static_assert(sizeof(BvhNode) == 64);
static_assert(sizeof(GpuTriangle) == 64);
static_assert(sizeof(GpuTriangleShading) == 128);
static_assert(sizeof(GpuTexture) == 16);
static_assert(sizeof(GpuInstance) == 64);
static_assert(sizeof(GpuPlane) == 32);
static_assert(sizeof(GpuMaterial) == 112);
static_assert(sizeof(GpuLight) == 96);
static_assert(sizeof(ThinLens) == 80);
static_assert(sizeof(GpuEnvironment) == 32);
static_assert(sizeof(RenderParams) == 192);
static_assert(sizeof(PathRay) == 64);
static_assert(sizeof(HitRecord) == 16);
static_assert(sizeof(ShadowRay) == 48);
static_assert(sizeof(QueueCounters) == WP_COUNTER_WORDS * 4);
static_assert(offsetof(QueueCounters, extendDispatch) == WP_COUNTER_EXTEND_DISPATCH * 4);
static_assert(offsetof(QueueCounters, connectDispatch) == WP_COUNTER_CONNECT_DISPATCH * 4);
static_assert(offsetof(QueueCounters, totals) == WP_COUNTER_TOTAL_RAYS * 4);
static_assert(sizeof(PassConstants) == 16);
static_assert(offsetof(RenderParams, image) == 112);

}  // namespace wp::gpu
