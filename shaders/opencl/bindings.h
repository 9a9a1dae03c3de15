// The arguments every OpenCL stage kernel takes, and the queue counters as a struct: the
// OpenCL counterpart of ../vulkan/bindings.glsl. The host includes it for WP_ARG_PASS.
#ifndef WP_OPENCL_BINDINGS_H
#define WP_OPENCL_BINDINGS_H

// Kernel argument i is the buffer of binding i (layout.h) for every i < WP_ARG_PASS, so the
// host sets each buffer once for all kernels; the pass constants follow, by value. The
// bindings through which Vulkan reads a queue again as texels have no argument here: the
// queue's own pointer reads it.
#define WP_ARG_PASS (WP_BINDING_TEXELS + 1u)

#if defined(__OPENCL_VERSION__) || defined(__OPENCL_C_VERSION__)
#include "common/layout.h"

#define WP_KERNEL_ARGS                                                                                   \
  __constant RenderParams *paramsBuffer, __global const BvhNode *nodes, __global const GpuTriangle *triangles, \
      __global const GpuInstance *instances, __global const GpuPlane *planes,                           \
      __global const GpuMaterial *materials, __global const GpuLight *lights, __global PathRay *rays,   \
      __global HitRecord *hits, __global ShadowRay *shadowRays, __global float4 *pathRadiance,         \
      __global uint *counters, __global float4 *accumulation, __global const float4 *envRadiance,     \
      __global const float *envMarginal, __global const float *envConditional,                         \
      __global const GpuTriangleShading *triangleShading, __global const GpuTexture *textures,          \
      __global const uint *texels, PassConstants pc

// Every dispatch runs workgroups of WP_WORKGROUP_SIZE, which lets the compiler specialise.
#define WP_KERNEL __kernel __attribute__((reqd_work_group_size(WP_WORKGROUP_SIZE, 1, 1)))

QueueCounters loadCounters(__global const uint *counters) { return *(__global const QueueCounters *)counters; }
void storeCounters(__global uint *counters, QueueCounters c) { *(__global QueueCounters *)counters = c; }

// The ray queue (and shadow queue) of the pass's current bounce.
uint bounceParity(PassConstants pc) { return pc.pass.w & 1u; }
#endif

#endif
