// End-to-end texture tests on both backends (Vulkan under validation): a Lambertian quad
// under the constant white sky of an emitter-less scene has radiance equal to its albedo,
// so every pixel shows the base colour texture as sampled there: the test checks that a
// known 4x4 texture lands at the right place, with nearest and bilinear filtering, each
// wrap mode and the sRGB decode (from a PNG, and once from a lossless WebP), and that COLOR_0
// multiplies it; as an emissive texture of a black emitter it shows the same way. A normal texture tilts the shading normal as the
// equivalent vertex normals do, in the file's TANGENT frame where there is one; an emissive
// texture on a lamp lights the same in every sampling mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include <stb_image_write.h>
#include <webp/encode.h>

#include "image/image_io.h"
#include "support/gltf_writer.h"
#include "support/image_stats.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

constexpr int kTexels = 4;
constexpr int kPixels = 64;  // the quad fills the image; 8 pixels per texel

struct TextureCase {
  const char* name;
  int wrap;       // glTF sampler wrapS = wrapT
  int magFilter;  // glTF NEAREST 9728 or LINEAR 9729
  bool vertexColor = false;  // COLOR_0 kVertexColor at every vertex (UNSIGNED_BYTE, normalized)
  bool emissive = false;     // the texture is the emissiveTexture of a black emitter instead
  bool webp = false;  // the image is a lossless WebP (EXT_texture_webp, required) instead of a PNG
};

// Exactly representable in 8 bits, so the expected product is exact too.
const glm::vec3 kVertexColor = glm::vec3(51, 102, 204) / 255.0f;

void PrintTo(const TextureCase& c, std::ostream* os) { *os << c.name; }

// Distinct sRGB-encoded colours per texel.
glm::u8vec3 texel(int x, int y) { return glm::u8vec3(30 + 60 * x, 30 + 60 * y, 200 - 40 * x); }

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

glm::vec3 linearTexel(int x, int y) {
  glm::vec3 c = glm::vec3(texel(x, y)) / 255.0f;
  return {srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z)};
}

int wrap(int i, int mode) {
  if (mode == 33071) return std::clamp(i, 0, kTexels - 1);  // CLAMP_TO_EDGE
  int period = mode == 33648 ? 2 * kTexels : kTexels;       // MIRRORED_REPEAT or REPEAT
  int m = ((i % period) + period) % period;
  return m < kTexels ? m : 2 * kTexels - 1 - m;
}

// The expected sample at uv, written independently of texture.h.
glm::vec3 textureAt(const TextureCase& c, glm::vec2 uv) {
  glm::vec2 t = uv * float(kTexels);
  if (c.magFilter == 9728) {
    return linearTexel(wrap(int(std::floor(t.x)), c.wrap), wrap(int(std::floor(t.y)), c.wrap));
  }
  glm::vec2 f = glm::floor(t - 0.5f);
  glm::vec2 a = t - 0.5f - f;
  int x0 = int(f.x), y0 = int(f.y);
  auto at = [&](int x, int y) { return linearTexel(wrap(x, c.wrap), wrap(y, c.wrap)); };
  return (at(x0, y0) * (1 - a.x) + at(x0 + 1, y0) * a.x) * (1 - a.y) +
         (at(x0, y0 + 1) * (1 - a.x) + at(x0 + 1, y0 + 1) * a.x) * a.y;
}

glm::vec3 expected(const TextureCase& c, glm::vec2 uv) {
  return textureAt(c, uv) * (c.vertexColor ? kVertexColor : glm::vec3(1.0f));
}

// A quad in the y = 0 plane over [-1, 1]^2 with uv = (x, z) + 0.5, so uv spans [-0.5, 1.5]
// and the wrap modes show; a camera 2 above it looking down sees exactly the quad, image
// left at -x and image top at -z: pixel (px, py) sees uv = -0.5 + 2 (p + 0.5) / kPixels.
std::filesystem::path writeScene(const TextureCase& c, const std::filesystem::path& dir) {
  std::vector<uint8_t> rgb;
  for (int y = 0; y < kTexels; ++y) {
    for (int x = 0; x < kTexels; ++x) {
      glm::u8vec3 t = texel(x, y);
      rgb.insert(rgb.end(), {t.x, t.y, t.z});
    }
  }
  stbi_write_png((dir / "checker.png").string().c_str(), kTexels, kTexels, 3, rgb.data(), kTexels * 3);
  uint8_t* webp = nullptr;
  const size_t webpSize = WebPEncodeLosslessRGB(rgb.data(), kTexels, kTexels, kTexels * 3, &webp);
  std::ofstream(dir / "checker.webp", std::ios::binary).write(reinterpret_cast<const char*>(webp), std::streamsize(webpSize));
  WebPFree(webp);
  std::vector<float> data = {-1, 0, -1, -0.5f, -0.5f, -1, 0, 1, -0.5f, 1.5f,
                             1,  0, 1,  1.5f,  1.5f,  1,  0, -1, 1.5f, -0.5f};
  std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
  std::vector<uint8_t> bytes(data.size() * 4 + indices.size() * 4 + 16);
  std::memcpy(bytes.data(), data.data(), data.size() * 4);
  std::memcpy(bytes.data() + data.size() * 4, indices.data(), indices.size() * 4);
  for (size_t v = 0; v < 4; ++v) {  // COLOR_0 at byte 104
    const uint8_t color[] = {51, 102, 204, 255};
    std::memcpy(bytes.data() + 104 + 4 * v, color, 4);
  }
  std::string json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
  "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 2, 0], "rotation": [-0.70710678, 0, 0, 0.70710678]}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.927295218, "aspectRatio": 1, "znear": 0.01}}],
  "buffers": [{"byteLength": )" + std::to_string(bytes.size()) +
                     R"(, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 80, "byteStride": 20},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 24},
                  {"buffer": 0, "byteOffset": 104, "byteLength": 16}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"},
                {"bufferView": 2, "componentType": 5121, "normalized": true, "count": 4, "type": "VEC4"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1)" +
                     std::string(c.vertexColor ? R"(, "COLOR_0": 3)" : "") + R"(}, "indices": 2, "material": 0}]}],
  "materials": [{)" + std::string(c.emissive ? R"("pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]},
                 "emissiveFactor": [1, 1, 1], "emissiveTexture": {"index": 0})"
                                            : R"("pbrMetallicRoughness": {"baseColorTexture": {"index": 0}})") +
                     R"(, "doubleSided": true, "extras": {"wavepath": {"bsdf": "lambert"}}}],
  "textures": [{)" + std::string(c.webp ? R"("extensions": {"EXT_texture_webp": {"source": 0}})" : R"("source": 0)") +
                     R"(, "sampler": 0}],
  "images": [{"uri": "checker.)" + std::string(c.webp ? "webp" : "png") + R"("}],)" +
                     (c.webp ? R"("extensionsUsed": ["EXT_texture_webp"], "extensionsRequired": ["EXT_texture_webp"],)" : "") +
                     R"(
  "samplers": [{"magFilter": )" + std::to_string(c.magFilter) +
                     R"(, "wrapS": )" + std::to_string(c.wrap) + R"(, "wrapT": )" + std::to_string(c.wrap) + "}]}";
  std::ofstream(dir / "quad.gltf") << json;
  return dir / "quad.gltf";
}

class TextureRender : public ::testing::TestWithParam<std::tuple<std::string, TextureCase>> {};

TEST_P(TextureRender, QuadShowsTheTextureAsSampled) {
  const auto& [backend, c] = GetParam();
  std::filesystem::path scene = writeScene(c, scratchDirectory(std::string("texture-") + c.name));
  RadianceImage image = renderExr(backend, scene,
                                  {"--width", std::to_string(kPixels), "--height", std::to_string(kPixels), "--spp",
                                   "64", "--mode", "bsdf"});
  ASSERT_EQ(image.mean.size(), size_t(kPixels * kPixels));
  int wrong = 0;
  for (int py = 0; py < kPixels; ++py) {
    for (int px = 0; px < kPixels; ++px) {
      glm::vec2 uv = glm::vec2(-0.5f) + 2.0f * (glm::vec2(px, py) + 0.5f) / float(kPixels);
      glm::vec3 want = expected(c, uv);
      size_t i = size_t(py) * kPixels + px;
      for (int k = 0; k < 3; ++k) {
        // Nearest: every pixel lies inside one texel, exact. Bilinear: the pixel's jittered
        // samples average the (locally bilinear) texture to its value at the pixel centre,
        // within their noise. 6 standard errors, estimated from 64 samples (Student's t
        // with 63 degrees of freedom), leave a 0.1% chance of a false alarm among 12288.
        double tolerance = 1e-4 + 6.0 * std::sqrt(double(image.variance[i][k]));
        if (std::abs(image.mean[i][k] - want[k]) > tolerance && ++wrong <= 5) {
          ADD_FAILURE() << "pixel (" << px << ", " << py << ") channel " << k << ": " << image.mean[i][k]
                        << ", expected " << want[k];
        }
      }
    }
  }
  EXPECT_EQ(wrong, 0);
}

// ---- Normal mapping, tangents and an emissive lamp ---------------------------------------

enum class Tilt { None, NormalTexture, VertexNormal, FileTangent, RotatedUv };

// The quad above (uv = (x, z) + 0.5, so +u is +x and +v is +z), Lambertian, lit by a
// one-sided area light off to the side at +x, out of view. NormalTexture tilts it with a
// 1x1 normal texture, VertexNormal with the same normal as glTF NORMALs: tangent-space
// (x, y, z) is world x T + y B + z N with T = +x, B = -z ("up" in the image), N = +y.
// FileTangent adds NORMAL +y and TANGENT (0, 0, 1, 1), a frame turned by 90 degrees from the
// uv gradient's: T = +z, B = cross(N, T) = +x. RotatedUv gives the uv gradient that frame
// instead, uv = (z + 0.5, 0.5 - x) without TANGENT, so it must render as FileTangent does.
// A texturedLamp's emission is multiplied by a 2x1 texture, white on its half nearer the
// quad (x < 1.5) and black beyond.
std::filesystem::path writeLitQuad(Tilt tilt, bool texturedLamp, const std::filesystem::path& dir) {
  const uint8_t texel[] = {230, 90, 220};
  stbi_write_png((dir / "normal.png").string().c_str(), 1, 1, 3, texel, 3);
  const uint8_t lampTexels[] = {255, 255, 255, 0, 0, 0};
  stbi_write_png((dir / "lamp.png").string().c_str(), 2, 1, 3, lampTexels, 6);
  glm::vec3 local = glm::vec3(texel[0], texel[1], texel[2]) / 255.0f * 2.0f - 1.0f;
  glm::vec3 tilted = glm::normalize(glm::vec3(local.x, local.z, -local.y));
  glm::vec3 world = tilt == Tilt::VertexNormal ? tilted : glm::vec3(0, 1, 0);
  std::vector<float> quad = {-1, 0, -1, -0.5f, -0.5f, -1, 0, 1, -0.5f, 1.5f,
                             1,  0, 1,  1.5f,  1.5f,  1,  0, -1, 1.5f, -0.5f};
  std::vector<float> normals;
  for (int v = 0; v < 4; ++v) normals.insert(normals.end(), {world.x, world.y, world.z});
  // Wound to face down, and off to +z too, so that a wrong bitangent sign shows.
  std::vector<float> lamp = {1, 1.5f, 0.5f, 2, 1.5f, 0.5f, 2, 1.5f, 2, 1, 1.5f, 2};
  std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
  std::vector<float> lampUvs = {0, 0, 1, 0, 1, 1, 0, 1};
  std::vector<float> tangents = {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1};
  std::vector<float> rotatedUvs = {-0.5f, 1.5f, 1.5f, 1.5f, 1.5f, -0.5f, -0.5f, -0.5f};
  std::vector<uint8_t> bytes(80 + 48 + 24 + 48 + 32 + 64 + 32);
  std::memcpy(bytes.data(), quad.data(), 80);
  std::memcpy(bytes.data() + 80, normals.data(), 48);
  std::memcpy(bytes.data() + 128, indices.data(), 24);
  std::memcpy(bytes.data() + 152, lamp.data(), 48);
  std::memcpy(bytes.data() + 200, lampUvs.data(), 32);
  std::memcpy(bytes.data() + 232, tangents.data(), 64);
  std::memcpy(bytes.data() + 296, rotatedUvs.data(), 32);
  std::string attributes = R"("POSITION": 0, "TEXCOORD_0": )" + std::string(tilt == Tilt::RotatedUv ? "7" : "1");
  if (tilt != Tilt::None && tilt != Tilt::NormalTexture) attributes += R"(, "NORMAL": 2)";
  if (tilt == Tilt::FileTangent) attributes += R"(, "TANGENT": 6)";
  bool mapped = tilt == Tilt::NormalTexture || tilt == Tilt::FileTangent || tilt == Tilt::RotatedUv;
  std::string normalTexture = mapped ? R"(, "normalTexture": {"index": 0})" : "";
  std::string lampAttributes = texturedLamp ? R"("POSITION": 4, "TEXCOORD_0": 5)" : R"("POSITION": 4)";
  std::string lampTexture = texturedLamp ? R"(, "emissiveTexture": {"index": 1})" : "";
  std::string json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
  "nodes": [{"mesh": 0}, {"mesh": 1}, {"camera": 0, "translation": [0, 2, 0], "rotation": [-0.70710678, 0, 0, 0.70710678]}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.927295218, "aspectRatio": 1, "znear": 0.01}}],
  "buffers": [{"byteLength": )" + std::to_string(bytes.size()) +
                     R"(, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 80, "byteStride": 20},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 128, "byteLength": 24},
                  {"buffer": 0, "byteOffset": 152, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 200, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 232, "byteLength": 64},
                  {"buffer": 0, "byteOffset": 296, "byteLength": 32}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5125, "count": 6, "type": "SCALAR"},
                {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC3", "min": [1, 1.5, 0.5], "max": [2, 1.5, 2]},
                {"bufferView": 4, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 5, "componentType": 5126, "count": 4, "type": "VEC4"},
                {"bufferView": 6, "componentType": 5126, "count": 4, "type": "VEC2"}],
  "meshes": [{"primitives": [{"attributes": {)" + attributes + R"(}, "indices": 3, "material": 0}]},
             {"primitives": [{"attributes": {)" + lampAttributes + R"(}, "indices": 3, "material": 1}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1]}, "extras": {"wavepath": {"bsdf": "lambert"}})" +
                     normalTexture + R"(},
                {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]}, "emissiveFactor": [1, 1, 1],
                 "extras": {"wavepath": {"bsdf": "lambert"}})" + lampTexture + R"(}],
  "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
  "images": [{"uri": "normal.png"}, {"uri": "lamp.png"}],
  "samplers": [{"magFilter": 9728}]})";
  std::ofstream(dir / "lit.gltf") << json;
  return dir / "lit.gltf";
}

// Lit by its lamp alone: the lamp's emission of 1 only glows by the default-lighting rule,
// which would add a white sky, and a uniform sky hides most of a normal's tilt.
ImageMean renderLitQuad(const std::string& backend, Tilt tilt) {
  std::filesystem::path scene = writeLitQuad(tilt, false, scratchDirectory("normal-map-" + std::to_string(int(tilt))));
  return imageMean(renderExr(backend, scene, {"--width", "32", "--height", "32", "--spp", "64", "--sky", "none"}));
}

class NormalMap : public ::testing::TestWithParam<std::string> {};

// The normal texture and the equivalent vertex normals render the same image mean, and it
// differs clearly from the untilted quad's.
TEST_P(NormalMap, TiltsLikeTheEquivalentVertexNormal) {
  std::vector<ImageMean> means;
  for (Tilt tilt : {Tilt::None, Tilt::NormalTexture, Tilt::VertexNormal}) {
    means.push_back(renderLitQuad(GetParam(), tilt));
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(meanZ(means[1], means[2], c), 4.0) << means[1].mean[c] << " vs " << means[2].mean[c];
    EXPECT_GT(meanZ(means[0], means[1], c), 10.0) << means[0].mean[c] << " vs " << means[1].mean[c];
  }
}

// A TANGENT in the file sets the normal texture's frame: it renders as the uv layout that
// gives the uv gradient that frame, and clearly unlike the uv gradient of its own layout
// (what it would render as if TANGENT were ignored).
TEST_P(NormalMap, FollowsTheFilesTangents) {
  std::vector<ImageMean> means;
  for (Tilt tilt : {Tilt::FileTangent, Tilt::RotatedUv, Tilt::NormalTexture}) {
    means.push_back(renderLitQuad(GetParam(), tilt));
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(meanZ(means[0], means[1], c), 4.0) << means[0].mean[c] << " vs " << means[1].mean[c];
    EXPECT_GT(meanZ(means[0], means[2], c), 10.0) << means[0].mean[c] << " vs " << means[2].mean[c];
  }
}

INSTANTIATE_TEST_SUITE_P(Backend, NormalMap, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

class EmissiveTexture : public ::testing::TestWithParam<std::string> {};

// The quad lit by the half-black lamp renders the same mean with light sampling alone, BSDF
// sampling alone and both: light samples see the texture where they land (without it they
// would find twice the light BSDF samples find), and the MIS weights of lamp hits use the
// light table that light sampling draws from. The lamp's untextured twin must light the
// quad clearly more, or the comparison would not show the texture at all. The lamp alone
// lights it (--sky none: its emission of 1 would otherwise only glow beside a white sky).
TEST_P(EmissiveTexture, LightSamplesSeeTheTextureAsHitsDo) {
  std::filesystem::path dir = scratchDirectory("emissive-lamp");
  std::vector<std::string> base = {"--width", "32", "--height", "32", "--spp", "256", "--sky", "none"};
  std::vector<ImageMean> means;
  std::vector<std::string> names;
  for (const char* mode : {"mis", "nee", "bsdf"}) {
    std::vector<std::string> args = base;
    args.insert(args.end(), {"--mode", mode});
    means.push_back(imageMean(renderExr(GetParam(), writeLitQuad(Tilt::None, true, dir), args)));
    names.push_back(mode);
  }
  expectAgreement(means, names);
  ImageMean untextured = imageMean(renderExr(GetParam(), writeLitQuad(Tilt::None, false, dir), base));
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(meanZ(means[0], untextured, c), 10.0) << means[0].mean[c] << " vs " << untextured.mean[c];
  }
}

INSTANTIATE_TEST_SUITE_P(Backend, EmissiveTexture, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

const TextureCase kCases[] = {
    {"NearestRepeat", 10497, 9728}, {"NearestClamp", 33071, 9728}, {"NearestMirror", 33648, 9728},
    {"LinearRepeat", 10497, 9729},  {"LinearClamp", 33071, 9729}, {"NearestRepeatVertexColor", 10497, 9728, true},
    {"NearestMirrorEmissive", 33648, 9728, false, true}, {"LinearRepeatEmissive", 10497, 9729, false, true},
    {"NearestRepeatWebp", 10497, 9728, false, false, true},
};

std::string caseName(const ::testing::TestParamInfo<std::tuple<std::string, TextureCase>>& info) {
  return std::string(std::get<1>(info.param).name) + "_" + std::get<0>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Textures, TextureRender,
                         ::testing::Combine(::testing::Values(std::string("vulkan"), std::string("opencl")),
                                            ::testing::ValuesIn(kCases)),
                         caseName);

}  // namespace
}  // namespace wp::test
