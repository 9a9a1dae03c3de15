// Closest-hit and any-hit traversal of the two-level BVH: a top level over instances, one
// bottom level per mesh, then the planes. Buffers are described in binding_table.h.
#ifndef WP_TRAVERSE_H
#define WP_TRAVERSE_H

#include "alpha.h"
#include "binding_table.h"
#include "instance.h"
#include "intersect.h"
#include "motion.h"

// Each level is built no deeper than WP_BVH_MAX_DEPTH binary levels, so its 4-wide nodes
// (each at least one binary level below its parent) are no deeper either. A node visit pushes
// at most three children, and a bottom-level lane that already holds a postponed leaf pushes
// one more back, so a stack of this size serves either level of any tree
// (traversalStackEntries, wide_nodes.h, gives what a given tree needs).
#define WP_BVH_MAX_DEPTH 32u
#define WP_LEVEL_STACK_SIZE ((WP_BVH_WIDTH - 1u) * WP_BVH_MAX_DEPTH + 2u)
// Bottom-level leaves hold at most this many triangles (the packer builds them so): a leaf's
// count fits the bits above a stack entry's index (packEntry, layout.h).
#define WP_MAX_LEAF_TRIANGLES 4u
// A ray passes at most this many alpha-tested surfaces (MASK cut-outs or BLEND panes it
// goes through); the next one stops it. Real scenes stack far fewer, and it bounds the work
// of a ray that grazes a pile of coplanar leaves.
#define WP_MAX_ALPHA_LAYERS 64u

WP_BEGIN

// Each level's stack: an array of the invocation's own, declared where the level is walked
// and read and written through WP_STACK_READ and WP_STACK_WRITE. Vulkan keeps it in workgroup
// memory instead where the scene's stacks fit there (WP_STACKS_IN_WORKGROUP_MEMORY), entry i
// of every invocation of the workgroup side by side. lavapipe stores to an invocation's own
// array at an index that differs between lanes, inside a loop, lane by lane: it loads the
// slot, selects the lane's value or the one it loaded by the lane's mask, and stores that
// back. On a CPU that guesses such a load independent of the stores just before it (AMD's
// Zen 4) a wrong guess re-executes the pipeline, and the lanes' data decides whether the
// guess is wrong: the pushes took half of lavapipe's extend there. Workgroup memory is stored
// to with a branch per lane, no load: extend and connect half as long on Zen 4.
#define WP_STACK_DECLARE(stack) uint stack[WP_LEVEL_STACK_SIZE];
#ifdef WP_GLSL
shared uint topLevelStackInWorkgroup[WP_TOP_LEVEL_STACK_ENTRIES * WP_WORKGROUP_SIZE];
shared uint bottomLevelStackInWorkgroup[WP_BOTTOM_LEVEL_STACK_ENTRIES * WP_WORKGROUP_SIZE];
#define WP_STACK_IN_WORKGROUP(stack, i) stack##InWorkgroup[(i) * WP_WORKGROUP_SIZE + gl_LocalInvocationIndex]
#define WP_STACK_READ(stack, i) (WP_STACKS_IN_WORKGROUP_MEMORY ? WP_STACK_IN_WORKGROUP(stack, i) : stack[i])
#define WP_STACK_WRITE(stack, i, value)        \
  if (WP_STACKS_IN_WORKGROUP_MEMORY) {         \
    WP_STACK_IN_WORKGROUP(stack, i) = (value); \
  } else {                                     \
    stack[i] = (value);                        \
  }
#else
#ifndef WP_NOTE_STACK_ENTRY
#define WP_NOTE_STACK_ENTRY(stack, i)  // C++ keeps count (prelude_cpp.h)
#endif
#define WP_STACK_READ(stack, i) stack[i]
#define WP_STACK_WRITE(stack, i, value) \
  stack[i] = (value);                   \
  WP_NOTE_STACK_ENTRY(stack, i);
#endif

WP_STRUCT(Hit)
  float t;         // distance along the ray (tMax for a miss)
  uint instance;   // instance index, planeIndex | WP_HIT_PLANE, or WP_INVALID for a miss
  uint primitive;  // global triangle index; WP_INVALID for spheres and planes
  bool alphaTested;  // the triangle's material is MASK or BLEND (read where primitive is valid)
WP_STRUCT_END(Hit)

// The children of a node that a ray reaches before tMax, nearest first.
WP_STRUCT(ChildHits)
  // Each child's stack entry (packEntry): the reached children in the first `count`
  // components by the distance at which the ray enters them (ties by slot), then the missed
  // and empty slots.
  uvec4 nearestFirst;
  uint count;  // children reached: 0 to 4
WP_STRUCT_END(ChildHits)

// Puts the pairs (keyA, entryA), (keyB, entryB) in order of key, swapping only when B's key is
// smaller, so equal keys keep their order. A macro of selects: no branches, and the same
// statements in GLSL, OpenCL C and C++ (which differ in how a function writes its arguments).
#define WP_ORDER_PAIR(keyA, entryA, keyB, entryB) \
  {                                               \
    bool swap_ = (keyB) < (keyA);                 \
    float key_ = swap_ ? (keyB) : (keyA);         \
    (keyB) = swap_ ? (keyA) : (keyB);             \
    (keyA) = key_;                                \
    uint entry_ = swap_ ? (entryB) : (entryA);    \
    (entryB) = swap_ ? (entryA) : (entryB);       \
    (entryA) = entry_;                            \
  }

// The slab test of all four children at once, one vec4 per axis: a child is reached when
// the ray (invDir = rayInverseDirection(direction)) enters its box at some t in [0, tMax];
// then the children in order of entry distance, by an odd-even transposition network of
// four rounds over (distance, entry) pairs: six compare-and-swaps of selects, stable, so
// ties go by slot and the missed slots (distance WP_FLT_MAX) stay after the reached ones.
// It replaced ranking each slot against the other three (twelve comparisons with a tie
// rule each, and four conditional stack writes per slot): PoCL's extend 7% and lavapipe's
// 5% faster on the instanced scene, images bit-identical.
// Where work-items are threads, a visit that reaches at most one child (four in five of
// the instanced scene's bottom-level visits; one in five reaches two) skips the network
// and takes the reached child: PoCL's extend 16% faster. Where they are SIMD lanes the
// branch made lavapipe 2-8% slower (every lane pays for the network when one needs it),
// so it is not taken there. Both give the same order, so the same images.
WP_FN_INLINED ChildHits intersectChildren(BvhNode node, vec3 origin, vec3 invDir, float tMax) {
  vec4 x0 = (node.childMinX - origin.x) * invDir.x;
  vec4 x1 = (node.childMaxX - origin.x) * invDir.x;
  vec4 y0 = (node.childMinY - origin.y) * invDir.y;
  vec4 y1 = (node.childMaxY - origin.y) * invDir.y;
  vec4 z0 = (node.childMinZ - origin.z) * invDir.z;
  vec4 z1 = (node.childMaxZ - origin.z) * invDir.z;
  vec4 entry = max(max(min(x0, x1), min(y0, y1)), max(min(z0, z1), make_vec4(0.0f, 0.0f, 0.0f, 0.0f)));
  vec4 exit = min(min(max(x0, x1), max(y0, y1)), min(max(z0, z1), make_vec4(tMax, tMax, tMax, tMax))) *
              WP_SLAB_PADDING;
  // Empty slots are recognised by their index: the slab test would see their boxes as any.
  uvec4 index = node.childIndex;
  bool reached0 = entry.x <= exit.x && index.x != WP_INVALID;
  bool reached1 = entry.y <= exit.y && index.y != WP_INVALID;
  bool reached2 = entry.z <= exit.z && index.z != WP_INVALID;
  bool reached3 = entry.w <= exit.w && index.w != WP_INVALID;
  // Missed slots sort after every reached one: a reached child's entry is at most tMax.
  float k0 = reached0 ? entry.x : WP_FLT_MAX;
  float k1 = reached1 ? entry.y : WP_FLT_MAX;
  float k2 = reached2 ? entry.z : WP_FLT_MAX;
  float k3 = reached3 ? entry.w : WP_FLT_MAX;
  uint e0 = packEntry(index.x, node.childCount.x);
  uint e1 = packEntry(index.y, node.childCount.y);
  uint e2 = packEntry(index.z, node.childCount.z);
  uint e3 = packEntry(index.w, node.childCount.w);
  ChildHits c;
  c.count = (reached0 ? 1u : 0u) + (reached1 ? 1u : 0u) + (reached2 ? 1u : 0u) + (reached3 ? 1u : 0u);
#if WP_WORK_ITEMS_ARE_THREADS
  if (c.count <= 1u) {
    c.nearestFirst = make_uvec4(reached0 ? e0 : reached1 ? e1 : reached2 ? e2 : e3, e1, e2, e3);
    return c;
  }
#endif
  WP_ORDER_PAIR(k0, e0, k1, e1)
  WP_ORDER_PAIR(k2, e2, k3, e3)
  WP_ORDER_PAIR(k1, e1, k2, e2)
  WP_ORDER_PAIR(k0, e0, k1, e1)
  WP_ORDER_PAIR(k2, e2, k3, e3)
  WP_ORDER_PAIR(k1, e1, k2, e2)
  c.nearestFirst = make_uvec4(e0, e1, e2, e3);
  return c;
}

// Pushes the children of `hits` that are reached but not nearest onto `stack` at `sp`, the
// farthest deepest so the nearer ones pop first, and advances sp past them. A macro, not a
// function: GLSL would copy the whole stack in and out of a call.
#define WP_PUSH_FAR_CHILDREN(stack, sp, hits)                        \
  {                                                                  \
    if ((hits).count > 3u) {                                         \
      WP_STACK_WRITE(stack, (sp) + (hits).count - 4u, (hits).nearestFirst.w) \
    }                                                                \
    if ((hits).count > 2u) {                                         \
      WP_STACK_WRITE(stack, (sp) + (hits).count - 3u, (hits).nearestFirst.z) \
    }                                                                \
    if ((hits).count > 1u) {                                         \
      WP_STACK_WRITE(stack, (sp) + (hits).count - 2u, (hits).nearestFirst.y) \
      (sp) += (hits).count - 1u;                                     \
    }                                                                \
  }

// Where work-items are threads, starts fetching every child of `node` (a node's two cache
// lines; a leaf's first and last triangle) as soon as the node is read, before its slab test
// decides which the ray reaches: a CPU thread otherwise waits for each node's memory in turn
// (the first loads of a node and of a leaf's triangle took a quarter of PoCL's extend
// samples). Fetching only the children pushed for later, once the test had ranked them, made
// PoCL's extend 7% faster on the instanced scene; fetching all of them at once, the nearest
// included, 10% more (and connect 9%), though three in four of the fetches are for children
// the ray misses: the dependent loads are what a thread waits on, not the memory's bandwidth.
// SIMD lanes have no such instruction, and their gathers overlap anyway.
WP_FN_INLINED void prefetchChildren(WP_BUFFERS BvhNode node) {
#if WP_WORK_ITEMS_ARE_THREADS
  for (uint k = 0u; k < WP_BVH_WIDTH; ++k) {
    uint index = k == 0u ? node.childIndex.x : k == 1u ? node.childIndex.y : k == 2u ? node.childIndex.z : node.childIndex.w;
    uint count = k == 0u ? node.childCount.x : k == 1u ? node.childCount.y : k == 2u ? node.childCount.z : node.childCount.w;
    if (index == WP_INVALID) {
      continue;
    }
    if (count == 0u) {
      WP_PREFETCH(WP_LOAD(nodes, index).childMinX);
      WP_PREFETCH(WP_LOAD(nodes, index).childMaxZ);
    } else {
      WP_PREFETCH(WP_LOAD(triangles, index).v0);
      WP_PREFETCH(WP_LOAD(triangles, index + count - 1u).v0);
    }
  }
#endif
}

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

// The triangles of a bottom-level leaf entry of `instance`, with the ray in object space. The
// loop runs over the leaf's own count: most leaves hold two triangles (a mesh's quads), and a
// loop of fixed length WP_MAX_LEAF_TRIANGLES, which tested the first triangle again in the
// empty slots, spent half its triangle tests for nothing (PoCL's extend 3% and lavapipe's 4%
// slower on the instanced scene).
WP_FN_INLINED Hit intersectLeaf(WP_BUFFERS uint leaf, uint instance, vec3 o, vec3 d, Hit hit) {
  uint first = entryIndex(leaf);
  uint count = entryCount(leaf);
  for (uint k = 0u; k < count; ++k) {
    uint j = first + k;
    GpuTriangle tri = WP_LOAD(triangles, j);
    float t = intersectTriangle(o, d, triangleVertex0(tri), triangleEdge1(tri), triangleEdge2(tri), hit.t);
    if (t < hit.t) {
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
WP_FN_INLINED Hit traceBottomLevel(WP_BUFFERS uint root, uint instance, vec3 o, vec3 d, Hit hit, bool anyHit) {
  vec3 invDir = rayInverseDirection(d);
  WP_STACK_DECLARE(bottomLevelStack)
  uint sp = 0u;
  uint node = root;         // next interior node to visit, WP_INVALID: none
  uint leaf = WP_INVALID;  // leaf entry waiting to be intersected
  for (;;) {
    while (node != WP_INVALID) {
      BvhNode n = WP_LOAD(nodes, node);
      prefetchChildren(WP_BUFFERS_ARG n);
      ChildHits b = intersectChildren(n, o, invDir, hit.t);
      WP_PUSH_FAR_CHILDREN(bottomLevelStack, sp, b)
      node = WP_INVALID;
      if (b.count > 0u && entryCount(b.nearestFirst.x) == 0u) {
        node = b.nearestFirst.x;
      } else {
        if (b.count > 0u && leaf == WP_INVALID) {
          leaf = b.nearestFirst.x;
        } else if (b.count > 0u) {
          // This lane already holds a leaf (it waits for the others): keep the new one.
          WP_STACK_WRITE(bottomLevelStack, sp, b.nearestFirst.x)
          ++sp;
        }
        if (sp > 0u) {
          --sp;
          uint popped = WP_STACK_READ(bottomLevelStack, sp);
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
      uint popped = WP_STACK_READ(bottomLevelStack, sp);
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
WP_FN_INLINED Hit intersectInstance(WP_BUFFERS uint i, vec3 origin, vec3 direction, float time, Hit hit, bool anyHit) {
  GpuInstance inst = instanceAt(WP_BUFFERS_ARG i, time);
  vec3 o = pointToObject(inst, origin);
  vec3 d = directionToObject(inst, direction);
  if (WP_SCENE_SPHERES && instanceKind(inst) == WP_INSTANCE_SPHERE) {
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
// placed at normalized shutter time `time` (motion.h): the planes, then the top level, whose
// root `topLevel` is a stack entry (GpuScene::topLevelEntry): a node, or, where the top level
// holds one instance (most scenes without instancing: their meshes are baked into one), that
// instance's leaf, which the walk enters at once. The root node's box test that this skips
// only rejected early what the bottom level's root rejects too, so the hits are the same.
// lavapipe runs a loop's body once even where no lane enters it, so Vulkan compiles the walk
// out of such a scene's stages (WP_SCENE_INSTANCED false): its extend and connect 13-15%
// faster on the Cornell box. (PoCL, where the walk stays in the kernel, gains nothing
// measurable; with the walk compiled out, 6-7%.)
//
// The top level is walked like a bottom level (traceBottomLevel): each lane visits nodes
// until it holds an instance or has none left, and the instances are entered only once every
// lane of the subgroup holds one, so the lanes run their bottom levels together. In a loop
// whose every iteration was a node visit or an instance, the lanes that reached an instance
// ran their bottom-level traversals while the others waited at a node, one after another:
// lavapipe's extend on the instanced scene 21% and connect 27% faster without it (images
// bit-identical; where work-items are threads nothing waits, and PoCL's times are unchanged).
// Neither level nests a loop per child or per leaf, which made every lane pay for the deepest
// nesting any lane reached.
WP_FN Hit traceScene(WP_BUFFERS uint topLevel, uint planeCount, vec3 origin, vec3 direction,
                     float tMax, float time, bool anyHit) {
  Hit hit;
  hit.t = tMax;
  hit.instance = WP_INVALID;
  hit.primitive = WP_INVALID;
  hit.alphaTested = false;
  // Planes first: a near plane shortens every box test that follows. (Vulkan and OpenCL compile the
  // loop out of a scene without planes, WP_SCENE_PLANES: on lavapipe its body, a plane's fetch
  // and test, ran once for every ray.)
  if (WP_SCENE_PLANES) {
    hit = intersectPlanes(WP_BUFFERS_ARG planeCount, origin, direction, hit, anyHit);
    if (anyHit && hit.instance != WP_INVALID) {
      return hit;
    }
  }
  if (!WP_SCENE_INSTANCED) {
    return intersectInstance(WP_BUFFERS_ARG entryIndex(topLevel), origin, direction, time, hit, anyHit);
  }
  vec3 invDir = rayInverseDirection(direction);
  WP_STACK_DECLARE(topLevelStack)
  uint sp = 0u;
  // WP_INVALID once the stack is empty: its count bits are not 0, so it ends the node loop.
  uint entry = topLevel;
  for (;;) {
    while (entryCount(entry) == 0u) {
      ChildHits c = intersectChildren(WP_LOAD(nodes, entryIndex(entry)), origin, invDir, hit.t);
      WP_PUSH_FAR_CHILDREN(topLevelStack, sp, c)
      if (c.count > 0u) {
        entry = c.nearestFirst.x;
      } else if (sp > 0u) {
        --sp;
        entry = WP_STACK_READ(topLevelStack, sp);
      } else {
        entry = WP_INVALID;
      }
      if (WP_SUBGROUP_ALL(entryCount(entry) != 0u)) {
        break;
      }
    }
    if (entry == WP_INVALID) {
      break;
    }
    // A top-level leaf holds one instance (GpuScene packs one per leaf).
    hit = intersectInstance(WP_BUFFERS_ARG entryIndex(entry), origin, direction, time, hit, anyHit);
    if (anyHit && hit.instance != WP_INVALID) {
      return hit;
    }
    // Ends here when the stack is empty, rather than setting WP_INVALID for the test above as
    // the node loop's pop does: going round once more made lavapipe's extend 8% slower.
    if (sp == 0u) {
      break;
    }
    --sp;
    entry = WP_STACK_READ(topLevelStack, sp);
  }
  return hit;
}

// Whether `hit` is on a triangle whose material is MASK or BLEND (the flag the traversal
// took from the triangle it loaded anyway).
WP_FN bool hitIsAlphaTested(Hit hit) { return hit.primitive != WP_INVALID && hit.alphaTested; }

// The rest of traceCovered, for a ray whose first trace found an alpha-tested triangle:
// nearest surfaces first, each alpha-tested one decided (alpha.h) and stepped over by
// tracing on from just beyond it when the ray passes it.
WP_FN Hit traceThroughAlpha(WP_BUFFERS uint topLevel, uint planeCount, vec3 origin, vec3 direction, float tMax,
                            float time) {
  uint seed = coverageSeedOf(origin, direction);
  vec3 o = origin;
  float travelled = 0.0f;  // from origin to o
  bool searching = true;
  Hit hit;
  for (uint layer = 0u; searching; ++layer) {
    hit = traceScene(WP_BUFFERS_ARG topLevel, planeCount, o, direction, tMax - travelled, time, false);
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
WP_FN Hit traceCovered(WP_BUFFERS uint topLevel, uint planeCount, vec3 origin, vec3 direction, float tMax,
                       float time, bool anyHit) {
  Hit hit = traceScene(WP_BUFFERS_ARG topLevel, planeCount, origin, direction, tMax, time, anyHit);
  if (WP_SCENE_ALPHA_TESTED && hitIsAlphaTested(hit)) {
    hit = traceThroughAlpha(WP_BUFFERS_ARG topLevel, planeCount, origin, direction, tMax, time);
  }
  return hit;
}

// Closest hit at 0 < t < tMax at normalized shutter time `time` in [0, 1] (which only moving
// instances see), through the alpha cut-outs and panes the ray passes. Requires a non-zero
// direction and a scene packed by wp::packScene (topLevel = GpuScene::topLevelEntry(), planeCount =
// its number of planes).
WP_FN Hit traceClosest(WP_BUFFERS uint topLevel, uint planeCount, vec3 origin, vec3 direction, float tMax,
                       float time) {
  return traceCovered(WP_BUFFERS_ARG topLevel, planeCount, origin, direction, tMax, time, false);
}

// Whether anything stops a ray at 0 < t < tMax (shadow rays). Same requirements as
// traceClosest.
WP_FN bool traceAny(WP_BUFFERS uint topLevel, uint planeCount, vec3 origin, vec3 direction, float tMax,
                    float time) {
  return traceCovered(WP_BUFFERS_ARG topLevel, planeCount, origin, direction, tMax, time, true).instance !=
         WP_INVALID;
}

WP_END

#endif
