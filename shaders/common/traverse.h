// Closest-hit and any-hit traversal of the two-level BVH: a top level over instances, one
// bottom level per mesh, then the planes. Buffers are described in binding_table.h.
#ifndef WP_TRAVERSE_H
#define WP_TRAVERSE_H

#include "alpha.h"
#include "binding_table.h"
#include "instance.h"
#include "intersect.h"
#include "motion.h"

// Each level is built no deeper than WP_BVH_MAX_DEPTH, and its traversal pushes at most one
// entry per level it descends (plus two while a bottom-level lane holds a postponed leaf),
// so a stack of this size serves either level.
#define WP_BVH_MAX_DEPTH 32u
#define WP_LEVEL_STACK_SIZE 34u
// Bottom-level leaves hold at most this many triangles (the packer builds them so), which
// lets the traversal test a leaf with a loop of fixed length.
#define WP_MAX_LEAF_TRIANGLES 4u
// Stack entries pack a node or leaf index with a leaf's primitive count above it.
#define WP_ENTRY_COUNT_SHIFT 29u
#define WP_ENTRY_INDEX_MASK 0x1fffffffu
// A ray passes at most this many alpha-tested surfaces (MASK cut-outs or BLEND panes it
// goes through); the next one stops it. Real scenes stack far fewer, and it bounds the work
// of a ray that grazes a pile of coplanar leaves.
#define WP_MAX_ALPHA_LAYERS 64u

WP_BEGIN

WP_STRUCT(Hit)
  float t;         // distance along the ray (tMax for a miss)
  uint instance;   // instance index, planeIndex | WP_HIT_PLANE, or WP_INVALID for a miss
  uint primitive;  // global triangle index; WP_INVALID for spheres and planes
  bool alphaTested;  // the triangle's material is MASK or BLEND (read where primitive is valid)
WP_STRUCT_END(Hit)

// The children of a node that the ray reaches before tMax, the nearer one first.
WP_STRUCT(ChildHits)
  uvec4 children;  // read by the accessors below (one vector: PoCL selects it in one go)
  uint count;      // children reached: 0, 1 or 2
WP_STRUCT_END(ChildHits)
// The index of the first and second child reached, and their leaf counts (0: interior node).
WP_FN uint nearChild(ChildHits c) { return c.children.x; }
WP_FN uint farChild(ChildHits c) { return c.children.y; }
WP_FN uint nearChildCount(ChildHits c) { return c.children.z; }
WP_FN uint farChildCount(ChildHits c) { return c.children.w; }

WP_FN ChildHits intersectChildren(BvhNode node, vec3 origin, vec3 invDir, float tMax) {
  vec2 l = intersectAabb(nodeLeftMin(node), nodeLeftMax(node), origin, invDir, tMax);
  vec2 r = intersectAabb(nodeRightMin(node), nodeRightMax(node), origin, invDir, tMax);
  uint leftIndex = nodeLeftIndex(node);
  uint rightIndex = nodeRightIndex(node);
  // Empty children are recognised by their index: the slab test would see their inverted
  // boxes as huge ones.
  bool hitLeft = l.x <= l.y && leftIndex != WP_INVALID;
  bool hitRight = r.x <= r.y && rightIndex != WP_INVALID;
  bool rightFirst = hitRight && (!hitLeft || r.x < l.x);
  ChildHits c;
  c.children = rightFirst
      ? make_uvec4(rightIndex, leftIndex, nodeRightCount(node), nodeLeftCount(node))
      : make_uvec4(leftIndex, rightIndex, nodeLeftCount(node), nodeRightCount(node));
  c.count = (hitLeft ? 1u : 0u) + (hitRight ? 1u : 0u);
  return c;
}

// A traversal stack entry: a node (count 0) or a leaf of `count` primitives at `index`.
WP_FN uint packEntry(uint index, uint count) { return index | (count << WP_ENTRY_COUNT_SHIFT); }
WP_FN uint entryIndex(uint entry) { return entry & WP_ENTRY_INDEX_MASK; }
WP_FN uint entryCount(uint entry) { return entry >> WP_ENTRY_COUNT_SHIFT; }

// The planes that `hit` does not already hide, nearest first found; with anyHit it returns at
// the first.
WP_FN Hit intersectPlanes(WP_BUFFERS uint planeCount, vec3 origin, vec3 direction, Hit hit, bool anyHit) {
  for (uint i = 0u; i < planeCount; ++i) {
    GpuPlane plane = WP_LOAD(planes, i);
    float t = intersectPlane(planeNormal(plane), planeDistance(plane), origin, direction, hit.t);
    if (t < hit.t) {
      hit.t = t;
      hit.instance = i | WP_HIT_PLANE;
      if (anyHit) {
        return hit;
      }
    }
  }
  return hit;
}

// The triangles of a bottom-level leaf entry of `instance`, with the ray in object space: a
// loop of fixed length WP_MAX_LEAF_TRIANGLES that the compiler unrolls (the slots past the
// leaf's count test its first triangle again and are ignored).
WP_FN Hit intersectLeaf(WP_BUFFERS uint leaf, uint instance, vec3 o, vec3 d, Hit hit) {
  uint first = entryIndex(leaf);
  uint count = entryCount(leaf);
  for (uint k = 0u; k < WP_MAX_LEAF_TRIANGLES; ++k) {
    uint j = first + (k < count ? k : 0u);
    GpuTriangle tri = WP_LOAD(triangles, j);
    float t = intersectTriangle(o, d, triangleVertex0(tri), triangleEdge1(tri), triangleEdge2(tri), hit.t);
    if (k < count && t < hit.t) {
      hit.t = t;
      hit.instance = instance;
      hit.primitive = j;
      hit.alphaTested = triangleAlphaTested(tri);
    }
  }
  return hit;
}

// The bottom-level BVH at `root` of mesh instance `instance`, with the ray (o, d) in object
// space; with anyHit it returns at the first hit. Interior nodes are walked until this lane
// holds a leaf, and the leaf is postponed until every lane of the subgroup holds one, so
// node visits and leaf tests run in separate SIMD iterations (Aila & Laine 2009,
// "while-while" with postponed leaves).
WP_FN Hit traceBottomLevel(WP_BUFFERS uint root, uint instance, vec3 o, vec3 d, Hit hit, bool anyHit) {
  vec3 invDir = rayInverseDirection(d);
  uint stack[WP_LEVEL_STACK_SIZE];
  uint sp = 0u;
  uint node = root;         // next interior node to visit, WP_INVALID: none
  uint leaf = WP_INVALID;  // leaf entry waiting to be intersected
  for (;;) {
    while (node != WP_INVALID) {
      ChildHits b = intersectChildren(WP_LOAD(nodes, node), o, invDir, hit.t);
      uint nearEntry = packEntry(nearChild(b), nearChildCount(b));
      if (b.count == 2u) {
        stack[sp] = packEntry(farChild(b), farChildCount(b));
        ++sp;
      }
      node = WP_INVALID;
      if (b.count > 0u && nearChildCount(b) == 0u) {
        node = nearChild(b);
      } else {
        if (b.count > 0u && leaf == WP_INVALID) {
          leaf = nearEntry;
        } else if (b.count > 0u) {
          // This lane already holds a leaf (it waits for the others): keep the new one.
          stack[sp] = nearEntry;
          ++sp;
        }
        if (sp > 0u) {
          --sp;
          uint popped = stack[sp];
          if (entryCount(popped) == 0u) {
            node = popped;
          } else if (leaf == WP_INVALID) {
            leaf = popped;
          } else {
            // Keep it for after the leaf in hand.
            ++sp;
          }
        }
      }
      if (WP_SUBGROUP_ALL(leaf != WP_INVALID || node == WP_INVALID)) {
        break;
      }
    }
    if (leaf != WP_INVALID) {
      hit = intersectLeaf(WP_BUFFERS_ARG leaf, instance, o, d, hit);
      leaf = WP_INVALID;
      if (anyHit && hit.instance != WP_INVALID) {
        return hit;
      }
    }
    if (node == WP_INVALID) {
      if (sp == 0u) {
        break;
      }
      --sp;
      uint popped = stack[sp];
      if (entryCount(popped) == 0u) {
        node = popped;
      } else {
        leaf = popped;
      }
    }
  }
  return hit;
}

// Instance `i`, placed at normalized shutter time `time`: its unit sphere, or its mesh's
// bottom level, with the ray taken to object space.
WP_FN Hit intersectInstance(WP_BUFFERS uint i, vec3 origin, vec3 direction, float time, Hit hit, bool anyHit) {
  GpuInstance inst = instanceAt(WP_BUFFERS_ARG i, time);
  vec3 o = pointToObject(inst, origin);
  vec3 d = directionToObject(inst, direction);
  if (instanceKind(inst) == WP_INSTANCE_SPHERE) {
    float t = intersectUnitSphere(o, d, hit.t);
    if (t < hit.t) {
      hit.t = t;
      hit.instance = i;
      hit.primitive = WP_INVALID;
    }
    return hit;
  }
  return traceBottomLevel(WP_BUFFERS_ARG instanceBvhRoot(inst), i, o, d, hit, anyHit);
}

// Nearest hit at 0 < t < tMax, or with anyHit the first one found, with moving instances
// placed at normalized shutter time `time` (motion.h): the planes, then the top level.
//
// Each level is one flat loop over stack entries. An iteration either tests a node's two
// children (the nearer becomes the next entry, the farther is pushed) or intersects one leaf
// (for the top level an instance, intersectInstance; for a bottom level a few triangles,
// intersectLeaf). Flat loops matter on SIMD implementations that run divergent branches
// under masks (lavapipe, and GPUs): nested loops per child and per leaf made every lane pay
// for the deepest nesting any lane reached, and a node visit cost as much as ten triangle
// tests.
WP_FN Hit traceScene(WP_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction,
                     float tMax, float time, bool anyHit) {
  Hit hit;
  hit.t = tMax;
  hit.instance = WP_INVALID;
  hit.primitive = WP_INVALID;
  hit.alphaTested = false;
  // Planes first: a near plane shortens every box test that follows.
  hit = intersectPlanes(WP_BUFFERS_ARG planeCount, origin, direction, hit, anyHit);
  if (anyHit && hit.instance != WP_INVALID) {
    return hit;
  }
  vec3 invDir = rayInverseDirection(direction);
  uint stack[WP_LEVEL_STACK_SIZE];
  uint sp = 0u;
  uint entry = packEntry(tlasRoot, 0u);
  for (;;) {
    if (entryCount(entry) == 0u) {
      ChildHits c = intersectChildren(WP_LOAD(nodes, entryIndex(entry)), origin, invDir, hit.t);
      if (c.count == 2u) {
        stack[sp] = packEntry(farChild(c), farChildCount(c));
        ++sp;
      }
      if (c.count > 0u) {
        entry = packEntry(nearChild(c), nearChildCount(c));
        continue;
      }
    } else {
      // A top-level leaf holds one instance (GpuScene packs one per leaf).
      hit = intersectInstance(WP_BUFFERS_ARG entryIndex(entry), origin, direction, time, hit, anyHit);
      if (anyHit && hit.instance != WP_INVALID) {
        return hit;
      }
    }
    if (sp == 0u) {
      break;
    }
    --sp;
    entry = stack[sp];
  }
  return hit;
}

// Whether `hit` is on a triangle whose material is MASK or BLEND (the flag the traversal
// took from the triangle it loaded anyway).
WP_FN bool hitIsAlphaTested(Hit hit) { return hit.primitive != WP_INVALID && hit.alphaTested; }

// The rest of traceCovered, for a ray whose first trace found an alpha-tested triangle:
// nearest surfaces first, each alpha-tested one decided (alpha.h) and stepped over by
// tracing on from just beyond it when the ray passes it.
WP_FN Hit traceThroughAlpha(WP_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction, float tMax,
                            float time) {
  uint seed = coverageSeedOf(origin, direction);
  vec3 o = origin;
  float travelled = 0.0f;  // from origin to o
  bool searching = true;
  Hit hit;
  for (uint layer = 0u; searching; ++layer) {
    hit = traceScene(WP_BUFFERS_ARG tlasRoot, planeCount, o, direction, tMax - travelled, time, false);
    hit.t += travelled;
    searching = false;
    if (layer < WP_MAX_ALPHA_LAYERS && hitIsAlphaTested(hit)) {
      GpuTriangle tri = WP_LOAD(triangles, hit.primitive);
      GpuInstance inst = instanceAt(WP_BUFFERS_ARG hit.instance, time);
      vec3 p = o + direction * (hit.t - travelled);
      if (!triangleCovers(WP_BUFFERS_ARG tri, hit.primitive, hit.instance, pointToObject(inst, p), seed)) {
        o = offsetRayOrigin(p, normalToWorld(inst, cross(triangleEdge1(tri), triangleEdge2(tri))), direction);
        travelled = hit.t;
        searching = true;
      }
    }
  }
  return hit;
}

// traceScene, with alpha (alpha.h): the nearest surface that stops the ray (with anyHit, any
// one), skipping the alpha-tested triangles it passes. The traversal itself knows nothing of
// alpha, and a ray that meets no alpha-tested triangle is traced once, as before alpha
// existed: only one that does is traced again, nearest-first, by traceThroughAlpha (with
// anyHit too, since a surface nearer than the one found may stop the ray). A loop around
// the traversal, or the alpha test inside it, made opaque scenes trace a third slower on
// lavapipe, and even this second, never-taken traversal (Mesa inlines both) cost 11% of
// lavapipe's samples/s: so Vulkan builds the tracing stages of a scene without
// alpha-tested triangles with WP_SCENE_ALPHA_TESTED false (a specialization constant,
// prelude_glsl.h), where the step compiles away. Every decision comes from coverageSeedOf
// of the ray.
WP_FN Hit traceCovered(WP_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction, float tMax,
                       float time, bool anyHit) {
  Hit hit = traceScene(WP_BUFFERS_ARG tlasRoot, planeCount, origin, direction, tMax, time, anyHit);
  if (WP_SCENE_ALPHA_TESTED && hitIsAlphaTested(hit)) {
    hit = traceThroughAlpha(WP_BUFFERS_ARG tlasRoot, planeCount, origin, direction, tMax, time);
  }
  return hit;
}

// Closest hit at 0 < t < tMax at normalized shutter time `time` in [0, 1] (which only moving
// instances see), through the alpha cut-outs and panes the ray passes. Requires a non-zero
// direction and a scene packed by wp::packScene (tlasRoot = GpuScene::tlasRoot, planeCount =
// its number of planes).
WP_FN Hit traceClosest(WP_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction, float tMax,
                       float time) {
  return traceCovered(WP_BUFFERS_ARG tlasRoot, planeCount, origin, direction, tMax, time, false);
}

// Whether anything stops a ray at 0 < t < tMax (shadow rays). Same requirements as
// traceClosest.
WP_FN bool traceAny(WP_BUFFERS uint tlasRoot, uint planeCount, vec3 origin, vec3 direction, float tMax,
                    float time) {
  return traceCovered(WP_BUFFERS_ARG tlasRoot, planeCount, origin, direction, tMax, time, true).instance !=
         WP_INVALID;
}

WP_END

#endif
