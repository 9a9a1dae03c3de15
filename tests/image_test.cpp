// Tests of PNG/EXR output and input, atomic writes, and the sRGB encoding in tonemap.h.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <string>

#include "core/error.h"
#include "image/image_io.h"
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
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    wp::writeImage(path, image);
    ::_exit(0);
  }
  // Signal the writer as soon as its temporary file exists, that is, mid-write.
  bool sawTemporary = false;
  int status = 0;
  while (!sawTemporary && ::waitpid(child, &status, WNOHANG) == 0) {
    for (const std::string& name : listing()) sawTemporary = sawTemporary || name.rfind(".big.exr.tmp", 0) == 0;
    if (sawTemporary) {
      ::kill(child, SIGINT);
      ::waitpid(child, &status, 0);
    }
  }
  ASSERT_TRUE(sawTemporary) << "the write ended before it was seen; write a larger image";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << "the signal must still end the process";
  EXPECT_EQ(listing(), std::vector<std::string>{"big.exr"});
  EXPECT_EQ(wp::readExr(path).width, 1024u);
}

TEST_F(ImageIoTest, ReadingMissingOrNonExrFileThrows) {
  EXPECT_THROW(wp::readExr(dir / "none.exr"), wp::Error);
  wp::writeImage(dir / "image.png", makeImage(2, 2, false));
  EXPECT_THROW(wp::readExr(dir / "image.png"), wp::Error);
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
