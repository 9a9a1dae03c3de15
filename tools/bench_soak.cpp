// Soak benchmark: runs `wavepath render` in-process for long and prints the resident memory at
// intervals, which should stay flat once the first pass or frame has allocated what it needs:
// the Cornell box at 10,000 samples per pixel (thousands of passes), then 100 frames of
// assets/animated.gltf (a new pose, GPU scene update and image per frame).
//   wavepath-bench-soak [--backend vulkan|opencl] [--interval S] [--spp N] [--frames N]
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/error.h"

namespace {

double residentMiB() {
  long pages = 0, resident = 0;
  std::ifstream("/proc/self/statm") >> pages >> resident;
  return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Prints the resident memory every `interval` seconds while it lives, and its range at the end.
class MemorySampler {
public:
  MemorySampler(std::string label, double interval) : label_(std::move(label)), interval_(interval) {
    thread_ = std::thread([this] { run(); });
  }
  ~MemorySampler() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    thread_.join();
    std::printf("%s: resident memory from %.1f MiB (first sample) to %.1f MiB (last), peak %.1f MiB\n", label_.c_str(),
                first_, last_, peak_);
  }

private:
  void run() {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      const bool done = wake_.wait_for(lock, std::chrono::duration<double>(interval_), [this] { return done_; });
      const double mib = residentMiB();
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (first_ == 0.0) first_ = mib;
      last_ = mib;
      peak_ = std::max(peak_, mib);
      std::printf("%s: %7.1f s  resident %.1f MiB\n", label_.c_str(), seconds, mib);
      std::fflush(stdout);
      if (done) return;
    }
  }

  std::string label_;
  double interval_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  double first_ = 0.0, last_ = 0.0, peak_ = 0.0;
  std::thread thread_;
};

}  // namespace

int main(int argc, char** argv) {
  std::string backend = "vulkan";
  double interval = 5.0;
  uint32_t spp = 10000, frames = 100;
  CLI::App app{"wavepath-bench-soak: resident memory over a long render and a long image sequence"};
  app.add_option("--backend", backend, "vulkan or opencl")->check(CLI::IsMember({"vulkan", "opencl"}));
  app.add_option("--interval", interval, "Seconds between memory samples")->check(CLI::Range(0.1, 3600.0));
  app.add_option("--spp", spp, "Samples per pixel of the Cornell box")->check(CLI::Range(1u, 1u << 20));
  app.add_option("--frames", frames, "Frames of the animated sequence")->check(CLI::Range(1u, 100000u));
  CLI11_PARSE(app, argc, argv);

  const std::filesystem::path source = std::filesystem::path(WAVEPATH_SOURCE_DIR);
  const std::filesystem::path out = std::filesystem::temp_directory_path() / ("wavepath-soak-" + std::to_string(::getpid()));
  std::filesystem::create_directories(out);
  try {
    {
      wp::RenderOptions o;
      o.scene = (source / "assets" / "cornell-box.gltf").string();
      o.output = (out / "cornell.exr").string();
      o.backend = backend;
      o.settings.width = o.settings.height = 64;
      o.widthGiven = o.heightGiven = true;
      o.settings.samplesPerPixel = spp;
      // 64 x 64 pixels at 16 samples a pass: thousands of passes.
      o.settings.maxPaths = 64 * 64 * 16;
      const MemorySampler sampler("cornell-box " + std::to_string(spp) + " spp", interval);
      wp::runRender(o);
    }
    {
      wp::RenderOptions o;
      o.scene = (source / "assets" / "animated.gltf").string();
      o.output = (out / "frame_###.png").string();
      o.backend = backend;
      o.settings.width = 96;
      o.widthGiven = true;
      o.settings.samplesPerPixel = 4;
      o.frames = "0.." + std::to_string(frames - 1);
      const MemorySampler sampler("animated " + std::to_string(frames) + " frames", interval);
      wp::runRender(o);
    }
  } catch (const wp::Error& e) {
    std::fprintf(stderr, "wavepath-bench-soak: error: %s\n", e.what());
    std::filesystem::remove_all(out);
    return 1;
  }
  std::filesystem::remove_all(out);
  return 0;
}
