// Closest-hit and any-hit traversal of the two-level BVH: a top level over instances, one
// bottom level per mesh, then the planes. Buffers are described in layout.h.
#ifndef WP_TRAVERSE_H
#define WP_TRAVERSE_H

#include "intersect.h"
#include "layout.h"

// Scene elements are read through WP_NODE(i) and friends (layout.h): C++ and OpenCL index the
// arrays passed as the leading arguments, GLSL fetches from texel buffers it declares.
#if defined(__cplusplus) || defined(__OPENCL_VERSION__)
#define WP_SCENE_BUFFERS                                                               \
  WP_GLOBAL_PTR(BvhNode) nodes, WP_GLOBAL_PTR(GpuTriangle) triangles,                \
      WP_GLOBAL_PTR(GpuInstance) instances, WP_GLOBAL_PTR(GpuPlane) planes,
#define WP_SCENE_BUFFER_ARGS nodes, triangles, instances, planes,
#else
#define WP_SCENE_BUFFERS
#define WP_SCENE_BUFFER_ARGS
#endif

// Each level is built no deeper than WP_BVH_MAX_DEPTH, and a traversal pushes at most one
// node per level it descends, so one stack of this size serves both levels.
#define WP_BVH_MAX_DEPTH 32u
#define WP_TRAVERSAL_STACK_SIZE 64u

WP_BEGIN

WP_STRUCT(Hit)
  float t;         // distance along the ray (tMax for a miss)
  uint instance;   // instance index, planeIndex | WP_HIT_PLANE, or WP_INVALID for a miss
  uint primitive;  // global triangle index; WP_INVALID for spheres and planes
WP_STRUCT_END(Hit)

// The children of a node that the ray reaches before tMax, the nearer one first.
WP_STRUCT(ChildHits)
  uvec4 children;  // x, y: index of the first and second child reached; z, w: their leaf
                   // counts (0: interior node)
  float secondEntry;  // entry distance of the second child, re-checked after the first
  uint count;         // children reached: 0, 1 or 2
WP_STRUCT_END(ChildHits)

WP_FN ChildHits intersectChildren(BvhNode node, vec3 origin, vec3 invDir, float tMax) {
  vec2 l = intersectAabb(make_vec3(node.leftMin.x, node.leftMin.y, node.leftMin.z),
                         make_vec3(node.leftMax.x, node.leftMax.y, node.leftMax.z), origin, invDir, tMax);
  vec2 r = intersectAabb(make_vec3(node.rightMin.x, node.rightMin.y, node.rightMin.z),
                         make_vec3(node.rightMax.x, node.rightMax.y, node.rightMax.z), origin, invDir, tMax);
  uint leftIndex = asUint(node.leftMin.w);
  uint rightIndex = asUint(node.rightMin.w);
  // Empty children are recognised by their index: the slab test would see their inverted
  // boxes as huge ones.
  bool hitLeft = l.x <= l.y && leftIndex != WP_INVALID;
  bool hitRight = r.x <= r.y && rightIndex != WP_INVALID;
  bool rightFirst = hitRight && (!hitLeft || r.x < l.x);
  ChildHits c;
  c.children = rightFirst
      ? make_uvec4(rightIndex, leftIndex, asUint(node.rightMax.w), asUint(node.leftMax.w))
      : make_uvec4(leftIndex, rightIndex, asUint(node.leftMax.w), asUint(node.rightMax.w));
  c.secondEntry = rightFirst ? l.x : r.x;
  c.count = (hitLeft ? 1u : 0u) + (hitRight ? 1u : 0u);
  return c;
}

// World-to-object transform of a point and of a direction by an instance's 3x4 rows. The
// direction keeps its length, so object-space t values equal world-space ones.
WP_FN vec3 instanceRayOrigin(GpuInstance inst, vec3 p) {
  vec4 q = make_vec4(p.x, p.y, p.z, 1.0f);
  return make_vec3(dot(inst.worldToObject0, q), dot(inst.worldToObject1, q), dot(inst.worldToObject2, q));
}
WP_FN vec3 instanceRayDirection(GpuInstance inst, vec3 d) {
  vec4 q = make_vec4(d.x, d.y, d.z, 0.0f);
  return make_vec3(dot(inst.worldToObject0, q), dot(inst.worldToObject1, q), dot(inst.worldToObject2, q));
}

// Nearest hit at 0 < t < tMax, or with anyHit the first one found. Ordered traversal: the
// nearer child is visited first and the farther pushed; leaf children are intersected as
// soon as their parent is. The bottom level runs nested inside a top-level leaf and stacks
// its nodes above the top level's in the same stack.
WP_FN Hit traceScene(WP_SCENE_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction,
                     float tMax, bool anyHit) {
  Hit hit;
  hit.t = tMax;
  hit.instance = WP_INVALID;
  hit.primitive = WP_INVALID;
  // Planes first: a near plane shortens every box test that follows.
  for (uint i = 0u; i < planeCount; ++i) {
    vec4 plane = WP_PLANE(i).normalDistance;
    float t = intersectPlane(make_vec3(plane.x, plane.y, plane.z), plane.w, origin, direction, hit.t);
    if (t < hit.t) {
      hit.t = t;
      hit.instance = i | WP_HIT_PLANE;
      if (anyHit) {
        return hit;
      }
    }
  }

  vec3 invDir = rayInverseDirection(direction);
  uint stack[WP_TRAVERSAL_STACK_SIZE];
  uint sp = 0u;
  uint node = tlasRoot;
  for (;;) {
    ChildHits c = intersectChildren(WP_NODE(node), origin, invDir, hit.t);
    uint next = WP_INVALID;
    for (uint k = 0u; k < c.count; ++k) {
      uint index = k == 0u ? c.children.x : c.children.y;
      uint count = k == 0u ? c.children.z : c.children.w;
      if (count == 0u) {
        if (next == WP_INVALID) {
          next = index;
        } else {
          stack[sp] = index;
          ++sp;
        }
        continue;
      }
      if (k == 1u && c.secondEntry > hit.t) {
        continue;
      }
      for (uint i = index; i < index + count; ++i) {
        GpuInstance inst = WP_INSTANCE(i);
        vec3 o = instanceRayOrigin(inst, origin);
        vec3 d = instanceRayDirection(inst, direction);
        if (inst.info.x == WP_INSTANCE_SPHERE) {
          float t = intersectUnitSphere(o, d, hit.t);
          if (t < hit.t) {
            hit.t = t;
            hit.instance = i;
            hit.primitive = WP_INVALID;
            if (anyHit) {
              return hit;
            }
          }
          continue;
        }
        vec3 objectInvDir = rayInverseDirection(d);
        uint stackBase = sp;
        uint blasNode = inst.info.y;
        for (;;) {
          ChildHits b = intersectChildren(WP_NODE(blasNode), o, objectInvDir, hit.t);
          uint blasNext = WP_INVALID;
          for (uint m = 0u; m < b.count; ++m) {
            uint first = m == 0u ? b.children.x : b.children.y;
            uint triangleCount = m == 0u ? b.children.z : b.children.w;
            if (triangleCount == 0u) {
              if (blasNext == WP_INVALID) {
                blasNext = first;
              } else {
                stack[sp] = first;
                ++sp;
              }
              continue;
            }
            if (m == 1u && b.secondEntry > hit.t) {
              continue;
            }
            for (uint j = first; j < first + triangleCount; ++j) {
              GpuTriangle tri = WP_TRIANGLE(j);
              float t = intersectTriangle(o, d, make_vec3(tri.v0.x, tri.v0.y, tri.v0.z),
                                          make_vec3(tri.edge1.x, tri.edge1.y, tri.edge1.z),
                                          make_vec3(tri.edge2.x, tri.edge2.y, tri.edge2.z), hit.t);
              if (t < hit.t) {
                hit.t = t;
                hit.instance = i;
                hit.primitive = j;
                if (anyHit) {
                  return hit;
                }
              }
            }
          }
          if (blasNext == WP_INVALID) {
            if (sp == stackBase) {
              break;
            }
            --sp;
            blasNext = stack[sp];
          }
          blasNode = blasNext;
        }
      }
    }
    if (next == WP_INVALID) {
      if (sp == 0u) {
        break;
      }
      --sp;
      next = stack[sp];
    }
    node = next;
  }
  return hit;
}

// Closest hit at 0 < t < tMax. Requires a non-zero direction and a scene packed by
// wp::packScene (tlasRoot = GpuScene::tlasRoot, planeCount = its number of planes).
WP_FN Hit traceClosest(WP_SCENE_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction, float tMax) {
  return traceScene(WP_SCENE_BUFFER_ARGS tlasRoot, planeCount, origin, direction, tMax, false);
}

// Whether anything lies at 0 < t < tMax (shadow rays). Same requirements as traceClosest.
WP_FN bool traceAny(WP_SCENE_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction, float tMax) {
  return traceScene(WP_SCENE_BUFFER_ARGS tlasRoot, planeCount, origin, direction, tMax, true).instance !=
         WP_INVALID;
}

WP_END

#endif
