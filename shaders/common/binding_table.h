// The one table of the buffers the stages use. Everything else about a buffer follows from
// its row: the GLSL declarations and texel loaders (shaders/vulkan/bindings.glsl), the
// OpenCL kernel arguments (shaders/opencl/bindings.h), the DeviceBuffers bundle that carries
// them through the physics headers, and on the host the Vulkan descriptor types and texel
// formats, the OpenCL argument indices and the list of scene arrays (src/render/bindings.h).
// src/render/gpu_layout_check.cpp checks every row's stride against sizeof.
#ifndef WP_BINDING_TABLE_H
#define WP_BINDING_TABLE_H

#include "layout.h"

// X(name, binding, Element, stride, format, access, backends), in binding order:
//   name      the buffer's name in every language: GLSL variable, OpenCL kernel argument,
//             DeviceBuffers member, GpuScene member for a scene array;
//   stride    16-byte texels per element, 0 for a 4-byte element;
//   format    how a Vulkan texel buffer holds the elements: RECORD (a WP_RECORD of `stride`
//             RGBA32UI texels), VEC4 (one RGBA32UI texel each), R32 (one R32UI texel each),
//             WORDS (four uints to an RGBA32UI texel), NONE (not a texel buffer), VIEWED (a
//             storage buffer whose elements Vulkan reads through the TEXEL_VIEW row of the
//             same name);
//   access    UNIFORM (the render parameters; Vulkan reads them at an entry given by a push
//             constant, bindings.glsl says why), TEXELS (read-only; a scene array), STORAGE
//             (read and written), WRITE (a queue the stage appends to), TEXEL_VIEW (Vulkan:
//             the buffer of the same name again, read as texels: a queue by the next stage,
//             the paths' radiance and features and the pixels' sums by the stages that add
//             to them), CONSTANT
//             (read-only texels the backend uploads once from a header's table);
//   backends  ALL, or VULKAN for what OpenCL and C++ do without (their kernels read a buffer
//             through the buffer's own pointer, and shade every material class in one go): no
//             kernel argument, no DeviceBuffers member. Rows for ALL come first: OpenCL's
//             kernel argument i is binding i.
// Read-only data goes through texel buffers on Vulkan: on lavapipe a texel fetch is a SIMD
// gather where a storage-buffer load is a per-lane scalar loop, and on GPUs it goes through
// the texture cache.
#define WP_BINDINGS(X)                                                            \
  X(params, 0, RenderParams, 14, NONE, UNIFORM, ALL)                              \
  X(nodes, 1, BvhNode, 8, RECORD, TEXELS, ALL)                                    \
  X(triangles, 2, GpuTriangle, 4, RECORD, TEXELS, ALL)                            \
  X(instances, 3, GpuInstance, 4, RECORD, TEXELS, ALL)                            \
  X(planes, 4, GpuPlane, 2, RECORD, TEXELS, ALL)                                  \
  X(materials, 5, GpuMaterial, 14, RECORD, TEXELS, ALL)                           \
  X(lights, 6, GpuLight, 6, RECORD, TEXELS, ALL)                                  \
  X(rays, 7, PathRay, 4, NONE, WRITE, ALL)                                        \
  X(hits, 8, HitRecord, 1, NONE, WRITE, ALL)                                      \
  X(shadowRays, 9, ShadowRay, 3, NONE, WRITE, ALL)                                \
  X(pathRadiance, 10, vec4, 1, VIEWED, STORAGE, ALL)                              \
  X(counters, 11, uint, 0, NONE, STORAGE, ALL)                                    \
  X(accumulation, 12, vec4, 1, VIEWED, STORAGE, ALL)                              \
  X(skyRadiance, 13, vec4, 1, VEC4, TEXELS, ALL)                                  \
  X(skyMarginal, 14, float, 0, R32, TEXELS, ALL)                                  \
  X(skyConditional, 15, float, 0, R32, TEXELS, ALL)                               \
  X(triangleShading, 16, GpuTriangleShading, 10, RECORD, TEXELS, ALL)             \
  X(textures, 17, GpuTexture, 3, RECORD, TEXELS, ALL)                             \
  X(texels, 18, uint, 0, WORDS, TEXELS, ALL)                                      \
  X(pathFeatures, 19, PathFeatures, 2, VIEWED, STORAGE, ALL)                       \
  X(rays, 20, PathRay, 4, RECORD, TEXEL_VIEW, VULKAN)                             \
  X(hits, 21, HitRecord, 1, RECORD, TEXEL_VIEW, VULKAN)                           \
  X(shadowRays, 22, ShadowRay, 3, RECORD, TEXEL_VIEW, VULKAN)                      \
  X(bsdfTables, 23, vec4, 1, VEC4, CONSTANT, VULKAN)                              \
  X(deferredHits, 24, uint, 0, NONE, STORAGE, VULKAN)                            \
  X(pathRadiance, 25, vec4, 1, VEC4, TEXEL_VIEW, VULKAN)                          \
  X(pathFeatures, 26, PathFeatures, 2, RECORD, TEXEL_VIEW, VULKAN)                \
  X(accumulation, 27, vec4, 1, VEC4, TEXEL_VIEW, VULKAN)

// What the rows mean:
//   params          RenderParams, the render's settings
//   nodes           all bottom-level BVHs, then the top level
//   triangles       in BVH leaf order
//   rays            PathRay[2 * maxPaths]: the two ping-pong ray queues
//   hits            HitRecord[maxPaths], parallel to the ray queue being traced
//   shadowRays      ShadowRay[maxPaths]: the shadow queue
//   pathRadiance    radiance of each path of the pass
//   counters        QueueCounters as words (WP_COUNTER_*)
//   accumulation    vec4[WP_ACCUMULATION_LAYERS * pixels]: per-pixel sums, one layer after
//                   another (accumulation.h: radiance, its square, the feature passes)
//   skyRadiance, skyMarginal, skyConditional   the sky's texels and distributions
//                   (environment.h)
//   triangleShading parallel to the triangles
//   pathFeatures    PathFeatures[maxPaths]: the feature passes of each path of the pass
//   texels          RGBA8 texels of every texture, r in the low byte
//   bsdfTables      the BSDF's constant tables (bsdf_table_lookup.h) as quads, one texel
//                   each, packed from the header's own array. Vulkan only: OpenCL and C++
//                   read that array as a constant, but llvmpipe takes minutes to compile a
//                   shader that holds it.
//   deferredHits    uint[maxPaths]: the deferred shade queue (queues.h), entries of the
//                   ray queue. Vulkan only: OpenCL shades every material in one kernel.

WP_BEGIN

#ifdef WP_BUFFERS_AS_ARGUMENTS
// C++ and OpenCL: every buffer but the parameters as a pointer in one bundle, which the
// functions that read buffers take first (WP_BUFFERS) and pass on (WP_BUFFERS_ARG).
#define WP_DEVICE_BUFFER_MEMBER(name, binding, Element, stride, format, access, backends) \
  WP_ON_OPENCL_##backends(WP_DEVICE_BUFFER_MEMBER_##access(name, Element))
// What a row gives C++ and OpenCL: all of it for ALL, nothing for VULKAN.
#define WP_ON_OPENCL_ALL(x) x
#define WP_ON_OPENCL_VULKAN(x)
#define WP_DEVICE_BUFFER_MEMBER_UNIFORM(name, Element)
#define WP_DEVICE_BUFFER_MEMBER_TEXELS(name, Element) WP_GLOBAL_PTR(Element) name;
#define WP_DEVICE_BUFFER_MEMBER_STORAGE(name, Element) WP_GLOBAL_MUTABLE_PTR(Element) name;
#define WP_DEVICE_BUFFER_MEMBER_WRITE(name, Element) WP_GLOBAL_MUTABLE_PTR(Element) name;
#define WP_DEVICE_BUFFER_MEMBER_TEXEL_VIEW(name, Element)
#define WP_DEVICE_BUFFER_MEMBER_CONSTANT(name, Element)
WP_STRUCT(DeviceBuffers)
  WP_BINDINGS(WP_DEVICE_BUFFER_MEMBER)
WP_STRUCT_END(DeviceBuffers)

#if defined(__cplusplus)
#define WP_BUFFERS const DeviceBuffers &buffers,
#define WP_LOAD(name, i) buffers.name[i]
#define WP_BUFFER(name) buffers.name
#else
// OpenCL: a pointer to the kernel's bundle in local memory (WP_KERNEL_BUFFERS), so that a
// call the compiler does not inline passes one pointer rather than a copy of every buffer's.
#define WP_BUFFERS __local const DeviceBuffers *buffers,
#define WP_LOAD(name, i) buffers->name[i]
#define WP_BUFFER(name) buffers->name
#endif
#define WP_BUFFERS_ARG buffers,
#else
// GLSL: the buffers are globals that the stage declares (shaders/vulkan/bindings.glsl),
// read through the generated <name>At(i) loaders.
#define WP_LOAD(name, i) name##At(i)
#define WP_BUFFER(name) name
#define WP_BUFFERS
#define WP_BUFFERS_ARG
#endif

#if defined(__cplusplus)
// The host's view of the table: what each binding is, for the backends.
enum class BindingAccess { Uniform, Texels, Storage, Write, TexelView, Constant };
enum class TexelFormat { None, Rgba32ui, R32ui };

struct BindingInfo {
  const char* name;
  uint index;
  uint elementBytes;
  uint stride;  // 16-byte texels per element; 0 for a 4-byte element
  TexelFormat format;  // of a Vulkan texel view
  BindingAccess access;
  bool openCl;  // an OpenCL kernel argument, at the binding's index
};

#define WP_HOST_BINDING(name, binding, Element, stride, format, access, backends)                       \
  BindingInfo{#name, binding, uint(sizeof(Element)), stride, WP_HOST_FORMAT_##format, WP_HOST_ACCESS_##access, \
              WP_HOST_ON_OPENCL_##backends},
#define WP_HOST_FORMAT_NONE TexelFormat::None
#define WP_HOST_FORMAT_VIEWED TexelFormat::None
#define WP_HOST_FORMAT_RECORD TexelFormat::Rgba32ui
#define WP_HOST_FORMAT_VEC4 TexelFormat::Rgba32ui
#define WP_HOST_FORMAT_WORDS TexelFormat::Rgba32ui
#define WP_HOST_FORMAT_R32 TexelFormat::R32ui
#define WP_HOST_ACCESS_UNIFORM BindingAccess::Uniform
#define WP_HOST_ACCESS_TEXELS BindingAccess::Texels
#define WP_HOST_ACCESS_STORAGE BindingAccess::Storage
#define WP_HOST_ACCESS_WRITE BindingAccess::Write
#define WP_HOST_ACCESS_TEXEL_VIEW BindingAccess::TexelView
#define WP_HOST_ACCESS_CONSTANT BindingAccess::Constant
#define WP_HOST_ON_OPENCL_ALL true
#define WP_HOST_ON_OPENCL_VULKAN false
inline constexpr BindingInfo kBindings[] = {WP_BINDINGS(WP_HOST_BINDING)};
inline constexpr uint kBindingCount = uint(sizeof(kBindings) / sizeof(kBindings[0]));

// Binding indices by name, for the host's own buffers: Binding::rays, and a queue's texel
// view as Binding::raysTexelView (a struct around a plain enum, so they convert to uint).
#define WP_HOST_ENUMERATOR(name, binding, Element, stride, format, access, backends) \
  WP_HOST_ENUMERATOR_##access(name, binding)
#define WP_HOST_ENUMERATOR_UNIFORM(name, binding) name = binding,
#define WP_HOST_ENUMERATOR_TEXELS(name, binding) name = binding,
#define WP_HOST_ENUMERATOR_STORAGE(name, binding) name = binding,
#define WP_HOST_ENUMERATOR_WRITE(name, binding) name = binding,
#define WP_HOST_ENUMERATOR_TEXEL_VIEW(name, binding) name##TexelView = binding,
#define WP_HOST_ENUMERATOR_CONSTANT(name, binding) name = binding,
struct Binding {
  enum : uint { WP_BINDINGS(WP_HOST_ENUMERATOR) };
};

// The scene arrays (the TEXELS rows) in binding order: WP_FOR_EACH_SCENE_ARRAY expands
// WP_SCENE_ARRAY(name) for each, a macro the including code defines.
#define WP_SCENE_ARRAY_ROW(name, binding, Element, stride, format, access, backends) \
  WP_SCENE_ARRAY_ROW_##access(name)
#define WP_SCENE_ARRAY_ROW_UNIFORM(name)
#define WP_SCENE_ARRAY_ROW_TEXELS(name) WP_SCENE_ARRAY(name)
#define WP_SCENE_ARRAY_ROW_STORAGE(name)
#define WP_SCENE_ARRAY_ROW_WRITE(name)
#define WP_SCENE_ARRAY_ROW_TEXEL_VIEW(name)
#define WP_SCENE_ARRAY_ROW_CONSTANT(name)
#define WP_FOR_EACH_SCENE_ARRAY WP_BINDINGS(WP_SCENE_ARRAY_ROW)
#endif

WP_END

#endif
