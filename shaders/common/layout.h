// GPU buffer structs, binding indices and workgroup sizes shared by host, GLSL and OpenCL.
// Every struct is made of 16-byte vec4/uvec4 fields so std430, OpenCL and C++ agree on the
// layout; the host checks sizes with static_assert (src/render/gpu_layout_check.cpp).
#ifndef WP_LAYOUT_H
#define WP_LAYOUT_H

#include "portable.h"
#include "thin_lens.h"

WP_BEGIN

#define WP_WORKGROUP_SIZE 64

// Binding indices (set 0) of the Vulkan stages; OpenCL passes the same buffers as kernel
// arguments. Read-only data is bound as uniform texel buffers (RGBA32UI): on lavapipe a
// texel fetch is a SIMD gather while a storage-buffer load is a per-lane scalar loop, and
// on GPUs it goes through the texture cache. Writes go through storage buffers.
#define WP_BINDING_PARAMS 0         // RenderParams (Vulkan: a read-only storage buffer, bindings.glsl)
#define WP_BINDING_NODES 1          // BvhNode[] (texels): all bottom-level BVHs, then the top level
#define WP_BINDING_TRIANGLES 2      // GpuTriangle[] (texels) in BVH leaf order
#define WP_BINDING_INSTANCES 3      // GpuInstance[] (texels)
#define WP_BINDING_PLANES 4         // GpuPlane[] (texels)
#define WP_BINDING_MATERIALS 5      // GpuMaterial[] (texels)
#define WP_BINDING_LIGHTS 6         // GpuLight[] (texels)
#define WP_BINDING_RAYS 7           // PathRay[2 * maxPaths]: two ping-pong queues (written)
#define WP_BINDING_HITS 8           // HitRecord[maxPaths] (written)
#define WP_BINDING_SHADOW_RAYS 9    // ShadowRay[maxPaths] (written)
#define WP_BINDING_PATH_RADIANCE 10 // vec4[maxPaths]: radiance of each path this pass
#define WP_BINDING_COUNTERS 11      // QueueCounters
#define WP_BINDING_ACCUM 12         // vec4[2 * pixels]: sum of radiance, sum of squares
#define WP_BINDING_ENV_RADIANCE 13  // vec4[] (texels): sky radiance per texel (environment.h)
#define WP_BINDING_ENV_MARGINAL 14  // float[] (texels): the sky's row distribution
#define WP_BINDING_ENV_CONDITIONAL 15  // float[] (texels): its column distributions
#define WP_BINDING_TRIANGLE_SHADING 16  // GpuTriangleShading[] (texels), parallel to the triangles
#define WP_BINDING_TEXTURES 17      // GpuTexture[] (texels)
#define WP_BINDING_TEXELS 18        // uint[] (texels): RGBA8 texels of every texture, r in the low byte
#define WP_BINDING_RAYS_READ 19     // the rays buffer again, as texels (Vulkan only)
#define WP_BINDING_HITS_READ 20     // the hits buffer again, as texels (Vulkan only)
#define WP_BINDING_SHADOW_RAYS_READ 21  // the shadow-ray buffer again, as texels (Vulkan only)
// float[] (texels): the BSDF's constant tables (energy_compensation.h), uploaded from the
// header's own array. Vulkan only: OpenCL and C++ read that array as a constant, but
// llvmpipe takes minutes to compile a shader that holds it.
#define WP_BINDING_BSDF_TABLES 22
#define WP_BINDING_COUNT 23u

// Integrator modes (RenderParams.mode.y).
#define WP_MODE_MIS 0u
#define WP_MODE_NEE 1u
#define WP_MODE_BSDF 2u

// Light selection for next event estimation (RenderParams.shading.z).
#define WP_LIGHT_SELECTION_POWER 0u        // alias table by emitted power
#define WP_LIGHT_SELECTION_SOLID_ANGLE 1u  // by subtended solid angle times luminance (lights.h)

// GpuInstance.info.x: what the instance is.
#define WP_INSTANCE_MESH 0u
#define WP_INSTANCE_SPHERE 1u  // unit sphere at the object-space origin

#define WP_INVALID 0xffffffffu

// Element access to the read-only scene buffers. C++ and OpenCL index arrays passed as
// arguments; GLSL (shaders/vulkan/bindings.glsl) fetches texels.
#ifdef WP_BUFFERS_AS_ARGUMENTS
#define WP_NODE(i) nodes[i]
#define WP_TRIANGLE(i) triangles[i]
#define WP_INSTANCE(i) instances[i]
#define WP_PLANE(i) planes[i]
#define WP_MATERIAL(i) materials[i]
#define WP_LIGHT(i) lights[i]
#define WP_TRIANGLE_SHADING(i) triangleShading[i]
#define WP_TEXTURE(i) textures[i]
#define WP_TEXEL_WORD(i) texels[i]
#endif

// BVH node with the bounds of both children (Aila & Laine layout), 64 bytes. A child with
// count 0 is an interior node whose index is `index`; a child with count > 0 is a leaf
// holding primitives [index, index + count). An empty child has min > max and count 0 and
// index WP_INVALID. Bottom-level leaves hold triangles, the top level holds instances.
WP_STRUCT(BvhNode)
  vec4 leftMin;   // xyz: bounds min; w: asFloat(left index)
  vec4 leftMax;   // xyz: bounds max; w: asFloat(left count)
  vec4 rightMin;  // xyz; w: asFloat(right index)
  vec4 rightMax;  // xyz; w: asFloat(right count)
WP_STRUCT_END(BvhNode)

// Triangle in object space, stored in BVH leaf order: 64 bytes.
WP_STRUCT(GpuTriangle)
  vec4 v0;     // xyz: vertex 0
  vec4 edge1;  // xyz: v1 - v0
  vec4 edge2;  // xyz: v2 - v0
  uvec4 info;  // x: material index, y: emitter ordinal within its mesh or WP_INVALID
WP_STRUCT_END(GpuTriangle)

// Shading data of the GpuTriangle at the same index, read only when shading a hit (and by
// light samples, for the emissive texture), so the traversal's triangle records stay 64
// bytes: 128 bytes.
WP_STRUCT(GpuTriangleShading)
  vec4 normal0;  // xyz: object-space unit vertex normal (glTF NORMAL) at vertex 0, w: u0;
  vec4 normal1;  // all three normals zero: shade with the geometric normal (flat); w: u1
  vec4 normal2;  // w: u2
  vec4 v;        // xyz: TEXCOORD_0's v at the three vertices, w: 1 if the mesh has TEXCOORD_0
  uvec4 colors;  // xyz: COLOR_0 at the three vertices as RGBA8 (linear, r in the low byte);
                 // white without COLOR_0
  vec4 tangent0;  // xyz: object-space unit glTF TANGENT at vertex 0, w: bitangent sign (+-1);
  vec4 tangent1;  // all zero without TANGENT (the frame then comes from the uv gradient)
  vec4 tangent2;
WP_STRUCT_END(GpuTriangleShading)

// GpuTexture.info.w bits: wrap modes (2 bits each, s then t) and flags.
#define WP_TEXTURE_WRAP_REPEAT 0u
#define WP_TEXTURE_WRAP_CLAMP 1u
#define WP_TEXTURE_WRAP_MIRROR 2u
#define WP_TEXTURE_SRGB 16u     // texels are sRGB-encoded colour (decoded before filtering)
#define WP_TEXTURE_NEAREST 32u  // nearest texel instead of bilinear

// A texture's header: 16 bytes.
WP_STRUCT(GpuTexture)
  uvec4 info;  // x: first texel in the texel buffer, y: width, z: height, w: wrap and flags
WP_STRUCT_END(GpuTexture)

// One placed object: a mesh (bottom-level BVH) or an analytic sphere, 64 bytes.
WP_STRUCT(GpuInstance)
  vec4 worldToObject0;  // rows of the 3x4 world-to-object matrix (at shutter open if it moves)
  vec4 worldToObject1;
  vec4 worldToObject2;
  uvec4 info;  // x: WP_INSTANCE_*, y: BVH root node (mesh) or material (sphere),
               // z: first light index of this instance's emissive triangles (WP_INVALID:
               // none sampled), w: WP_INVALID if it stands still, else the index of its
               // two motion keys in the instance buffer (motion.h)
WP_STRUCT_END(GpuInstance)

// A moving instance's placement at shutter open and at shutter close is kept as two motion
// keys, stored after the placed instances in the instance buffer in GpuInstance records (so
// no binding is added): a TRS key holds the translation in worldToObject0.xyz, the rotation
// quaternion (x, y, z, w) in worldToObject1 and the scale in worldToObject2.xyz; a matrix key
// (a transform with shear) the rows of the 3x4 object-to-world matrix. info.x says which.
#define WP_MOTION_KEY_TRS 0u
#define WP_MOTION_KEY_MATRIX 1u

// Infinite plane dot(n, p) = d, 32 bytes.
WP_STRUCT(GpuPlane)
  vec4 normalDistance;  // xyz: unit normal, w: d
  uvec4 info;           // x: material index
WP_STRUCT_END(GpuPlane)

// GpuMaterial.info.x: which BSDF the material has.
#define WP_MATERIAL_GLTF 0u     // glTF metallic-roughness mixture (shaders/common/material.h)
#define WP_MATERIAL_LAMBERT 1u  // ideal diffuse (extras.wavepath.bsdf = "lambert")
#define WP_MATERIAL_GLTF_DISNEY_DIFFUSE 2u  // the mixture with the seed's Disney diffuse base
                                            // (extras.wavepath.diffuse = "disney")

// A surface material, 112 bytes.
WP_STRUCT(GpuMaterial)
  vec4 baseColor;    // rgb: linear base colour (albedo, metal F0, glass tint), a: alpha
  vec4 emission;     // rgb: emitted radiance (factor * strength); w: 1 if double-sided, else 0
  vec4 surface;      // x: metallic, y: perceptual roughness, z: ior, w: transmission
  vec4 attenuation;  // rgb: KHR_materials_volume attenuationColor, w: attenuationDistance
                     // (WP_FLT_MAX: no absorption)
  uvec4 info;        // x: WP_MATERIAL_*, y: base colour texture, z: metallic-roughness
                     // texture, w: normal texture (WP_INVALID: none)
  vec4 normalMap;    // x: the normal texture's scale, yzw: unused
  uvec4 emissiveMap;  // x: emissive texture (sRGB, multiplies `emission`; WP_INVALID: none),
                      // yzw: unused
WP_STRUCT_END(GpuMaterial)

// GpuLight.info.y: what the light is, in the low bits, and its flags above them.
#define WP_LIGHT_TRIANGLE 0u     // an emissive triangle (an area light)
#define WP_LIGHT_POINT 1u        // KHR_lights_punctual: a point
#define WP_LIGHT_SPOT 2u         // a point emitting into a cone
#define WP_LIGHT_DIRECTIONAL 3u  // a distant light (a sun) from one direction
#define WP_LIGHT_KIND_MASK 3u
#define WP_LIGHT_DOUBLE_SIDED 4u  // a triangle that emits on both sides (else the front only,
                                  // the side of cross(edge1, edge2))

// One light of next event estimation, with its alias-table entry for power-proportional
// selection (pick i = min(floor(u * n), n - 1), keep i if fract(u * n) < threshold, else take
// alias): an emissive triangle in world space, or a glTF punctual light, whose position and
// direction may move while the shutter is open. Read it through the accessors of lights.h.
// 96 bytes.
WP_STRUCT(GpuLight)
  vec4 v0;        // triangle: xyz vertex 0, w area; punctual: xyz position at shutter open,
                  // w cos of a spot's outer cone angle
  vec4 edge1;     // triangle: xyz v1 - v0; punctual: xyz the unit direction it points (spot,
                  // directional) at shutter open; w: probability of selecting this light
  vec4 edge2;     // triangle: xyz v2 - v0; punctual: xyz position at shutter close;
                  // w: alias threshold in [0, 1]
  vec4 emission;  // rgb: radiance (triangle), radiant intensity in W/sr (point, spot) or
                  // irradiance in W/m^2 (directional); w: luminance of the triangle's mean
                  // emitted radiance (texture included), or of the intensity or irradiance
  vec4 motion;    // punctual: xyz the direction at shutter close, w cos of a spot's inner
                  // cone angle; unused by triangles
  uvec4 info;     // x: alias index, y: WP_LIGHT_* kind | WP_LIGHT_DOUBLE_SIDED, z: the
                  // triangle's GpuTriangleShading (its vertices in the order of v0, edge1,
                  // edge2), w: its emissive texture (WP_INVALID: none)
WP_STRUCT_END(GpuLight)

// Settings of the sky, 32 bytes of vec4/uvec4 for a uniform or constant buffer.
WP_STRUCT(GpuEnvironment)
  vec4 transform;  // x: intensity (radiance multiplier); y: rotation about +y, radians;
                   // z: probability that next event estimation samples the sky rather than
                   // the emissive triangles; w: unused
  uvec4 size;      // x: width, y: height (texels); z, w: unused
WP_STRUCT_END(GpuEnvironment)

// Per-frame settings, a read-only storage buffer (OpenCL: a constant argument).
WP_STRUCT(RenderParams)
  ThinLens camera;      // optics and placement of the camera (thin_lens.h)
  GpuEnvironment sky;   // the sky seen by rays that leave the scene (environment.h)
  uvec4 image;          // x: width, y: height, z: pixels traced (of region), w: seed
  uvec4 mode;           // x: max bounces, y: WP_MODE_*, z: Russian roulette start bounce,
                        // w: number of lights (triangles and punctual)
  uvec4 counts;         // x: planes, y: top-level root node, z: instances, w: maxPaths
  uvec4 shading;        // x: WP_BSDF_* flags, y: asUint(contribution clamp; 0 = off),
                        // z: WP_LIGHT_SELECTION_*, w: number of punctual (delta) lights
  uvec4 region;         // the pixels traced (image.z of them, row-major): x, y: first column
                        // and row, z: width, w: height (the whole image unless --region, or
                        // a tile of it when it does not fit the device at once)
WP_STRUCT_END(RenderParams)

// One path waiting to be traced: 64 bytes.
WP_STRUCT(PathRay)
  vec4 origin;      // xyz; w: asFloat(path slot in this pass)
  vec4 direction;   // xyz: unit; w: solid-angle pdf of the BSDF sample (0: camera ray)
  vec4 throughput;  // rgb; w: the path's shutter time in [0, 1) (motion blur)
  uvec4 state;      // x: RNG state, y: bounce of the vertex this ray will hit, z, w: unused
WP_STRUCT_END(PathRay)

// Closest hit of the PathRay at the same queue position: 16 bytes.
WP_STRUCT(HitRecord)
  uvec4 hit;  // x: asUint(t) (WP_INVALID: miss), y: instance or plane index | WP_HIT_PLANE,
              // z: primitive (global triangle index), w: unused
WP_STRUCT_END(HitRecord)
#define WP_HIT_PLANE 0x80000000u

// Next-event-estimation shadow ray: 48 bytes.
WP_STRUCT(ShadowRay)
  vec4 origin;        // xyz; w: asFloat(path slot)
  vec4 direction;     // xyz: unit; w: distance to the light sample (exclusive)
  vec4 contribution;  // rgb: radiance added to the path if unoccluded; w: the path's shutter time
WP_STRUCT_END(ShadowRay)

// Queue sizes and indirect dispatch arguments, written on the GPU. Kernels address it as a
// flat uint array (atomics need a plain uint lvalue) through the word indices below.
WP_STRUCT(QueueCounters)
  uvec4 counts;           // x, y: ray queues 0 and 1; z, w: shadow queues of even/odd bounces
  uvec4 totals;           // x: extension rays traced this pass, y: shadow rays
  uvec4 extendDispatch;   // xyz: VkDispatchIndirectCommand for extend and shade
  uvec4 connectDispatch;  // xyz: VkDispatchIndirectCommand for connect
WP_STRUCT_END(QueueCounters)
#define WP_COUNTER_RAYS 0u            // + queue (0 or 1)
#define WP_COUNTER_SHADOW_RAYS 2u     // + bounce parity
#define WP_COUNTER_TOTAL_RAYS 4u
#define WP_COUNTER_TOTAL_SHADOW_RAYS 5u
#define WP_COUNTER_EXTEND_DISPATCH 8u
#define WP_COUNTER_CONNECT_DISPATCH 12u
#define WP_COUNTER_WORDS 16u

// Per-dispatch constants (Vulkan push constants, OpenCL kernel arguments). A pass traces
// `pathCount` paths: path slot i is pixel (firstPixel + i) % pixels of sample
// firstSample + (firstPixel + i) / pixels, so a pass may span several samples of a small
// image while every slot of one pixel is accumulated in sample order.
WP_STRUCT(PassConstants)
  uvec4 pass;  // x: firstPixel, y: firstSample, z: pathCount, w: bounce
WP_STRUCT_END(PassConstants)

WP_END

#endif
