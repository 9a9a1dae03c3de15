// --backend auto, the default: which backend it picks from the devices each backend offers
// (autoBackend, on made-up device lists, since CI has no GPU), and that a render without
// --backend runs where it picks on this machine's devices (on CI, where Vulkan has lavapipe
// and OpenCL has PoCL, both CPUs: OpenCL). The suite sets WAVEPATH_BACKEND=vulkan for every
// test (tests/CMakeLists.txt); these clear it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/backend_factory.h"
#include "core/error.h"
#include "support/run_wavepath.h"

namespace wp {
namespace {

VulkanDeviceInfo vulkanDevice(const std::string& name, bool gpu, const std::string& missing = "", int rank = 0) {
  VulkanDeviceInfo device;
  device.name = name;
  device.type = gpu ? "discrete GPU" : "CPU";
  device.gpu = gpu;
  device.rank = rank > 0 ? rank : gpu ? 4 : 1;  // as describe ranks a discrete GPU and a CPU
  device.missing = missing;
  return device;
}

// A device that meets missingRequirement's checks, or, with `compiler` false, lacks one.
OpenClDeviceInfo openClDevice(const std::string& name, const std::string& type, bool compiler = true) {
  OpenClDeviceInfo device;
  device.name = name;
  device.type = type;
  device.languageVersion = "OpenCL C 1.2 ";
  device.compilerAvailable = compiler;
  device.maxWorkGroupSize = 4096;
  device.rank = type == "GPU" ? 3 : 1;  // as listOpenClDevices ranks them
  return device;
}

const VulkanDeviceInfo kLavapipe = vulkanDevice("llvmpipe", false);
const OpenClDeviceInfo kPocl = openClDevice("pthread-cpu", "CPU");

TEST(AutoBackend, VulkanWhereItHasAGpu) {
  EXPECT_EQ(autoBackend({kLavapipe, vulkanDevice("NVIDIA H200", true)}, {kPocl, openClDevice("NVIDIA H200", "GPU")}).name,
            "vulkan");
}

TEST(AutoBackend, NamesTheGpuVulkanWillTake) {
  // An integrated GPU (rank 3) listed before a discrete one: the render takes the discrete.
  const AutoBackend chosen =
      autoBackend({vulkanDevice("integrated", true, "", 3), vulkanDevice("discrete", true)}, {kPocl});
  EXPECT_EQ(chosen.name, "vulkan");
  EXPECT_NE(chosen.reason.find("discrete"), std::string::npos) << chosen.reason;
}

TEST(AutoBackend, OpenClWhereVulkanHasOnlyACpu) {
  const AutoBackend chosen = autoBackend({kLavapipe}, {kPocl});
  EXPECT_EQ(chosen.name, "opencl");
  EXPECT_NE(chosen.reason.find("pthread-cpu"), std::string::npos) << chosen.reason;
}

TEST(AutoBackend, AGpuWithAnOpenClDriverAloneIsOpenCl) {
  EXPECT_EQ(autoBackend({}, {openClDevice("gfx1100", "GPU")}).name, "opencl");
  // The reason names the device OpenCL will take, the GPU, though PoCL is listed first.
  const AutoBackend chosen = autoBackend({kLavapipe}, {kPocl, openClDevice("gfx1100", "GPU")});
  EXPECT_EQ(chosen.name, "opencl");
  EXPECT_NE(chosen.reason.find("gfx1100"), std::string::npos) << chosen.reason;
}

TEST(AutoBackend, AVulkanGpuThatCannotRunTheStagesDoesNotCount) {
  EXPECT_EQ(autoBackend({vulkanDevice("old GPU", true, "Vulkan 1.1")}, {kPocl}).name, "opencl");
}

TEST(AutoBackend, VulkanWhereOpenClHasNoUsableDevice) {
  EXPECT_EQ(autoBackend({kLavapipe}, {openClDevice("no compiler", "CPU", false)}).name, "vulkan");
  EXPECT_EQ(autoBackend({kLavapipe}, {}).name, "vulkan");
  // Neither has a device: Vulkan, whose error line says what to install.
  EXPECT_EQ(autoBackend({}, {}).name, "vulkan");
}

// The backend a render's summary line names: "... on DEVICE (Vulkan)" or "(OpenCL)".
std::string backendOfRender(const std::vector<std::string>& flags, const std::vector<std::string>& env) {
  const std::string out = (test::scratchDirectory("backend") / "box.png").string();
  std::vector<std::string> args = {"render", (test::sourceDirectory() / "assets/cornell-box.gltf").string(),
                                   "-o", out, "--width", "16", "--height", "16", "--spp", "1"};
  args.insert(args.end(), flags.begin(), flags.end());
  const test::RunResult r = test::runWavepath(args, env, 300);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  if (r.out.find("(OpenCL)\n") != std::string::npos) return "opencl";
  if (r.out.find("(Vulkan)\n") != std::string::npos) return "vulkan";
  return "none: " + r.out;
}

const std::string kUnset = "WAVEPATH_BACKEND=";  // empty counts as unset

// What auto picks on this machine's devices: OpenCL where CI runs (lavapipe and PoCL, both
// CPUs), Vulkan on a machine with a Vulkan GPU.
std::string autoHere() {
  std::vector<VulkanDeviceInfo> vulkan;
  std::vector<OpenClDeviceInfo> openCl;
  try {
    vulkan = listVulkanDevices();
  } catch (const Error&) {
  }
  try {
    openCl = listOpenClDevices();
  } catch (const Error&) {
  }
  return autoBackend(vulkan, openCl).name;
}

TEST(BackendFlag, WithoutItARenderRunsWhereAutoPicks) {
  const std::string expected = autoHere();
  EXPECT_EQ(backendOfRender({}, {kUnset}), expected);
  EXPECT_EQ(backendOfRender({"--backend", "auto"}, {kUnset}), expected);
  const test::RunResult devices = test::runWavepath({"devices"}, {kUnset}, 60);
  const std::string line = std::string("Renders without --backend run on ") +
                           (expected == "vulkan" ? "Vulkan" : "OpenCL") + " (--backend auto: ";
  EXPECT_NE(devices.out.find(line), std::string::npos) << devices.out;
}

TEST(BackendFlag, WithoutItAndWithoutOpenClLavapipeRenders) {
  EXPECT_EQ(backendOfRender({}, {kUnset, "OCL_ICD_VENDORS=/nonexistent"}), "vulkan");
}

TEST(BackendFlag, WavepathBackendSetsTheDefaultAndTheFlagOverridesIt) {
  EXPECT_EQ(backendOfRender({}, {"WAVEPATH_BACKEND=opencl"}), "opencl");
  EXPECT_EQ(backendOfRender({}, {"WAVEPATH_BACKEND=vulkan"}), "vulkan");
  EXPECT_EQ(backendOfRender({"--backend", "vulkan"}, {"WAVEPATH_BACKEND=opencl"}), "vulkan");
  EXPECT_EQ(backendOfRender({"--backend", "auto"}, {"WAVEPATH_BACKEND=vulkan"}), autoHere());
}

TEST(BackendFlag, AWavepathBackendThatIsNoBackendIsOneErrorLine) {
  const std::string out = (test::scratchDirectory("backend") / "box.png").string();
  const test::RunResult r = test::runWavepath(
      {"render", (test::sourceDirectory() / "assets/cornell-box.gltf").string(), "-o", out}, {"WAVEPATH_BACKEND=cuda"});
  test::expectOneErrorLine(r, "WAVEPATH_BACKEND is 'cuda', not a backend; set it to vulkan, opencl or auto", 1);
  test::expectOneErrorLine(test::runWavepath({"devices"}, {"WAVEPATH_BACKEND=cuda"}, 60), "WAVEPATH_BACKEND is 'cuda'",
                           1);
}

}  // namespace
}  // namespace wp
