// Tests of PNG/EXR output and input, atomic writes, and the sRGB encoding in tonemap.h.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <stb_image_write.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <random>
#include <string>

#include "core/error.h"
#include "image/image_io.h"
#include "image/texture_decoder.h"
#include "shaders/common/tonemap.h"

namespace fs = std::filesystem;

namespace {

// A fresh empty directory per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() / ("wavepath_image_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  // Names of everything in the test directory, to catch leftover temporary files.
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir;
};

wp::RadianceImage makeImage(uint32_t width, uint32_t height, bool withVariance) {
  wp::RadianceImage image;
  image.width = width;
  image.height = height;
  for (uint32_t i = 0; i < width * height; ++i) {
    float x = float(i);
    image.mean.emplace_back(0.25f * x, -1.5f + x * x, 1e6f / (1.0f + x));
    if (withVariance) image.variance.emplace_back(1e-7f * x, 3.0f + x, 0.5f / (2.0f + x));
  }
  return image;
}

double referenceSrgb(double c) { return c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(ImageIoTest, PngHoldsRoundedSrgbOfClampedRadiance) {
  // Linear values and their 8-bit sRGB codes, worked out by hand from the sRGB formula:
  // 0.5 -> 0.735357 * 255 = 187.5 -> 188; 0.0031308 -> 0.0404499 * 255 = 10.3 -> 10.
  const float values[] = {0.0f, 0.0031308f, 0.5f, 1.0f, 2.0f, -1.0f, NAN};
  const unsigned char codes[] = {0, 10, 188, 255, 255, 0, 0};
  const int n = 7;
  wp::RadianceImage image;
  image.width = n;
  image.height = 2;
  // Each channel cycles through the values at a different phase, so a swapped channel or a
  // flipped row shows up; the second row is the first one reversed.
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < n; ++x) {
      int i = y == 0 ? x : n - 1 - x;
      image.mean.emplace_back(values[i], values[(i + 1) % n], values[(i + 3) % n]);
    }
  fs::path path = dir / "known.png";
  wp::writeImage(path, image);

  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
  EXPECT_EQ(width, n);
  EXPECT_EQ(height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < n; ++x) {
      int i = y == 0 ? x : n - 1 - x;
      const unsigned char* p = pixels + 3 * (y * n + x);
      EXPECT_EQ(p[0], codes[i]) << "x=" << x << " y=" << y;
      EXPECT_EQ(p[1], codes[(i + 1) % n]) << "x=" << x << " y=" << y;
      EXPECT_EQ(p[2], codes[(i + 3) % n]) << "x=" << x << " y=" << y;
    }
  stbi_image_free(pixels);
}

TEST_F(ImageIoTest, ExrRoundTripKeepsMeanAndVarianceExactly) {
  wp::RadianceImage image = makeImage(13, 7, true);
  fs::path path = dir / "radiance.exr";
  wp::writeImage(path, image);
  wp::RadianceImage back = wp::readExr(path);
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  ASSERT_EQ(back.mean.size(), image.mean.size());
  ASSERT_EQ(back.variance.size(), image.variance.size());
  for (size_t i = 0; i < image.mean.size(); ++i) {
    EXPECT_EQ(back.mean[i], image.mean[i]) << "pixel " << i;
    EXPECT_EQ(back.variance[i], image.variance[i]) << "pixel " << i;
  }
}

// Every pass the writer stores reads back bit for bit through tinyexr (an independent
// reader), across blocks of 16 scanlines with a partial last one: smooth passes (deflated),
// white noise of every float bit pattern but NaNs (which does not deflate, so its blocks are
// stored as they are), and the render record in the header.
TEST_F(ImageIoTest, ExrRoundTripOfEveryPassAndTheRecordIsBitExact) {
  const uint32_t width = 37, height = 35;
  wp::RadianceImage image = makeImage(width, height, true);
  std::mt19937 bits(7);
  auto noise = [&bits] {
    float value = 0.0f;
    do {
      const uint32_t word = bits();
      std::memcpy(&value, &word, sizeof(value));
    } while (std::isnan(value));
    return value;
  };
  for (uint32_t i = 0; i < width * height; ++i) {
    image.variance[i] = glm::vec3(noise(), noise(), noise());
    image.albedo.emplace_back(float(i % width) / width, 0.5f, 1.0f);
    image.normal.emplace_back(noise(), -1.0f, 0.0f);
    image.depth.push_back(1e-3f * float(i));
    image.sampleCount.push_back(float(i % 5));
  }
  wp::RenderRecord record;
  record.frameWidth = width;
  record.frameHeight = height;
  record.samplesPerPixel = 64;
  record.lastSample = 63;
  record.x1 = width;
  record.y1 = height;
  record.seed = 11;
  record.sceneHash = "0123456789abcdef";
  record.settings = "--max-depth 8";
  image.record = record;
  const fs::path path = dir / "passes.exr";
  wp::writeImage(path, image);
  const wp::RadianceImage back = wp::readExr(path);
  ASSERT_EQ(back.width, width);
  ASSERT_EQ(back.height, height);
  auto sameBits = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
  };
  EXPECT_TRUE(sameBits(back.mean, image.mean));
  EXPECT_TRUE(sameBits(back.variance, image.variance));
  EXPECT_TRUE(sameBits(back.albedo, image.albedo));
  EXPECT_TRUE(sameBits(back.normal, image.normal));
  EXPECT_TRUE(sameBits(back.depth, image.depth));
  EXPECT_TRUE(sameBits(back.sampleCount, image.sampleCount));
  ASSERT_TRUE(back.record.has_value());
  EXPECT_EQ(back.record->sceneHash, record.sceneHash);
  EXPECT_EQ(back.record->settings, record.settings);
  EXPECT_EQ(back.record->seed, record.seed);
  EXPECT_EQ(back.record->lastSample, record.lastSample);

  // An image of noise alone: no block deflates, so every one is stored as it is.
  wp::RadianceImage noiseOnly;
  noiseOnly.width = 19;
  noiseOnly.height = 3;
  for (uint32_t i = 0; i < noiseOnly.width * noiseOnly.height; ++i) {
    noiseOnly.mean.emplace_back(noise(), noise(), noise());
  }
  wp::writeImage(dir / "noise.exr", noiseOnly);
  EXPECT_TRUE(sameBits(wp::readExr(dir / "noise.exr").mean, noiseOnly.mean));
}

TEST_F(ImageIoTest, ExrWithoutVarianceReadsBackWithoutVariance) {
  wp::RadianceImage image = makeImage(4, 3, false);
  fs::path path = dir / "UPPER.EXR";
  wp::writeImage(path, image);
  wp::RadianceImage back = wp::readExr(path);
  EXPECT_EQ(back.mean, image.mean);
  EXPECT_TRUE(back.variance.empty());
}

TEST_F(ImageIoTest, WriteIntoMissingDirectoryThrowsAndCreatesNothing) {
  fs::path path = dir / "missing" / "out.png";
  EXPECT_THROW(wp::checkOutputPath(path), wp::Error);
  EXPECT_THROW(wp::writeImage(path, makeImage(2, 2, false)), wp::Error);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, UnknownExtensionThrowsWithOneLineMessage) {
  for (const char* name : {"out.bmp", "out", "out.png.txt", "out.hdr"}) {
    EXPECT_THROW(wp::checkOutputPath(dir / name), wp::Error) << name;
    try {
      wp::writeImage(dir / name, makeImage(2, 2, false));
      ADD_FAILURE() << name << " was accepted";
    } catch (const wp::Error& e) {
      std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos);
      EXPECT_NE(message.find(name), std::string::npos) << message;
    }
  }
  for (const char* name : {"out.png", "out.PNG", "out.Exr", "out.exr"})
    EXPECT_NO_THROW(wp::checkOutputPath(dir / name)) << name;
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, DirectoryAsOutputPathThrows) {
  fs::create_directory(dir / "image.png");
  EXPECT_THROW(wp::checkOutputPath(dir / "image.png"), wp::Error);
}

// An unwritable destination must be refused before rendering. A read-only directory does not
// stop root (as CI runs), so the test uses a parent that is a regular file, which stops anyone.
TEST_F(ImageIoTest, UnwritableDestinationThrows) {
  fs::path file = dir / "not-a-directory";
  std::ofstream(file) << "x";
  EXPECT_THROW(wp::checkOutputPath(file / "out.exr"), wp::Error);
  EXPECT_THROW(wp::writeImage(file / "out.png", makeImage(2, 2, false)), wp::Error);
}

TEST_F(ImageIoTest, MismatchedPixelCountThrows) {
  wp::RadianceImage image = makeImage(3, 3, true);
  image.variance.pop_back();
  EXPECT_THROW(wp::writeImage(dir / "bad.exr", image), wp::Error);
  image.variance.clear();
  image.mean.pop_back();
  EXPECT_THROW(wp::writeImage(dir / "bad.png", image), wp::Error);
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, SuccessfulWritesLeaveOnlyTheImages) {
  wp::writeImage(dir / "a.png", makeImage(8, 8, false));
  wp::writeImage(dir / "b.exr", makeImage(8, 8, true));
  wp::writeImage(dir / "b.exr", makeImage(4, 4, true));  // replaces the existing file
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.png", "b.exr"}));
  EXPECT_EQ(wp::readExr(dir / "b.exr").width, 4u);
}

// A write cut short (here by a file size limit, as a full disk would) throws, leaves the
// previous image intact and removes its temporary file.
TEST_F(ImageIoTest, FailedWriteKeepsOldFileAndRemovesTemporary) {
  fs::path path = dir / "frame.exr";
  wp::writeImage(path, makeImage(2, 2, false));
  std::string before = readFile(path);

  rlimit saved;
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  bool threw = false;
  try {
    wp::writeImage(path, makeImage(256, 256, true));  // ~1.5 MB of floats, barely compressible
  } catch (const wp::Error&) {
    threw = true;
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previousHandler);

  EXPECT_TRUE(threw);
  EXPECT_EQ(readFile(path), before);
  EXPECT_EQ(listing(), std::vector<std::string>{"frame.exr"});
}

// Ctrl-C or kill while the image is being written used to leave a hidden .NAME.tmpPID_N of
// several MB. The write now finishes (and renames) before the signal takes effect.
TEST_F(ImageIoTest, ASignalDuringTheWriteLeavesNoTemporaryFile) {
  const fs::path path = dir / "big.exr";
  const wp::RadianceImage image = makeImage(1024, 1024, true);  // ~24 MB of barely compressible floats
  // Signal the writer as soon as its temporary file exists, that is, mid-write. The file
  // exists only while the encoded blocks are written out, and on a machine busy with other
  // tests this process may not look during that time: then the attempt proves nothing, and
  // the next one tries again.
  bool sawTemporary = false;
  int status = 0;
  for (int attempt = 0; attempt < 5 && !sawTemporary; ++attempt) {
    fs::remove(path);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      wp::writeImage(path, image);
      ::_exit(0);
    }
    while (!sawTemporary && ::waitpid(child, &status, WNOHANG) == 0) {
      for (const std::string& name : listing()) sawTemporary = sawTemporary || name.rfind(".big.exr.tmp", 0) == 0;
      if (sawTemporary) {
        ::kill(child, SIGINT);
        ::waitpid(child, &status, 0);
      }
    }
  }
  ASSERT_TRUE(sawTemporary) << "the write ended before it was seen, five times; write a larger image";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << "the signal must still end the process";
  EXPECT_EQ(listing(), std::vector<std::string>{"big.exr"});
  EXPECT_EQ(wp::readExr(path).width, 1024u);
}

TEST_F(ImageIoTest, ReadingMissingOrNonExrFileThrows) {
  EXPECT_THROW(wp::readExr(dir / "none.exr"), wp::Error);
  wp::writeImage(dir / "image.png", makeImage(2, 2, false));
  EXPECT_THROW(wp::readExr(dir / "image.png"), wp::Error);
}

// --- textures: PNG and JPEG through libpng and libjpeg-turbo ---

std::vector<uint8_t> encodeWithStb(bool jpeg, int width, int height, int channels, const std::vector<uint8_t>& pixels) {
  std::vector<uint8_t> out;
  auto append = [](void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<uint8_t>*>(context);
    bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  if (jpeg) {
    stbi_write_jpg_to_func(append, &out, width, height, channels, pixels.data(), 95);
  } else {
    stbi_write_png_to_func(append, &out, width, height, channels, pixels.data(), width * channels);
  }
  return out;
}

std::string decodeError(const std::vector<uint8_t>& bytes) {
  try {
    wp::decodeTexture(bytes.data(), bytes.size());
  } catch (const wp::Error& e) {
    return e.what();
  }
  return "";
}

TEST(TextureDecoder, PngOfEveryChannelCountBecomesRgba8Exactly) {
  const int width = 5, height = 3;
  for (int channels = 1; channels <= 4; ++channels) {
    SCOPED_TRACE(channels);
    std::vector<uint8_t> pixels;
    for (int i = 0; i < width * height * channels; ++i) pixels.push_back(uint8_t(i * 37 + 11));
    const std::vector<uint8_t> png = encodeWithStb(false, width, height, channels, pixels);
    const wp::Rgba8Image image = wp::decodeTexture(png.data(), png.size());
    ASSERT_EQ(image.width, uint32_t(width));
    ASSERT_EQ(image.height, uint32_t(height));
    for (int p = 0; p < width * height; ++p) {
      const uint8_t* in = &pixels[size_t(p) * channels];
      const bool grey = channels <= 2;
      const uint8_t expected[4] = {in[0], grey ? in[0] : in[1], grey ? in[0] : in[2],
                                   channels == 2 ? in[1] : channels == 4 ? in[3] : uint8_t(255)};
      for (int c = 0; c < 4; ++c) EXPECT_EQ(image.rgba[size_t(p) * 4 + c], expected[c]) << "pixel " << p << " " << c;
    }
  }
}

TEST(TextureDecoder, JpegDecodesCloseToWhatWasEncoded) {
  const int width = 16, height = 16;
  std::vector<uint8_t> pixels;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) pixels.insert(pixels.end(), {uint8_t(16 * x), uint8_t(16 * y), 128});
  const std::vector<uint8_t> jpeg = encodeWithStb(true, width, height, 3, pixels);
  const wp::Rgba8Image image = wp::decodeTexture(jpeg.data(), jpeg.size());
  ASSERT_EQ(image.width, uint32_t(width));
  for (int p = 0; p < width * height; ++p) {
    // Quality 95 with chroma subsampling: a smooth ramp keeps within a few codes.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.rgba[size_t(p) * 4 + c], pixels[size_t(p) * 3 + c], 12) << p;
    EXPECT_EQ(image.rgba[size_t(p) * 4 + 3], 255);
  }
}

TEST(TextureDecoder, AJpegHuffmanTableOfMoreThan256CodesIsAnError) {
  // stb_image sized its Huffman tables for 256 codes and never checked the counts a table
  // declares: fuzz_texture found a write past them (UBSan: index 257 out of bounds). Here the
  // first table's 16 counts say 16 * 20 = 320 codes.
  std::vector<uint8_t> pixels(8 * 8 * 3, 100);
  std::vector<uint8_t> jpeg = encodeWithStb(true, 8, 8, 3, pixels);
  size_t dht = 0;
  while (dht + 1 < jpeg.size() && !(jpeg[dht] == 0xff && jpeg[dht + 1] == 0xc4)) ++dht;
  ASSERT_LT(dht + 21, jpeg.size()) << "no DHT segment";
  for (int i = 0; i < 16; ++i) jpeg[dht + 5 + i] = 20;  // after FF C4, the length and the class/id byte
  const std::string message = decodeError(jpeg);
  EXPECT_EQ(message.rfind("JPEG: ", 0), 0u) << message;
}

TEST(TextureDecoder, DamagedOrOversizedOrOtherFilesAreErrors) {
  std::vector<uint8_t> pixels(6 * 4 * 3, 50);
  const std::vector<uint8_t> png = encodeWithStb(false, 6, 4, 3, pixels);
  const std::vector<uint8_t> jpeg = encodeWithStb(true, 6, 4, 3, pixels);
  for (size_t cut : {size_t(8), size_t(20), png.size() / 2, png.size() - 4}) {
    EXPECT_EQ(decodeError({png.begin(), png.begin() + long(cut)}).rfind("PNG: ", 0), 0u) << cut;
  }
  for (size_t cut : {size_t(3), size_t(40), jpeg.size() / 2, jpeg.size() - 2}) {
    EXPECT_EQ(decodeError({jpeg.begin(), jpeg.begin() + long(cut)}).rfind("JPEG: ", 0), 0u) << cut;
  }
  // A PNG whose header declares 16000x16000 pixels, with a valid CRC, in under 100 bytes.
  std::vector<uint8_t> bomb = png;
  const uint8_t size[8] = {0, 0, 0x3e, 0x80, 0, 0, 0x3e, 0x80};
  std::copy(size, size + 8, bomb.begin() + 16);  // IHDR's width and height
  uint32_t crc = 0xffffffffu;  // CRC-32 of the chunk type and data, as PNG stores it
  for (size_t i = 12; i < 29; ++i) {
    crc ^= bomb[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  crc = ~crc;
  for (int i = 0; i < 4; ++i) bomb[29 + i] = uint8_t(crc >> (24 - 8 * i));
  EXPECT_NE(decodeError(bomb).find("declares 16000x16000 pixels, more than its"), std::string::npos)
      << decodeError(bomb);
  EXPECT_EQ(decodeError({'G', 'I', 'F', '8', '9', 'a', 0, 0}), "not a PNG, JPEG or WebP image");
}

TEST(Tonemap, LinearToSrgbMatchesTheFormula) {
  for (int i = 0; i <= 100000; ++i) {
    double c = i / 100000.0;
    c = c * c * c;  // denser near 0, where the linear piece and the breakpoint are
    EXPECT_NEAR(wp::gpu::linearToSrgb(float(c)), referenceSrgb(float(c)), 1e-6) << "c=" << c;
  }
  glm::vec3 v = wp::gpu::linearToSrgb3(glm::vec3(0.001f, 0.2f, 0.9f));
  EXPECT_NEAR(v.x, referenceSrgb(0.001f), 1e-6);
  EXPECT_NEAR(v.y, referenceSrgb(0.2f), 1e-6);
  EXPECT_NEAR(v.z, referenceSrgb(0.9f), 1e-6);
}

// sRGB's published constants leave the two pieces 2.9e-8 apart at 0.0031308 (the linear
// piece ends slightly above where the power piece starts), far below any display precision;
// that one step is the only decrease allowed.
TEST(Tonemap, LinearToSrgbIsMonotone) {
  const float breakpoint = 0.0031308f;
  auto check = [&](uint32_t first, uint32_t last, uint32_t step) {
    float previous = wp::gpu::linearToSrgb(wp::gpu::asFloat(first));
    for (uint32_t bits = first + step; bits <= last; bits += step) {
      float c = wp::gpu::asFloat(bits);
      float value = wp::gpu::linearToSrgb(c);
      bool atBreakpoint = c >= breakpoint && wp::gpu::asFloat(bits - step) < breakpoint;
      if (atBreakpoint)
        ASSERT_GT(value, previous - 3e-8f) << "c=" << c;
      else
        ASSERT_GE(value, previous) << "c=" << c;
      previous = value;
    }
  };
  uint32_t breakBits = wp::gpu::asUint(breakpoint);
  check(wp::gpu::asUint(0.0f), wp::gpu::asUint(1.0f), 61);  // every 61st float in [0, 1]
  check(breakBits - 100000, breakBits + 100000, 1);         // every float near the breakpoint
  EXPECT_EQ(wp::gpu::linearToSrgb(0.0f), 0.0f);
  EXPECT_NEAR(wp::gpu::linearToSrgb(1.0f), 1.0f, 1e-7);
}

TEST(Tonemap, PackSrgba8OrdersBytesRgbaWithOpaqueAlpha) {
  uint32_t packed = wp::gpu::packSrgba8(glm::vec3(0.5f, 0.0031308f, 2.0f));
  EXPECT_EQ(packed & 0xffu, 188u);
  EXPECT_EQ((packed >> 8) & 0xffu, 10u);
  EXPECT_EQ((packed >> 16) & 0xffu, 255u);
  EXPECT_EQ(packed >> 24, 255u);
  EXPECT_EQ(wp::gpu::packSrgba8(glm::vec3(-3.0f, NAN, INFINITY)), 0xffff0000u);
}

// Every 8-bit code is reachable and the encoding never goes down as radiance goes up.
TEST(Tonemap, PackSrgba8IsMonotoneAndCoversAllCodes) {
  uint32_t previous = 0;
  std::vector<bool> seen(256, false);
  for (int i = 0; i <= 1 << 20; ++i) {
    float c = float(i) / float(1 << 20);
    uint32_t code = wp::gpu::packSrgba8(glm::vec3(c)) & 0xffu;
    ASSERT_GE(code, previous) << "c=" << c;
    previous = code;
    seen[code] = true;
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), true), 256);
}

}  // namespace
