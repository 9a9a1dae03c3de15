// Buffer declarations shared by every Vulkan stage (one descriptor set, see layout.h), the
// texel-fetch loaders behind the WP_NODE(i)-style accessors of the portable headers, and
// the queue counters as a QueueCounters struct for the stage functions of stages.h.
#include "common/layout.h"

layout(local_size_x = WP_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { PassConstants pc; };
layout(std140, binding = WP_BINDING_PARAMS) uniform Params { RenderParams params; };

layout(binding = WP_BINDING_NODES) uniform usamplerBuffer nodeTexels;
layout(binding = WP_BINDING_TRIANGLES) uniform usamplerBuffer triangleTexels;
layout(binding = WP_BINDING_INSTANCES) uniform usamplerBuffer instanceTexels;
layout(binding = WP_BINDING_PLANES) uniform usamplerBuffer planeTexels;
layout(binding = WP_BINDING_MATERIALS) uniform usamplerBuffer materialTexels;
layout(binding = WP_BINDING_LIGHTS) uniform usamplerBuffer lightTexels;
layout(binding = WP_BINDING_ENV_RADIANCE) uniform usamplerBuffer skyRadianceTexels;
layout(binding = WP_BINDING_ENV_MARGINAL) uniform usamplerBuffer skyMarginalTexels;
layout(binding = WP_BINDING_ENV_CONDITIONAL) uniform usamplerBuffer skyConditionalTexels;
layout(binding = WP_BINDING_TRIANGLE_SHADING) uniform usamplerBuffer triangleShadingTexels;
layout(binding = WP_BINDING_TEXTURES) uniform usamplerBuffer textureTexels;
layout(binding = WP_BINDING_TEXELS) uniform usamplerBuffer texelTexels;
layout(binding = WP_BINDING_RAYS_READ) uniform usamplerBuffer rayTexels;
layout(binding = WP_BINDING_HITS_READ) uniform usamplerBuffer hitTexels;
layout(binding = WP_BINDING_SHADOW_RAYS_READ) uniform usamplerBuffer shadowRayTexels;
layout(binding = WP_BINDING_BSDF_TABLES) uniform usamplerBuffer bsdfTableTexels;
#define WP_BSDF_TABLE(i) uintBitsToFloat(texelFetch(bsdfTableTexels, int(i)).x)

layout(std430, binding = WP_BINDING_RAYS) writeonly buffer Rays { PathRay rays[]; };
layout(std430, binding = WP_BINDING_HITS) writeonly buffer Hits { HitRecord hits[]; };
layout(std430, binding = WP_BINDING_SHADOW_RAYS) writeonly buffer ShadowRays { ShadowRay shadowRays[]; };
layout(std430, binding = WP_BINDING_PATH_RADIANCE) buffer PathRadiance { vec4 pathRadiance[]; };
layout(std430, binding = WP_BINDING_COUNTERS) buffer Counters { uint counters[]; };
layout(std430, binding = WP_BINDING_ACCUM) buffer Accumulation { vec4 accumulation[]; };

// Texel t of element i of a struct `stride` texels long, as floats or as uints.
#define WP_FLOATS(texels, i, stride, t) uintBitsToFloat(texelFetch(texels, int((i) * (stride) + (t))))
#define WP_UINTS(texels, i, stride, t) texelFetch(texels, int((i) * (stride) + (t)))

BvhNode loadNode(uint i) {
  BvhNode n;
  n.leftMin = WP_FLOATS(nodeTexels, i, 4u, 0u);
  n.leftMax = WP_FLOATS(nodeTexels, i, 4u, 1u);
  n.rightMin = WP_FLOATS(nodeTexels, i, 4u, 2u);
  n.rightMax = WP_FLOATS(nodeTexels, i, 4u, 3u);
  return n;
}

GpuTriangle loadTriangle(uint i) {
  GpuTriangle t;
  t.v0 = WP_FLOATS(triangleTexels, i, 4u, 0u);
  t.edge1 = WP_FLOATS(triangleTexels, i, 4u, 1u);
  t.edge2 = WP_FLOATS(triangleTexels, i, 4u, 2u);
  t.info = WP_UINTS(triangleTexels, i, 4u, 3u);
  return t;
}

GpuInstance loadInstance(uint i) {
  GpuInstance inst;
  inst.worldToObject0 = WP_FLOATS(instanceTexels, i, 4u, 0u);
  inst.worldToObject1 = WP_FLOATS(instanceTexels, i, 4u, 1u);
  inst.worldToObject2 = WP_FLOATS(instanceTexels, i, 4u, 2u);
  inst.info = WP_UINTS(instanceTexels, i, 4u, 3u);
  return inst;
}

GpuPlane loadPlane(uint i) {
  GpuPlane p;
  p.normalDistance = WP_FLOATS(planeTexels, i, 2u, 0u);
  p.info = WP_UINTS(planeTexels, i, 2u, 1u);
  return p;
}

GpuTriangleShading loadTriangleShading(uint i) {
  GpuTriangleShading t;
  t.normal0 = WP_FLOATS(triangleShadingTexels, i, 8u, 0u);
  t.normal1 = WP_FLOATS(triangleShadingTexels, i, 8u, 1u);
  t.normal2 = WP_FLOATS(triangleShadingTexels, i, 8u, 2u);
  t.v = WP_FLOATS(triangleShadingTexels, i, 8u, 3u);
  t.colors = WP_UINTS(triangleShadingTexels, i, 8u, 4u);
  t.tangent0 = WP_FLOATS(triangleShadingTexels, i, 8u, 5u);
  t.tangent1 = WP_FLOATS(triangleShadingTexels, i, 8u, 6u);
  t.tangent2 = WP_FLOATS(triangleShadingTexels, i, 8u, 7u);
  return t;
}

GpuTexture loadTexture(uint i) {
  GpuTexture t;
  t.info = WP_UINTS(textureTexels, i, 1u, 0u);
  return t;
}

// Four packed texels per RGBA32UI texel of the buffer.
uint loadTexelWord(uint i) { return texelFetch(texelTexels, int(i >> 2u))[i & 3u]; }

GpuMaterial loadMaterial(uint i) {
  GpuMaterial m;
  m.baseColor = WP_FLOATS(materialTexels, i, 7u, 0u);
  m.emission = WP_FLOATS(materialTexels, i, 7u, 1u);
  m.surface = WP_FLOATS(materialTexels, i, 7u, 2u);
  m.attenuation = WP_FLOATS(materialTexels, i, 7u, 3u);
  m.info = WP_UINTS(materialTexels, i, 7u, 4u);
  m.normalMap = WP_FLOATS(materialTexels, i, 7u, 5u);
  m.emissiveMap = WP_UINTS(materialTexels, i, 7u, 6u);
  return m;
}

GpuLight loadLight(uint i) {
  GpuLight l;
  l.v0 = WP_FLOATS(lightTexels, i, 6u, 0u);
  l.edge1 = WP_FLOATS(lightTexels, i, 6u, 1u);
  l.edge2 = WP_FLOATS(lightTexels, i, 6u, 2u);
  l.emission = WP_FLOATS(lightTexels, i, 6u, 3u);
  l.motion = WP_FLOATS(lightTexels, i, 6u, 4u);
  l.info = WP_UINTS(lightTexels, i, 6u, 5u);
  return l;
}

PathRay loadRay(uint i) {
  PathRay r;
  r.origin = WP_FLOATS(rayTexels, i, 4u, 0u);
  r.direction = WP_FLOATS(rayTexels, i, 4u, 1u);
  r.throughput = WP_FLOATS(rayTexels, i, 4u, 2u);
  r.state = WP_UINTS(rayTexels, i, 4u, 3u);
  return r;
}

ShadowRay loadShadowRay(uint i) {
  ShadowRay s;
  s.origin = WP_FLOATS(shadowRayTexels, i, 3u, 0u);
  s.direction = WP_FLOATS(shadowRayTexels, i, 3u, 1u);
  s.contribution = WP_FLOATS(shadowRayTexels, i, 3u, 2u);
  return s;
}

#define WP_NODE(i) loadNode(i)
#define WP_TRIANGLE(i) loadTriangle(i)
#define WP_INSTANCE(i) loadInstance(i)
#define WP_PLANE(i) loadPlane(i)
#define WP_MATERIAL(i) loadMaterial(i)
#define WP_LIGHT(i) loadLight(i)
#define WP_ENV_RADIANCE(i) WP_FLOATS(skyRadianceTexels, i, 1u, 0u)
#define WP_ENV_MARGINAL(i) uintBitsToFloat(texelFetch(skyMarginalTexels, int(i)).x)
#define WP_ENV_CONDITIONAL(i) uintBitsToFloat(texelFetch(skyConditionalTexels, int(i)).x)
#define WP_TRIANGLE_SHADING(i) loadTriangleShading(i)
#define WP_TEXTURE(i) loadTexture(i)
#define WP_TEXEL_WORD(i) loadTexelWord(i)

uint bounceParity() { return pc.pass.w & 1u; }

QueueCounters loadCounters() {
  QueueCounters c;
  c.counts = uvec4(counters[0], counters[1], counters[2], counters[3]);
  c.totals = uvec4(counters[4], counters[5], counters[6], counters[7]);
  c.extendDispatch = uvec4(counters[8], counters[9], counters[10], counters[11]);
  c.connectDispatch = uvec4(counters[12], counters[13], counters[14], counters[15]);
  return c;
}

void storeCounters(QueueCounters c) {
  for (uint i = 0u; i < 4u; ++i) {
    counters[i] = c.counts[i];
    counters[4u + i] = c.totals[i];
    counters[8u + i] = c.extendDispatch[i];
    counters[12u + i] = c.connectDispatch[i];
  }
}
