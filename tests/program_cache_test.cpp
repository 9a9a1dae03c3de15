// The OpenCL program binary cache: entries survive only intact and under their own key, and
// through the real command line a second run reuses the kernels while a damaged entry is
// rebuilt without a word.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <fstream>
#include <iterator>

#include "backend/opencl/opencl_backend.h"
#include "backend/opencl/program_cache.h"
#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeFile(const std::filesystem::path& file, const std::string& data) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << data;
}

std::vector<std::filesystem::path> entries(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    files.push_back(entry.path());
  }
  return files;
}

const std::vector<unsigned char> kBinary = {'b', 'i', 'n', 0, 1, 2, 3, 255, 'a', 'r', 'y'};

// On a CPU device the kernels are built for work-items that run as threads (prelude_cl.h:
// the traversal branches where SIMD lanes would not, and prefetches); on a GPU they are not.
// The options are the cache key too, so the two builds are cached apart.
TEST(ProgramOptions, CpuDevicesBuildWorkItemsAsThreadsGpusAsLanes) {
  OpenClDeviceInfo cpu;
  cpu.type = "CPU";
  OpenClDeviceInfo gpu;
  gpu.type = "GPU";
  const std::string threads = "-DWP_WORK_ITEMS_ARE_THREADS=1";
  EXPECT_NE(openClProgramOptions(cpu, false, false).find(threads), std::string::npos);
  EXPECT_NE(openClProgramOptions(cpu, true, true).find(threads), std::string::npos);
  EXPECT_EQ(openClProgramOptions(gpu, false, false).find(threads), std::string::npos);
  EXPECT_EQ(openClProgramOptions(gpu, true, true).find(threads), std::string::npos);
  EXPECT_EQ(openClProgramOptions(gpu, true, true), "-cl-std=CL1.2 -cl-denorms-are-zero -Werror -DWP_MOTION_BLUR=1");
  EXPECT_EQ(openClProgramOptions(cpu, false, false),
            "-cl-std=CL1.2 -cl-denorms-are-zero -DWP_WORK_ITEMS_ARE_THREADS=1");
}

// Every device flushes denormal floats to zero: a CPU pays a microcode assist for each
// denormal operand (PoCL's generate stage ran at half speed without the flag), and the
// images do not depend on values below 1e-38.
TEST(ProgramOptions, EveryDeviceFlushesDenormals) {
  for (const char* type : {"CPU", "GPU", "ACCELERATOR"}) {
    OpenClDeviceInfo device;
    device.type = type;
    for (bool validate : {false, true}) {
      for (bool motion : {false, true}) {
        EXPECT_NE(openClProgramOptions(device, validate, motion).find(" -cl-denorms-are-zero"), std::string::npos)
            << type;
      }
    }
  }
}

TEST(ProgramCache, StoredBinaryLoadsBackAndNoTemporaryFileRemains) {
  std::filesystem::path dir = scratchDirectory("cache") / "new" / "dir";
  ProgramCache cache(dir, "device A\ndriver 1\n");
  EXPECT_TRUE(cache.load().empty());
  cache.store(kBinary);
  EXPECT_EQ(cache.load(), kBinary);
  EXPECT_EQ(entries(dir), std::vector<std::filesystem::path>{cache.file()});
}

TEST(ProgramCache, EntryUnderAnotherKeyIsNotLoaded) {
  std::filesystem::path dir = scratchDirectory("cache");
  ProgramCache a(dir, "device A\ndriver 1\n");
  ProgramCache b(dir, "device A\ndriver 2\n");
  ASSERT_NE(a.file(), b.file());
  a.store(kBinary);
  // Even a file of b's name (a hash collision, a copied file) holds a's key, not b's.
  std::filesystem::copy_file(a.file(), b.file());
  EXPECT_TRUE(b.load().empty());
  EXPECT_EQ(a.load(), kBinary);
}

TEST(ProgramCache, EveryTruncationAndEveryAlteredByteIsRejected) {
  std::filesystem::path dir = scratchDirectory("cache");
  ProgramCache cache(dir, "device A\ndriver 1\n");
  cache.store(kBinary);
  const std::string intact = readFile(cache.file());
  for (size_t size = 0; size < intact.size(); ++size) {
    writeFile(cache.file(), intact.substr(0, size));
    EXPECT_TRUE(cache.load().empty()) << "truncated to " << size << " bytes";
  }
  writeFile(cache.file(), intact + "x");
  EXPECT_TRUE(cache.load().empty()) << "trailing byte";
  for (size_t i = 0; i < intact.size(); ++i) {
    std::string altered = intact;
    altered[i] = char(altered[i] ^ 0x20);
    writeFile(cache.file(), altered);
    EXPECT_TRUE(cache.load().empty()) << "byte " << i << " altered";
  }
  writeFile(cache.file(), intact);
  EXPECT_EQ(cache.load(), kBinary);
}

TEST(ProgramCache, UnusableDirectoryIsIgnored) {
  std::filesystem::path blocker = scratchDirectory("cache") / "file";
  writeFile(blocker, "not a directory");
  ProgramCache cache(blocker / "wavepath", "device A\n");
  cache.store(kBinary);
  EXPECT_TRUE(cache.load().empty());
  ProgramCache none({}, "device A\n");
  none.store(kBinary);
  EXPECT_TRUE(none.load().empty());
}

TEST(ProgramCache, DefaultDirectoryFollowsTheEnvironment) {
  const char* names[3] = {"WAVEPATH_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  std::optional<std::string> saved[3];
  for (int i = 0; i < 3; ++i) {
    if (const char* value = std::getenv(names[i])) {
      saved[i] = value;
    }
  }
  setenv("WAVEPATH_CACHE_DIR", "/c/wavepath-cache", 1);
  setenv("XDG_CACHE_HOME", "/x", 1);
  setenv("HOME", "/h", 1);
  EXPECT_EQ(ProgramCache::defaultDirectory(), "/c/wavepath-cache");
  unsetenv("WAVEPATH_CACHE_DIR");
  EXPECT_EQ(ProgramCache::defaultDirectory(), "/x/wavepath");
  unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(ProgramCache::defaultDirectory(), "/h/.cache/wavepath");
  for (int i = 0; i < 3; ++i) {
    if (saved[i]) {
      setenv(names[i], saved[i]->c_str(), 1);
    } else {
      unsetenv(names[i]);
    }
  }
}

// Through the real command line, with a cache directory of the test's own.
struct CachedRun {
  RunResult run;
  RadianceImage image;
};

// The Cornell box with --sky none, which it has anyway: a sky the user chose leaves the
// lighting rule nothing to note, so the compile note is all a run may say.
CachedRun renderWithCache(const std::filesystem::path& cacheDir, std::vector<std::string> environment = {}) {
  std::filesystem::path out = scratchDirectory("cached-render") / "image.exr";
  CachedRun r;
  environment.push_back("WAVEPATH_CACHE_DIR=" + cacheDir.string());
  r.run = runWavepath({"render", (sourceDirectory() / "assets" / "cornell-box.gltf").string(), "-o", out.string(),
                       "--backend", "opencl", "--width", "16", "--height", "16", "--spp", "2", "--sky", "none"},
                      environment);
  EXPECT_EQ(r.run.exitCode, 0) << r.run.err;
  if (r.run.exitCode == 0) {
    r.image = readExr(out);
  }
  return r;
}

const std::string kCompiling = "wavepath: note: compiling the OpenCL kernels";

// The only thing a run that rebuilds may say: the note that it compiles.
void expectOnlyTheCompileNote(const RunResult& r) {
  EXPECT_EQ(r.err.rfind(kCompiling, 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(ProgramCacheRun, SecondRunLoadsTheKernelsFromTheCache) {
  std::filesystem::path dir = scratchDirectory("cache");
  CachedRun first = renderWithCache(dir);
  expectOnlyTheCompileNote(first.run);
  ASSERT_EQ(entries(dir).size(), 1u);
  CachedRun second = renderWithCache(dir);
  EXPECT_EQ(second.run.err, "");
  EXPECT_EQ(second.image.mean, first.image.mean);
}

// The stored key: the entry starts with "WPCLBIN1", the key's length (8 bytes, little
// endian) and the key (program_cache.cpp).
std::string storedKey(const std::filesystem::path& entry) {
  std::string data = readFile(entry);
  uint64_t size = 0;
  for (int i = 0; i < 8; ++i) {
    size |= uint64_t(static_cast<unsigned char>(data.at(8 + i))) << (8 * i);
  }
  return data.substr(16, size);
}

// PoCL's compiled kernels hold its work-group method: wavepath sets "auto" (3.3x faster than
// PoCL 3.1's default vectorized loops on the Cornell box with the binary BVH,
// opencl_devices.cpp), a user's choice wins, and a
// program compiled under one method is not loaded under another (it would run the old
// one's work-group functions). The method must be one PoCL knows: PoCL compiles its
// work-group functions afresh here (its own kernel cache off) and would warn on stderr for
// each kernel about a method it does not know (3.1 has no "cbs").
TEST(ProgramCacheRun, PoclWorkGroupMethodIsAutoUnlessChosenAndKeysTheCache) {
  std::filesystem::path dir = scratchDirectory("cache-method");
  expectOnlyTheCompileNote(renderWithCache(dir, {"POCL_KERNEL_CACHE=0"}).run);
  ASSERT_EQ(entries(dir).size(), 1u);
  EXPECT_NE(storedKey(entries(dir)[0]).find("pocl work-group method: auto\n"), std::string::npos);
  CachedRun chosen = renderWithCache(dir, {"POCL_WORK_GROUP_METHOD=loopvec"});
  expectOnlyTheCompileNote(chosen.run);
  ASSERT_EQ(entries(dir).size(), 2u);
  CachedRun again = renderWithCache(dir);
  EXPECT_EQ(again.run.err, "");
}

TEST(ProgramCacheRun, DamagedOrUnloadableEntryIsRebuiltSilently) {
  std::filesystem::path dir = scratchDirectory("cache");
  CachedRun first = renderWithCache(dir);
  ASSERT_EQ(entries(dir).size(), 1u);
  std::filesystem::path entry = entries(dir).front();
  std::string key = storedKey(entry);

  // Damaged on disk: the file checks reject it.
  std::string damaged = readFile(entry);
  damaged[damaged.size() / 2] = char(damaged[damaged.size() / 2] ^ 0xff);
  writeFile(entry, damaged);
  CachedRun rebuilt = renderWithCache(dir);
  expectOnlyTheCompileNote(rebuilt.run);
  EXPECT_EQ(rebuilt.image.mean, first.image.mean);
  EXPECT_EQ(renderWithCache(dir).run.err, "") << "the rebuilt entry was not stored";

  // Intact as a file, but not a binary the driver accepts.
  ProgramCache(dir, key).store(std::vector<unsigned char>(4096, 'x'));
  ASSERT_EQ(entries(dir), std::vector<std::filesystem::path>{entry});
  CachedRun reloaded = renderWithCache(dir);
  expectOnlyTheCompileNote(reloaded.run);
  EXPECT_EQ(reloaded.image.mean, first.image.mean);
}

}  // namespace
}  // namespace wp::test
