// Stage 3: shade each hit (shadeStage in stages.h) and append continuations and shadow rays
// to the next queues, which compacts them.
//
// Shade classes: in a scene whose surfaces have both materials that need glTF's BRDF and
// materials that do not (ideal diffuse, unlit: materialShadeNeeds), the backend builds this
// stage twice and runs both in turn. WP_SHADE_CLASS_DIFFUSE, without the BRDF's code, runs
// over the whole ray queue: it shades the misses and its own hits and defers the others to
// the deferred shade queue (queues.h); WP_SHADE_CLASS_MICROFACET, specialized to the whole
// scene, shades those. lavapipe runs every line of a shader for a SIMD group whatever its
// lanes' materials, so a diffuse hit no longer pays for the BRDF (docs/performance.md). The
// results go to each path's own slot: the images are those of one pipeline.
//
// Appends are counted per workgroup, with one atomic per queue and workgroup, as OpenCL's
// shade does. lavapipe runs a dispatch's workgroups on all its threads at once: with an atomic
// per subgroup, the threads' appends interleaved every few entries at the queues' ends, where
// each store could find its line in the other core's cache; on this project's 2-core machines
// shade then gained nothing from its second thread (docs/performance.md). Per workgroup, each
// thread writes runs of up to 64 entries. The two barriers cost lavapipe a fifth to a quarter
// of shade's time on one thread (it runs the subgroups of a workgroup with barriers as
// coroutines), and win back more on two.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bindings.glsl"
#include "common/stages.h"

// This pipeline's shade class, and whether the scene has the other (the diffuse class then
// defers the hits it does not shade).
layout(constant_id = 9) const uint WP_SHADE_CLASS = WP_SHADE_CLASS_DIFFUSE;
layout(constant_id = 10) const bool WP_SHADE_SPLIT = false;

// Whether the hit at entry `i` of the bounce's ray queue needs glTF's BRDF.
bool needsMicrofacet(uint i) {
  HitRecord hit = hitsAt(i);
  return !hitIsMiss(hit) &&
         materialShadeNeeds(materialsAt(hitMaterial(hitInstanceField(hit), hitPrimitive(hit)))) != 0u;
}

// The counts of a subgroup's or a workgroup's appends to the three queues, packed into one
// word so that they are summed together (a subgroup reduction is a loop over the lanes on
// lavapipe): x the continuations, y the shadow rays, z the deferred hits, 10 bits each.
#if WP_WORKGROUP_SIZE > 1023
#error "a workgroup's appends to one queue must fit in 10 bits"
#endif
uint packAppendCounts(uvec3 counts) { return counts.x | (counts.y << 10u) | (counts.z << 20u); }
uvec3 unpackAppendCounts(uint packed) { return uvec3(packed & 1023u, (packed >> 10u) & 1023u, packed >> 20u); }

// What each subgroup of the workgroup appends (packed), then the workgroup's first entry in
// each queue.
shared uint subgroupAppends[WP_WORKGROUP_SIZE];
shared uvec3 workgroupFirstEntries;

// This subgroup's first entry in each queue (x `continuations`, y `shadows`, z `deferred`),
// given how many entries the subgroup appends to each (`subgroupCounts`, the same in all its
// invocations). Every invocation of the workgroup must call it: it holds the workgroup's
// barriers.
uvec3 subgroupFirstEntries(WorkQueue continuations, WorkQueue shadows, WorkQueue deferred, uvec3 subgroupCounts) {
  if (subgroupElect()) {
    subgroupAppends[gl_SubgroupID] = packAppendCounts(subgroupCounts);
  }
  barrier();
  // Each lane reads one subgroup's counts: the sums of those before this subgroup and of all.
  uint before = 0u;
  uint all = 0u;
  for (uint first = 0u; first < gl_NumSubgroups; first += gl_SubgroupSize) {
    uint s = first + gl_SubgroupInvocationID;
    uint counts = s < gl_NumSubgroups ? subgroupAppends[s] : 0u;
    before += subgroupAdd(s < gl_SubgroupID ? counts : 0u);
    all += subgroupAdd(counts);
  }
  uvec3 total = unpackAppendCounts(all);
  if (gl_LocalInvocationIndex == 0u) {
    workgroupFirstEntries.x = reserveQueueEntries(continuations, total.x);
    workgroupFirstEntries.y = reserveQueueEntries(shadows, total.y);
    workgroupFirstEntries.z = 0u;
    if (total.z > 0u) {
      // The deferred hits' pipeline is dispatched over what the first appended.
      workgroupFirstEntries.z = reserveQueueEntries(deferred, total.z);
      atomicMax(counters[WP_COUNTER_DEFERRED_SHADE_DISPATCH], dispatchGroups(workgroupFirstEntries.z + total.z));
      counters[WP_COUNTER_DEFERRED_SHADE_DISPATCH + 1u] = 1u;  // every workgroup that appends writes the same
      counters[WP_COUNTER_DEFERRED_SHADE_DISPATCH + 2u] = 1u;
    }
  }
  barrier();
  return workgroupFirstEntries + unpackAppendCounts(before);
}

void main() {
  RenderParams params = renderParams();
  WorkQueue continuations = continuationQueue(params, pc);
  WorkQueue shadows = shadowQueue(pc.bounce);
  WorkQueue deferred = deferredShadeQueue();
  uint i = gl_GlobalInvocationID.x;
  bool shades;
  bool defers = false;
  if (WP_SHADE_CLASS == WP_SHADE_CLASS_DIFFUSE) {
    shades = i < queueSize(rayQueue(pc.bounce, params.maxPaths));
    if (WP_SHADE_SPLIT && shades) {
      defers = needsMicrofacet(i);
      shades = !defers;
    }
  } else {
    shades = i < queueSize(deferred);
    if (shades) {
      i = deferredHitsAt(queueEntry(deferred, i));
    }
  }
  ShadeResult r;
  r.flags = 0u;
  if (shades) {
    r = shadeStage(params, pc, i);
  }
  bool extends = (r.flags & WP_SHADE_EXTEND) != 0u;
  bool castsShadow = (r.flags & WP_SHADE_SHADOW) != 0u;
  uvec4 extendBallot = subgroupBallot(extends);
  uvec4 shadowBallot = subgroupBallot(castsShadow);
  uvec4 deferBallot = subgroupBallot(defers);
  uvec3 counts = uvec3(subgroupBallotBitCount(extendBallot), subgroupBallotBitCount(shadowBallot),
                       subgroupBallotBitCount(deferBallot));
  uvec3 first = subgroupFirstEntries(continuations, shadows, deferred, counts);
  if (extends) {
    rays[queueEntry(continuations, first.x + subgroupBallotExclusiveBitCount(extendBallot))] = r.next;
  }
  if (castsShadow) {
    shadowRays[queueEntry(shadows, first.y + subgroupBallotExclusiveBitCount(shadowBallot))] = r.shadow;
  }
  if (defers) {
    deferredHits[queueEntry(deferred, first.z + subgroupBallotExclusiveBitCount(deferBallot))] = i;
  }
}
