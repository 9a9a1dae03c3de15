// Compile-time checks that the host's view of the GPU structs matches std430 / OpenCL.
#include <cstddef>

#include "shaders/common/binding_table.h"
// Not used on the host: included so that the stage code is compiled as C++ too, as every
// portable header is.
#include "shaders/common/stages.h"

namespace wp::gpu {

static_assert(sizeof(BvhNode) == 128);
static_assert(sizeof(GpuTriangle) == 64);
static_assert(sizeof(GpuTriangleShading) == 160);
static_assert(sizeof(GpuTexture) == 48);
static_assert(sizeof(GpuInstance) == 64);
static_assert(sizeof(GpuPlane) == 32);
static_assert(sizeof(GpuMaterial) == 224);
static_assert(sizeof(GpuLight) == 96);
static_assert(sizeof(ThinLens) == 80);
static_assert(sizeof(GpuEnvironment) == 32);
static_assert(sizeof(RenderParams) == 224);
static_assert(sizeof(PathRay) == 64);
static_assert(sizeof(HitRecord) == 16);
static_assert(sizeof(ShadowRay) == 48);
static_assert(sizeof(PathFeatures) == 32);
static_assert(sizeof(QueueCounters) == WP_COUNTER_WORDS * 4);
static_assert(offsetof(QueueCounters, extendDispatch) == WP_COUNTER_EXTEND_DISPATCH * 4);
static_assert(offsetof(QueueCounters, connectDispatch) == WP_COUNTER_CONNECT_DISPATCH * 4);
static_assert(offsetof(QueueCounters, totals) == WP_COUNTER_TOTAL_RAYS * 4);
static_assert(sizeof(PassConstants) == 16);
static_assert(offsetof(RenderParams, width) == 112);
static_assert(offsetof(RenderParams, maxBounces) == 128);
static_assert(offsetof(RenderParams, planeCount) == 144);
static_assert(offsetof(RenderParams, bsdfFlags) == 160);
static_assert(offsetof(RenderParams, regionX) == 176);
static_assert(offsetof(RenderParams, samplerKind) == 200);
static_assert(offsetof(GpuEnvironment, width) == 16);

// The binding table: each row's stride is its element's size in 16-byte texels (what the
// GLSL loaders step by), rows come in binding order with no gaps, and the OpenCL rows come
// first (kernel argument i is binding i).
#define WP_CHECK_STRIDE(name, binding, Element, stride, format, access, backends)                   \
  static_assert((stride) == 0 ? sizeof(Element) == 4 : sizeof(Element) == 16 * (stride),              \
                "binding " #name ": the table's stride must be sizeof / 16 (0 for a 4-byte element)");
WP_BINDINGS(WP_CHECK_STRIDE)
static_assert([] {
  bool openClPart = true;
  for (uint i = 0; i < kBindingCount; ++i) {
    if (kBindings[i].index != i || (kBindings[i].openCl && !openClPart)) {
      return false;
    }
    openClPart = kBindings[i].openCl;
  }
  return true;
}());

}  // namespace wp::gpu
