// Bad input through the command line: each case must end with one clear error line, a
// non-zero exit code and no output file; never a crash or a hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>

#include "support/gltf_writer.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

struct Outcome {
  RunResult run;
  std::filesystem::path output;
};

Outcome renderExpectingFailure(const std::filesystem::path& scene, std::vector<std::string> extra = {},
                               std::vector<std::string> env = {}) {
  Outcome o;
  o.output = scratchDirectory("out") / "image.png";
  std::vector<std::string> args = {"render", scene.string(), "-o", o.output.string(), "--width", "8", "--height", "8",
                                   "--spp", "1"};
  args.insert(args.end(), extra.begin(), extra.end());
  o.run = runWavepath(args, env, 120);
  return o;
}

void writeText(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

// One triangle (3 positions, 3 uint16 indices) as a glTF JSON text with the given pieces
// swapped in, so each case differs from a valid file in exactly one way.
std::string triangleGltf(const std::vector<glm::vec3>& positions, std::vector<uint16_t> indices,
                         const std::string& nodes = "[{\"mesh\":0}]", const std::string& extra = "") {
  std::vector<uint8_t> bytes(positions.size() * 12 + 8);
  std::memcpy(bytes.data(), positions.data(), positions.size() * 12);
  std::memcpy(bytes.data() + positions.size() * 12, indices.data(), 6);
  return "{\"asset\":{\"version\":\"2.0\"}," + extra + "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":" +
         nodes +
         ",\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
         "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
         "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}],"
         "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
         "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}],"
         "\"buffers\":[{\"byteLength\":" +
         std::to_string(bytes.size()) + ",\"uri\":\"data:application/octet-stream;base64," + base64(bytes) + "\"}]}";
}

const std::vector<glm::vec3> kTriangle = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};

class BadScene : public ::testing::Test {
protected:
  std::filesystem::path dir = scratchDirectory("bad-scene");

  void expectRejected(const std::string& name, const std::string& text, const std::string& phrase) {
    std::filesystem::path file = dir / name;
    writeText(file, text);
    Outcome o = renderExpectingFailure(file);
    expectOneErrorLine(o.run, phrase);
    EXPECT_FALSE(std::filesystem::exists(o.output));
  }
};

TEST_F(BadScene, ValidTriangleRenders) {
  // The control case: the same file without the defect renders, so the failures below are
  // caused by the defects.
  std::filesystem::path file = dir / "ok.gltf";
  writeText(file, triangleGltf(kTriangle, {0, 1, 2}));
  std::filesystem::path out = dir / "ok.png";
  RunResult r = runWavepath({"render", file.string(), "-o", out.string(), "--width", "8", "--height", "8", "--spp", "1"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST_F(BadScene, MissingFile) {
  Outcome o = renderExpectingFailure(dir / "does-not-exist.gltf");
  expectOneErrorLine(o.run, "does-not-exist.gltf");
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

TEST_F(BadScene, MalformedJson) { expectRejected("malformed.gltf", "{\"asset\": {\"version\": \"2.0\"", "malformed.gltf"); }

TEST_F(BadScene, TruncatedGlb) {
  std::string json = triangleGltf(kTriangle, {0, 1, 2});
  while (json.size() % 4) json += ' ';
  std::string glb = "glTF";
  auto u32 = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  u32(2);
  u32(uint32_t(12 + 8 + json.size()));
  u32(uint32_t(json.size()));
  u32(0x4E4F534A);  // "JSON"
  glb += json;
  expectRejected("truncated.glb", glb.substr(0, glb.size() / 2), "truncated.glb");
}

TEST_F(BadScene, IndexOutOfRange) { expectRejected("index.gltf", triangleGltf(kTriangle, {0, 1, 7}), "out of range"); }

TEST_F(BadScene, NanPosition) {
  std::vector<glm::vec3> p = kTriangle;
  p[1].y = std::numeric_limits<float>::quiet_NaN();
  expectRejected("nan.gltf", triangleGltf(p, {0, 1, 2}), "finite");
}

TEST_F(BadScene, NodeCycle) {
  expectRejected("cycle.gltf",
                 triangleGltf(kTriangle, {0, 1, 2}, "[{\"mesh\":0,\"children\":[1]},{\"children\":[0]}]"), "cycle");
}

TEST_F(BadScene, UnsupportedRequiredExtension) {
  std::string ext = "\"extensionsUsed\":[\"KHR_materials_pbrSpecularGlossiness\"],"
                    "\"extensionsRequired\":[\"KHR_materials_pbrSpecularGlossiness\"],";
  expectRejected("specgloss.gltf", triangleGltf(kTriangle, {0, 1, 2}, "[{\"mesh\":0}]", ext),
                 "KHR_materials_pbrSpecularGlossiness");
}

TEST_F(BadScene, NothingRenderable) {
  expectRejected("empty.gltf", "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{}]}",
                 "nothing");
}

std::filesystem::path testData(const char* name) { return sourceDirectory() / "tests" / "data" / name; }

TEST(Animation, TheValidAnimatedFilesRender) {
  // The control case of BadAnimation: the files the bad ones are edited from render.
  for (const char* name : {"anim_trs.gltf", "anim_morph.gltf", "anim_skin.gltf"}) {
    std::filesystem::path out = scratchDirectory("animated") / "image.png";
    RunResult r = runWavepath({"render", testData(name).string(), "-o", out.string(), "--time", "0.5", "--width", "8",
                               "--height", "8", "--spp", "1"});
    EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(out)) << name;
  }
}

TEST(BadAnimation, IsOneErrorLineNamingTheDefect) {
  // tools/make_animation_tests.py writes each file with one defect.
  const std::vector<std::pair<const char*, const char*>> cases = {
      {"bad_channel_node.gltf", "channel 0: its target node 99 does not exist"},
      {"bad_input_order.gltf", "sampler 0: input times are not strictly increasing"},
      {"bad_output_count.gltf", "the output has 9 numbers but 2 keyframes of 3 numbers need 6"},
      {"bad_interpolation.gltf", "interpolation 'SMOOTH' is not LINEAR, STEP or CUBICSPLINE"},
      {"bad_morph_count.gltf", "primitive 1 has 1 morph targets but an earlier one 2"},
      {"bad_mesh_weights.gltf", "it has 3 default weights but 2 morph targets"},
      {"bad_weights_count.gltf", "the output has 6 numbers but 2 keyframes of 2 numbers need 4"},
  };
  for (const auto& [name, phrase] : cases) {
    SCOPED_TRACE(name);
    Outcome o = renderExpectingFailure(testData(name), {"--time", "0.5"});
    expectOneErrorLine(o.run, phrase);
    EXPECT_FALSE(std::filesystem::exists(o.output));
  }
}

TEST(BadAnimation, FlagsAreRejected) {
  const std::filesystem::path scene = testData("anim_trs.gltf");
  const std::filesystem::path dir = scratchDirectory("bad-frames");
  const std::string pattern = (dir / "frame_###.png").string();
  for (const std::vector<std::string>& flags : std::vector<std::vector<std::string>>{
           {"--frames", "3..1"},
           {"--frames", "1..x"},
           {"--frames", "-2..4"},
           {"--frames", "0..2", "--fps", "0"},
           {"--frames", "0..2", "--fps", "-24"},
           {"--time", "nan"},
           {"--time", "1", "--frames", "0..2"},
       }) {
    std::vector<std::string> args = {"render", scene.string(), "-o", pattern};
    args.insert(args.end(), flags.begin(), flags.end());
    SCOPED_TRACE(flags[1]);
    expectOneErrorLine(runWavepath(args, {}, 60), "wavepath --help", 2);
  }
  // Several frames into one file would overwrite each other.
  RunResult single =
      runWavepath({"render", scene.string(), "-o", (dir / "frame.png").string(), "--frames", "0..2"}, {}, 60);
  expectOneErrorLine(single, "has no '#' for the frame number");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(BadFlags, AreRejectedWithUsageHint) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"render", scene.string(), "--spp", "0"},
           {"render", scene.string(), "--mode", "guess"},
           {"render", scene.string(), "--width", "abc"},
           {"render", scene.string(), "--no-such-flag"},
           {"render", scene.string(), "--backend", "nonsense"},
           {"render", scene.string(), "--cl-dispatch", "sometimes"},
           {"render"},
           {"teleport"},
       }) {
    RunResult r = runWavepath(args, {}, 60);
    SCOPED_TRACE(args.back());
    expectOneErrorLine(r, "wavepath --help", 2);
  }
}

TEST(BadFlags, ANumberOutOfItsRangeSaysWhatItMustBe) {
  // CLI11's own checks printed the range up to the largest double.
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  for (const auto& [flag, phrase] : std::vector<std::pair<const char*, const char*>>{
           {"--clamp", "--clamp: '-1' must be 0 or more"},
           {"--filter-glossy", "--filter-glossy: '-1' must be 0 or more"},
           {"--focus-distance", "--focus-distance: '-1' must be more than 0"},
       }) {
    SCOPED_TRACE(flag);
    RunResult r = runWavepath({"render", scene.string(), flag, "-1"}, {}, 60);
    expectOneErrorLine(r, phrase, 2);
    EXPECT_EQ(r.err.find("179769"), std::string::npos) << r.err;
  }
}

TEST(BadOutput, MissingDirectoryAndUnknownFormatFailBeforeRendering) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  std::filesystem::path dir = scratchDirectory("bad-output");
  RunResult missing = runWavepath({"render", scene.string(), "-o", (dir / "no" / "such" / "dir.png").string()}, {}, 60);
  expectOneErrorLine(missing, "dir.png");
  RunResult format = runWavepath({"render", scene.string(), "-o", (dir / "image.jpg").string()}, {}, 60);
  expectOneErrorLine(format, "image.jpg");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(NoDevice, MissingVulkanDriverIsOneClearError) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  Outcome o = renderExpectingFailure(scene, {},
                                     {"VK_ICD_FILENAMES=/nonexistent/icd.json", "VK_DRIVER_FILES=/nonexistent/icd.json",
                                      "WAVEPATH_VALIDATION=0"});
  expectOneErrorLine(o.run, "Vulkan");
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

TEST(NoDevice, DeviceIndexOutOfRange) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  Outcome o = renderExpectingFailure(scene, {"--device", "99"});
  expectOneErrorLine(o.run, "wavepath devices");
}

TEST(Devices, ListsTheLavapipeAndPoclDevices) {
  RunResult r = runWavepath({"devices"}, {}, 60);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Vulkan devices:\n  0: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("OpenCL devices:\n  0: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("compute units"), std::string::npos) << r.out;
}

TEST(Devices, ABackendWithoutDevicesIsSaidToHaveNoneAndTheOtherStillListed) {
  RunResult r = runWavepath({"devices"}, {"OCL_ICD_VENDORS=/nonexistent"}, 60);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Vulkan devices:\n  0: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("OpenCL devices:\n  none: no OpenCL platform found"), std::string::npos) << r.out;
}

// --timings says where the whole process went outside the passes (device, scene load, BVH
// and packing, upload, image write), each part measured on its own: the parts inside the
// frame's wall clock (all but the device and the load) cannot add up to more than it.
TEST(Timings, SayWhereTheTimeOutsideThePassesWent) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  std::filesystem::path out = scratchDirectory("timings") / "image.exr";
  RunResult r = runWavepath({"render", scene.string(), "-o", out.string(), "--width", "32", "--height", "32", "--spp",
                             "4", "--timings"},
                            {}, 120);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  double device = -1, load = -1, pack = -1, upload = -1, write = -1;
  const size_t setup = r.out.find("outside the passes (ms): ");
  ASSERT_NE(setup, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.c_str() + setup,
                        "outside the passes (ms): device %lf, scene load %lf, BVH and packing %lf, upload %lf, "
                        "image write %lf",
                        &device, &load, &pack, &upload, &write),
            5)
      << r.out;
  double render = -1, wall = -1;
  const size_t summary = r.out.find(" spp in ");
  ASSERT_NE(summary, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.c_str() + summary, " spp in %lf s (%lf s wall)", &render, &wall), 2) << r.out;
  for (double part : {device, load, pack, upload, write}) {
    EXPECT_GE(part, 0.0) << r.out;
  }
  // The render and the wall clock are printed to 0.01 s, the parts to 0.1 ms.
  EXPECT_LE((pack + upload + write) * 1e-3 + render, wall + 0.011) << r.out;
  EXPECT_GT(write, 0.0) << "an EXR takes some time to write: " << r.out;
}

// The error line is the last line of stderr and the only error; notes (the OpenCL compile)
// and a compiler log may come before it.
void expectErrorAsLastLine(const RunResult& r, const std::string& phrase) {
  EXPECT_EQ(r.exitCode, 1) << r.err;
  std::string err = r.err;
  while (!err.empty() && err.back() == '\n') {
    err.pop_back();
  }
  std::string lastLine = err.substr(err.rfind('\n') == std::string::npos ? 0 : err.rfind('\n') + 1);
  EXPECT_EQ(lastLine.rfind("wavepath: error: ", 0), 0u) << r.err;
  EXPECT_NE(lastLine.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << r.err;
  EXPECT_EQ(err.find("wavepath: error: "), err.rfind("wavepath: error: ")) << "more than one error: " << r.err;
}

TEST(OpenCl, NoPlatformIsOneClearError) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  // ocl-icd reads the vendor ICDs from OCL_ICD_VENDORS instead of /etc/OpenCL/vendors.
  Outcome o = renderExpectingFailure(scene, {"--backend", "opencl"}, {"OCL_ICD_VENDORS=/nonexistent"});
  expectOneErrorLine(o.run, "no OpenCL platform found; install pocl-opencl-icd");
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

TEST(OpenCl, DeviceIndexOutOfRange) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  Outcome o = renderExpectingFailure(scene, {"--backend", "opencl", "--device", "99"});
  expectOneErrorLine(o.run, "OpenCL devices; run 'wavepath devices'");
}

TEST(OpenCl, KernelBuildFailurePrintsTheCompilerLogThenOneErrorLine) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  Outcome o = renderExpectingFailure(scene, {"--backend", "opencl"},
                                     {"WAVEPATH_CL_EXTRA_SOURCE=this is not OpenCL C"});
  expectErrorAsLastLine(o.run, "the OpenCL kernels failed to build");
  // The log names the line the compiler rejected (the source carries #line directives).
  EXPECT_NE(o.run.err.find("WAVEPATH_CL_EXTRA_SOURCE:1:"), std::string::npos) << o.run.err;
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

}  // namespace
}  // namespace wp::test
