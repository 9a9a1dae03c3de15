// Buffer declarations shared by every Vulkan stage (one descriptor set, see layout.h).
// The portable headers read the scene through these global names.

#include "common/layout.h"

layout(local_size_x = WP_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { PassConstants pc; };
layout(std140, binding = WP_BINDING_PARAMS) uniform Params { RenderParams params; };
layout(std430, binding = WP_BINDING_NODES) readonly buffer Nodes { BvhNode nodes[]; };
layout(std430, binding = WP_BINDING_TRIANGLES) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = WP_BINDING_INSTANCES) readonly buffer Instances { GpuInstance instances[]; };
layout(std430, binding = WP_BINDING_PLANES) readonly buffer Planes { GpuPlane planes[]; };
layout(std430, binding = WP_BINDING_MATERIALS) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = WP_BINDING_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = WP_BINDING_RAYS) buffer Rays { PathRay rays[]; };
layout(std430, binding = WP_BINDING_HITS) buffer Hits { HitRecord hits[]; };
layout(std430, binding = WP_BINDING_SHADOW_RAYS) buffer ShadowRays { ShadowRay shadowRays[]; };
layout(std430, binding = WP_BINDING_PATH_RADIANCE) buffer PathRadiance { vec4 pathRadiance[]; };
layout(std430, binding = WP_BINDING_COUNTERS) buffer Counters { uint counters[]; };
layout(std430, binding = WP_BINDING_ACCUM) buffer Accumulation { vec4 accumulation[]; };

uint bounceParity() { return pc.pass.w & 1u; }
