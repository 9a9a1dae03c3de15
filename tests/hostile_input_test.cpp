// Regression tests of issue 16's findings: each hostile file or flag, written here at test
// time as the smallest reproducer, must end with one error line and exit code 1 (files) or 2
// (flags), within a time limit: never a crash, a hang, an internal error or a non-finite image.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <tinyexr.h>

#include "image/image_io.h"
#include "support/gltf_writer.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Generous for a machine under load; a hang (the old .hdr decoder) runs into it.
constexpr int kTimeoutSeconds = 60;

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Renders `scene` (8x8, 1 spp) with `extra` flags, expecting one error line with `phrase` and no image.
void expectRefused(const fs::path& scene, const std::string& phrase, std::vector<std::string> extra = {},
                   int code = 1) {
  const fs::path output = scratchDirectory("out") / "image.png";
  std::vector<std::string> args = {"render", scene.string(), "-o", output.string(), "--width", "8", "--height", "8",
                                   "--spp", "1"};
  args.insert(args.end(), extra.begin(), extra.end());
  expectOneErrorLine(runWavepath(args, {}, kTimeoutSeconds), phrase, code);
  EXPECT_FALSE(fs::exists(output));
}

// A valid one-triangle scene whose buffer is the data: URI of 3 positions and 3 indices; the
// tests change one thing in it.
Json triangleScene() {
  const float positions[] = {0, 0, -1, 1, 0, -1, 0, 1, -1};
  const uint16_t indices[] = {0, 1, 2, 0};
  std::vector<uint8_t> bytes(sizeof(positions) + sizeof(indices));
  std::memcpy(bytes.data(), positions, sizeof(positions));
  std::memcpy(bytes.data() + sizeof(positions), indices, sizeof(indices));
  Json scene = Json::parse(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
    "materials":[{"emissiveFactor":[1,1,1]}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                 {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],
    "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}]})");
  scene["buffers"] = Json::array(
      {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}});
  return scene;
}

fs::path writeScene(const fs::path& dir, const Json& scene, const char* name = "scene.gltf") {
  writeBytes(dir / name, scene.dump());
  return dir / name;
}

TEST(HostileScene, TheUnchangedTriangleRenders) {
  // The control: every scene below differs from this one in one way.
  const fs::path dir = scratchDirectory("hostile-control");
  RunResult r = runWavepath({"render", writeScene(dir, triangleScene()).string(), "-o", (dir / "ok.png").string(),
                             "--width", "8", "--height", "8", "--spp", "1"},
                            {}, kTimeoutSeconds);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "ok.png"));
}

TEST(HostileScene, APositionAccessorIndexOutOfRangeIsAnError) {
  // 2147483648 crashed the Release build: the accessor's count was read before its index was checked.
  const fs::path dir = scratchDirectory("hostile-accessor");
  for (const int64_t index : {int64_t(2147483648), int64_t(7), int64_t(-5)}) {
    SCOPED_TRACE(index);
    Json scene = triangleScene();
    scene["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = index;
    expectRefused(writeScene(dir, scene), "accessor");
  }
}

TEST(HostileScene, AGlbBufferOfByteLengthZeroIsAnError) {
  // tinygltf threw std::out_of_range: exit 3, "internal error".
  Json scene = triangleScene();
  scene["buffers"] = Json::array({{{"byteLength", 0}}});
  std::string json = scene.dump();
  while (json.size() % 4 != 0) json += ' ';
  const std::string chunk(36, '\0');  // any BIN chunk: the buffer declares 0 of its bytes
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string glb = "glTF" + u32(2) + u32(uint32_t(12 + 8 + json.size() + 8 + chunk.size())) +
                          u32(uint32_t(json.size())) + "JSON" + json + u32(uint32_t(chunk.size())) + "BIN" +
                          std::string(1, '\0') + chunk;
  const fs::path file = scratchDirectory("hostile-glb") / "empty-buffer.glb";
  writeBytes(file, glb);
  expectRefused(file, "is empty");
}

TEST(HostileScene, BufferAndImageUrisMustNameRegularFilesOfAFewGiB) {
  // A directory made tinygltf ask for 2^63 bytes (exit 3), a FIFO blocked forever, and a
  // 48 GB file was read whole (exit 3 or worse).
  const fs::path dir = scratchDirectory("hostile-uri");
  fs::create_directories(dir / "folder.bin");
  ASSERT_EQ(::mkfifo((dir / "pipe.bin").c_str(), 0600), 0);
  { std::ofstream(dir / "huge.bin"); }
  fs::resize_file(dir / "huge.bin", 48ull << 30);  // sparse: no disk space is used
  struct Case {
    const char* uri;
    const char* says;
  };
  for (const Case& c : {Case{"folder.bin", "is a directory"}, Case{"pipe.bin", "is not a regular file"},
                        Case{"huge.bin", "more than the 4096 MiB"}}) {
    SCOPED_TRACE(c.uri);
    Json buffer = triangleScene();
    buffer["buffers"][0]["uri"] = c.uri;
    expectRefused(writeScene(dir, buffer), c.says);
    // The same file as the image of a base colour texture.
    Json image = triangleScene();
    image["images"] = Json::array({{{"uri", c.uri}}});
    image["textures"] = Json::array({{{"source", 0}}});
    image["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
    image["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 0;  // any VEC2 would do; refused first
    expectRefused(writeScene(dir, image), c.says);
  }
}

TEST(HostileScene, AnImageBufferViewPastItsBufferIsAnError) {
  // tinygltf hands an image's buffer view to the decoder without checking it against its
  // buffer: fuzz_gltf found the PNG decoder reading past the buffer (ASan heap overflow).
  Json scene = triangleScene();
  scene["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 1000}});
  scene["images"] = Json::array({{{"bufferView", 2}, {"mimeType", "image/png"}}});
  scene["textures"] = Json::array({{{"source", 0}}});
  scene["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  expectRefused(writeScene(scratchDirectory("hostile-image-view"), scene), "reaches past its buffer");
}

TEST(HostileScene, CoordinatesBeyondReachAreRefused) {
  // fuzz_gltf: vertices near the largest float made the BVH builder convert NaN to an integer
  // (UBSan), and would overflow every ray; a node scaled by 1e20 does the same to a sane mesh.
  const fs::path dir = scratchDirectory("hostile-coordinates");
  const float far[] = {0, 0, -1, 3e38f, 0, -1, 0, 1, -1};
  const uint16_t indices[] = {0, 1, 2, 0};
  std::vector<uint8_t> bytes(sizeof(far) + sizeof(indices));
  std::memcpy(bytes.data(), far, sizeof(far));
  std::memcpy(bytes.data() + sizeof(far), indices, sizeof(indices));
  Json vertex = triangleScene();
  vertex["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bytes);
  expectRefused(writeScene(dir, vertex), "is beyond ±1e12");
  Json scaled = triangleScene();
  scaled["nodes"][0]["scale"] = {1e20, 1e20, 1e20};
  expectRefused(writeScene(dir, scaled), "reaches coordinate 1e+20, beyond the ±1e12 scene units", {"--sky", "none"});
}

TEST(HostileScene, EmissionAboveTheRadianceLimitIsAnError) {
  // emissiveStrength 1e39 gave infinite radiance and a NaN variance, with exit 0.
  const fs::path dir = scratchDirectory("hostile-emission");
  Json strength = triangleScene();
  strength["materials"][0]["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e39}}}};
  expectRefused(writeScene(dir, strength), "emission 1e+39");
  Json factor = triangleScene();
  factor["materials"][0]["emissiveFactor"] = {1e30, 0, 0};
  expectRefused(writeScene(dir, factor), "above 1e+12");
}

TEST(HostileScene, ALampBrighterThanAnyRealOneIsAnError) {
  // KHR_lights_punctual intensity 1e37 candela: an image of Inf and NaN, caught as an internal
  // error, before the lamp got the bound emission and skies have.
  Json scene = triangleScene();
  scene["extensionsUsed"] = {"KHR_lights_punctual"};
  scene["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 1e37}}}}}}};
  scene["nodes"].push_back({{"translation", {0.2, 0.2, -0.5}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  scene["scenes"][0]["nodes"].push_back(1);
  expectRefused(writeScene(scratchDirectory("hostile-lamp"), scene), "brighter than any real lamp");
}

TEST(HostileScene, RepeatedWarningsAreFoldedIntoOneLineWithACount) {
  // 1,000 nodes with a scale of 0 printed 1,000 warnings.
  const fs::path dir = scratchDirectory("hostile-warnings");
  Json scene = triangleScene();
  for (int i = 0; i < 1000; ++i) {
    scene["nodes"].push_back({{"mesh", 0}, {"scale", {0, 0, 0}}});
    scene["scenes"][0]["nodes"].push_back(i + 1);
  }
  RunResult r = runWavepath({"render", writeScene(dir, scene).string(), "-o", (dir / "out.png").string(), "--width",
                             "8", "--height", "8", "--spp", "1"},
                            {}, kTimeoutSeconds);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  size_t warnings = 0;
  for (size_t at = r.err.find("wavepath: warning:"); at != std::string::npos; at = r.err.find("wavepath: warning:", at + 1)) {
    ++warnings;
  }
  EXPECT_LE(warnings, 4u) << r.err;
  EXPECT_NE(r.err.find("997 more like that, the last: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("node 1000"), std::string::npos) << r.err;
}

// --- skies ---

class HostileSky : public ::testing::Test {
protected:
  const fs::path dir = scratchDirectory("hostile-sky");
  const fs::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
};

TEST_F(HostileSky, TruncatedExrIsAnError) {
  // tinyexr freed the image when decoding failed and ~ExrHandles freed it again: a double
  // free on every truncation past the offset table.
  RadianceImage image;
  image.width = 16;
  image.height = 8;
  for (uint32_t i = 0; i < image.width * image.height; ++i) image.mean.emplace_back(float(i), 1.0f, 0.5f);
  writeImage(dir / "whole.exr", image);
  const std::string whole = readBytes(dir / "whole.exr");
  for (size_t length = 64; length < whole.size(); length += whole.size() / 8) {
    SCOPED_TRACE(length);
    writeBytes(dir / "cut.exr", whole.substr(0, length));
    expectRefused(scene, "cut.exr", {"--sky", (dir / "cut.exr").string()});
  }
}

// A 2x2 EXR of float B, G and R planes (the order OpenEXR sorts them in) and, with
// `idChannel`, a UINT plane "id" after them, written by tinyexr with `compression`.
void writeSmallExr(const fs::path& path, int compression, bool idChannel) {
  const float red[4] = {1, 2, 3, 4}, green[4] = {0, 0, 0, 0}, blue[4] = {5, 5, 5, 5};
  const uint32_t ids[4] = {7, 7, 9, 9};
  const void* planes[4] = {blue, green, red, ids};
  EXRChannelInfo channels[4] = {};
  std::strcpy(channels[0].name, "B");
  std::strcpy(channels[1].name, "G");
  std::strcpy(channels[2].name, "R");
  std::strcpy(channels[3].name, "id");
  int types[4] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_UINT};
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = idChannel ? 4 : 3;
  header.channels = channels;
  header.pixel_types = types;
  header.requested_pixel_types = types;
  header.compression_type = compression;
  EXRImage image;
  InitEXRImage(&image);
  image.images = reinterpret_cast<unsigned char**>(const_cast<void**>(planes));
  image.width = 2;
  image.height = 2;
  image.num_channels = header.num_channels;
  const char* err = nullptr;
  ASSERT_EQ(SaveEXRImageToFile(&image, &header, path.c_str(), &err), TINYEXR_SUCCESS);
}

TEST_F(HostileSky, PizCompressedExrIsRefused) {
  // tinyexr's PIZ decoder copies what a chunk's header says, past the chunk (fuzz_exr found a
  // heap overflow): wavepath reads no PIZ file, damaged or not. This one is intact.
  writeSmallExr(dir / "piz.exr", TINYEXR_COMPRESSIONTYPE_PIZ, false);
  expectRefused(scene, "PIZ-compressed", {"--sky", (dir / "piz.exr").string()});
}

TEST_F(HostileSky, ExrWithAnIntegerChannelIsRefused) {
  // tinyexr's bound check of a UINT plane is 3 bytes short, so a chunk cut inside one reads
  // past the file (fuzz_exr's long run found it through a channel wavepath does not even
  // use): wavepath reads no file with a UINT channel. This one is intact, and its radiance
  // channels are fine.
  writeSmallExr(dir / "id.exr", TINYEXR_COMPRESSIONTYPE_NONE, true);
  expectRefused(scene, "channel id holds integers", {"--sky", (dir / "id.exr").string()});
  writeSmallExr(dir / "rgb.exr", TINYEXR_COMPRESSIONTYPE_NONE, false);
  RunResult r = runWavepath({"render", scene.string(), "--sky", (dir / "rgb.exr").string(), "-o",
                             (dir / "out.png").string(), "--width", "8", "--height", "8", "--spp", "1"},
                            {}, kTimeoutSeconds);
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST_F(HostileSky, TruncatedHdrOrARunOfZeroIsAnError) {
  // stb_image looped forever on a run length of 0, which is what it reads past the end.
  const std::string whole = readBytes(sourceDirectory() / "assets" / "sky.hdr");
  for (size_t length : {size_t(119), size_t(4096), whole.size() / 2, whole.size() - 1}) {
    SCOPED_TRACE(length);
    writeBytes(dir / "cut.hdr", whole.substr(0, length));
    expectRefused(scene, "cut.hdr", {"--sky", (dir / "cut.hdr").string()});
  }
  std::string zeroRun = whole;
  const size_t pixels = zeroRun.find("+X 512\n") + 7;
  ASSERT_EQ(zeroRun.substr(pixels, 2), "\x02\x02");  // a run-length encoded first row
  zeroRun[pixels + 4] = '\0';  // the first count byte of the first row
  writeBytes(dir / "zero.hdr", zeroRun);
  expectRefused(scene, "a run of 0 pixels", {"--sky", (dir / "zero.hdr").string()});
}

TEST_F(HostileSky, HdrDeclaringMorePixelsThanItHoldsIsRefusedBeforeAllocating) {
  // 118 bytes claiming 16384x8192 took 38 s and 13 GB before their error.
  std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 16384\n";
  header += std::string(118 - header.size(), '\x02');
  writeBytes(dir / "huge.hdr", header);
  expectRefused(scene, "more than its", {"--sky", (dir / "huge.hdr").string()});
}

TEST_F(HostileSky, TheLargestRgbeTexelIsRefused) {
  // RGBE 255,255,255,255 is 1.7e38: finite, but its square is not, so the image had Inf and NaN.
  writeBytes(dir / "bright.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n\xff\xff\xff\xff\x80\x80\x80\x81");
  expectRefused(scene, "above 1e+12, brighter than any real sky", {"--sky", (dir / "bright.hdr").string()});
}

TEST_F(HostileSky, IntensityTimesTheBrightestTexelIsLimited) {
  RadianceImage sun;
  sun.width = 2;
  sun.height = 1;
  sun.mean = {glm::vec3(1e9f), glm::vec3(1.0f)};
  writeImage(dir / "sun.exr", sun);
  expectRefused(scene, "lower --sky-intensity", {"--sky", (dir / "sun.exr").string(), "--sky-intensity", "1e4"});
}

// --- flags ---

// Every option `wavepath <command> --help` lists with a FLOAT value.
std::vector<std::string> floatFlags(const std::string& command) {
  const RunResult help = runWavepath({command, "--help"}, {}, kTimeoutSeconds);
  std::vector<std::string> flags;
  std::istringstream lines(help.out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string flag, type;
    words >> flag >> type;
    const size_t comma = flag.find(',');
    if (comma != std::string::npos) flag = flag.substr(comma + 1);
    if (flag.rfind("--", 0) == 0 && type.rfind("FLOAT", 0) == 0) flags.push_back(flag);
  }
  return flags;
}

TEST(HostileFlags, EveryNumberFlagRefusesWhatIsNotAFiniteFloat) {
  // CLI11's range checks let NaN through: --focus-distance nan gave a black image, --clamp nan
  // was ignored. Every FLOAT flag of both commands is tried, so a new one cannot miss the check.
  const fs::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  for (const char* command : {"render", "view"}) {
    const std::vector<std::string> flags = floatFlags(command);
    EXPECT_GE(flags.size(), 12u) << command;
    for (const std::string& flag : flags) {
      for (const char* value : {"nan", "inf", "-inf", "1e39"}) {
        SCOPED_TRACE(std::string(command) + " " + flag + " " + value);
        const fs::path dir = scratchDirectory("flags");
        std::vector<std::string> args = {command, scene.string(), flag, value};
        if (command == std::string("render")) {
          // Small, so that a flag wrongly accepted costs little before the test fails.
          args.insert(args.end(), {"-o", (dir / "image.png").string(), "--width", "8", "--height", "8", "--spp", "1"});
        }
        expectOneErrorLine(runWavepath(args, {}, kTimeoutSeconds), flag, 2);
        EXPECT_TRUE(fs::is_empty(dir));
      }
    }
  }
}

}  // namespace
}  // namespace wp::test
