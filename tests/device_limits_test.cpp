// Device buffers of both backends: what they copy in, and how renders meet the device's
// limits: an image too large for one buffer is rendered in tiles, identical to one render,
// and what cannot be split is one error line. WAVEPATH_MAX_BUFFER_BYTES lowers the limits the
// backends believe, so small images take the paths that 8192x8192 takes on lavapipe.
#include <gtest/gtest.h>

#include <array>

#include "backend/opencl/cl_check.h"
#include "backend/opencl/opencl_buffer.h"
#include "backend/opencl/opencl_context.h"
#include "image/image_io.h"
#include "render/wavefront.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

namespace fs = std::filesystem;

TEST(OpenClBuffer, ASourceSmallerThanThePlaceholderIsCopiedAndPaddedWithZeros) {
  // The sky's row distribution of a one-texel sky is 8 bytes; the buffer is 16, and it used
  // to copy 16 bytes from the 8-byte source. Here the 8 bytes are followed by 7s, which a copy
  // past the source would bring along (under ASan a heap source is reported at once).
  OpenClContext context(-1);
  const std::array<float, 4> region = {0.25f, 0.5f, 7.0f, 7.0f};
  OpenClBuffer buffer(context.context, CL_MEM_READ_ONLY, 2 * sizeof(float), region.data());
  ASSERT_EQ(buffer.size(), 16u);
  std::array<float, 4> back{};
  CL_CHECK(clEnqueueReadBuffer(context.queue, buffer.handle(), CL_TRUE, 0, sizeof(back), back.data(), 0, nullptr,
                               nullptr));
  EXPECT_EQ(back, (std::array<float, 4>{0.25f, 0.5f, 0.0f, 0.0f}));
}

TEST(Tiles, CoverTheRegionInEvenBandsOfWholeRowsWithinTheLimit) {
  for (const auto& [region, maxPixels] : std::vector<std::pair<PixelRegion, uint64_t>>{
           {{0, 0, 64, 48}, 512},
           {{0, 0, 64, 48}, 1u << 20},
           {{0, 0, 7, 5}, 7},
           {{0, 0, 7, 5}, 20},
           {{0, 0, 100, 3}, 1},
           {{0, 0, 8192, 8192}, 4194304},
           {{10, 20, 30, 41}, 45}}) {
    SCOPED_TRACE(std::to_string(region.width()) + "x" + std::to_string(region.height()) + " in " +
                 std::to_string(maxPixels));
    const std::vector<PixelRegion> tiles = splitIntoTiles(region, maxPixels);
    const uint64_t rowsAllowed = std::clamp<uint64_t>(maxPixels / region.width(), 1, region.height());
    ASSERT_EQ(tiles.size(), (region.height() + rowsAllowed - 1) / rowsAllowed);  // as few as the limit allows
    uint32_t nextRow = region.y0, lowest = UINT32_MAX, highest = 0;
    for (const PixelRegion& tile : tiles) {
      EXPECT_EQ(tile.x0, region.x0);
      EXPECT_EQ(tile.x1, region.x1);
      EXPECT_EQ(tile.y0, nextRow);
      EXPECT_GE(tile.height(), 1u);
      EXPECT_LE(tile.height(), rowsAllowed);
      lowest = std::min(lowest, tile.height());
      highest = std::max(highest, tile.height());
      nextRow = tile.y1;
    }
    EXPECT_EQ(nextRow, region.y1);
    EXPECT_LE(highest - lowest, 1u);  // even
  }
}

class DeviceLimits : public ::testing::TestWithParam<const char*> {
protected:
  RunResult render(const fs::path& output, std::vector<std::string> env, std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {"render", (sourceDirectory() / "assets" / "cornell-box.gltf").string(),
                                     "-o", output.string(), "--width", "64", "--height", "48", "--spp", "4",
                                     "--backend", GetParam(), "--sky", "none"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runWavepath(args, env, 300);
  }
  const fs::path dir = scratchDirectory("limits");
};

TEST_P(DeviceLimits, AnImageTooLargeForOneBufferIsRenderedInTilesIdenticalToOneRender) {
  // 16 KiB hold the accumulation of 256 pixels (4 rows, 64 bytes each): 12 tiles. 8192x8192
  // on lavapipe, whose largest storage buffer is 128 MiB, takes the same path (32 tiles).
  const RunResult whole = render(dir / "whole.exr", {});
  ASSERT_EQ(whole.exitCode, 0) << whole.err;
  const RunResult tiled = render(dir / "tiled.exr", {"WAVEPATH_MAX_BUFFER_BYTES=16384"});
  ASSERT_EQ(tiled.exitCode, 0) << tiled.err;
  EXPECT_NE(tiled.err.find("is rendered in 12 tiles"), std::string::npos) << tiled.err;
  // Each pixel's paths are the same whatever tile and pass they run in: bit for bit.
  const RadianceImage a = readExr(dir / "whole.exr");
  const RadianceImage b = readExr(dir / "tiled.exr");
  ASSERT_EQ(a.mean.size(), b.mean.size());
  for (size_t i = 0; i < a.mean.size(); ++i) {
    ASSERT_EQ(a.mean[i], b.mean[i]) << "pixel " << i;
    ASSERT_EQ(a.variance[i], b.variance[i]) << "pixel " << i;
    ASSERT_EQ(a.albedo[i], b.albedo[i]) << "pixel " << i;
    ASSERT_EQ(a.normal[i], b.normal[i]) << "pixel " << i;
    ASSERT_EQ(a.depth[i], b.depth[i]) << "pixel " << i;
  }
}

TEST_P(DeviceLimits, ASceneArrayTooLargeForTheDeviceIsOneErrorLine) {
  // The Cornell box's 32 triangles take 2 KiB; a scene array is not split.
  const RunResult r = render(dir / "image.png", {"WAVEPATH_MAX_BUFFER_BYTES=1024"});
  expectOneErrorLine(r, "the scene's triangles: 2 KiB, more than the 1 KiB");
  EXPECT_NE(r.err.find("(WAVEPATH_MAX_BUFFER_BYTES); render a smaller scene"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "image.png"));
}

TEST_P(DeviceLimits, ARegionInTilesEqualsTheRegionInOne) {
  // --region renders a crop (a part of a frame split over machines); split again into
  // tiles, each pixel still gets the paths it gets in the whole image.
  const std::vector<std::string> region = {"--region", "8,4,56,40"};
  const RunResult whole = render(dir / "whole.exr", {}, region);
  ASSERT_EQ(whole.exitCode, 0) << whole.err;
  const RunResult tiled = render(dir / "tiled.exr", {"WAVEPATH_MAX_BUFFER_BYTES=8192"}, region);
  ASSERT_EQ(tiled.exitCode, 0) << tiled.err;
  EXPECT_NE(tiled.err.find("tiles"), std::string::npos) << tiled.err;
  const RadianceImage a = readExr(dir / "whole.exr");
  const RadianceImage b = readExr(dir / "tiled.exr");
  ASSERT_EQ(a.mean.size(), size_t(48 * 36));
  ASSERT_EQ(a.mean, b.mean);
  ASSERT_EQ(a.variance, b.variance);
}

TEST_P(DeviceLimits, ACheckpointOfARenderInTilesIsRefused) {
  const RunResult r = render(dir / "image.exr", {"WAVEPATH_MAX_BUFFER_BYTES=16384"},
                             {"--checkpoint", (dir / "render.checkpoint").string()});
  expectOneErrorLine(r, "tiles, which cannot be checkpointed");
  EXPECT_FALSE(fs::exists(dir / "image.exr"));
}

INSTANTIATE_TEST_SUITE_P(Backends, DeviceLimits, ::testing::Values("vulkan", "opencl"));

}  // namespace
}  // namespace wp::test
