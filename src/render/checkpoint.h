// A render's state on disk, to resume it after an interruption: what it renders (identity,
// samples, region), how far it got, and the per-pixel sums so far.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "render/backend.h"
#include "render/render_identity.h"
#include "render/settings.h"

namespace wp {

// The file format (its "format" line); a reader refuses a newer one rather than misread it.
inline constexpr int kCheckpointFormat = 1;

struct Checkpoint {
  RenderIdentity identity;
  uint32_t samplesPerPixel = 0;
  uint32_t firstSample = 0, endSample = 0;  // the render's samples [firstSample, endSample)
  PixelRegion region;                       // the pixels rendered (never empty here)
  uint64_t pathsDone = 0;                   // WavefrontRenderer::pathsDone()
  std::string device;                       // backend and device that traced the paths
  Accumulation accumulation;                // one entry per pixel of the region, row-major
};

// Writes `checkpoint` to `path` atomically (the file is the previous checkpoint or this one,
// whole, even after a crash). Format: a text header of "key value" lines (wavepath
// checkpoint, format, scene-hash, settings, spp, samples, region, paths-done, device, one
// "layer NAME TYPE COUNT" line per layer, end), the layers' little-endian floats in the
// order listed (radiance.sum, radiance.sumSquares, albedo.sum, depth.sum, normal.sum,
// samples, stopped; TYPE f32x3 or f32), then the XXH3-64 of everything before it (8 bytes, little-endian). New
// per-pixel layers join as more layer lines.
void writeCheckpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);

// Reads a checkpoint; throws a one-line wp::Error naming the file when it is missing, not a
// checkpoint, of a newer format, truncated or damaged (checksum), or inconsistent.
Checkpoint readCheckpoint(const std::filesystem::path& path);

}  // namespace wp
