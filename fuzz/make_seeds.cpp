// Writes the fuzz targets' seed corpora (tools/fuzz runs it): small valid inputs of every kind
// each target reads, made with the project's own assets and writers, so the fuzzers start
// from files that reach deep into the readers; and the flag fuzzer's dictionary, from the
// command line itself.
//   fuzz_seeds SOURCE_DIR OUTPUT_DIR  ->  OUTPUT_DIR/{gltf,texture,hdr,exr,flags}/..., OUTPUT_DIR/flags.dict
#include <stb_image_write.h>
#include <tiny_gltf.h>
#include <tinyexr.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "fuzz_support.h"
#include "image/image_io.h"

namespace fs = std::filesystem;

namespace {

void write(const fs::path& file, const void* data, size_t size) {
  std::ofstream(file, std::ios::binary).write(static_cast<const char*>(data), std::streamsize(size));
}

void write(const fs::path& file, const std::string& text) { write(file, text.data(), text.size()); }

std::vector<uint8_t> encoded(bool jpeg, int width, int height, int channels) {
  std::vector<uint8_t> pixels;
  for (int i = 0; i < width * height * channels; ++i) pixels.push_back(uint8_t(i * 37 + i / 5));
  std::vector<uint8_t> out;
  auto append = [](void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<uint8_t>*>(context);
    bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  if (jpeg) {
    stbi_write_jpg_to_func(append, &out, width, height, channels, pixels.data(), 80);
  } else {
    stbi_write_png_to_func(append, &out, width, height, channels, pixels.data(), width * channels);
  }
  return out;
}

// The project's glTF files as they are, and as .glb (tinygltf's writer).
void gltfSeeds(const fs::path& source, const fs::path& out) {
  std::vector<fs::path> files;
  for (const char* dir : {"assets", "tests/data"}) {
    for (const auto& entry : fs::directory_iterator(source / dir)) {
      if (entry.path().extension() == ".gltf") files.push_back(entry.path());
    }
  }
  for (const fs::path& file : files) {
    fs::copy_file(file, out / file.filename(), fs::copy_options::overwrite_existing);
    tinygltf::TinyGLTF parser;
    tinygltf::Model model;
    std::string err, warn;
    if (!parser.LoadASCIIFromFile(&model, &err, &warn, file.string())) continue;
    std::ostringstream glb;
    if (parser.WriteGltfSceneToStream(&model, glb, false, true)) {
      write(out / (file.stem().string() + ".glb"), glb.str());
    }
  }
  const std::vector<uint8_t> png = encoded(false, 4, 4, 4);
  const std::vector<uint8_t> textured = wp::fuzz::texturedQuadGlb(png.data(), png.size());
  write(out / "textured.glb", textured.data(), textured.size());
}

void textureSeeds(const fs::path& out) {
  for (int channels = 1; channels <= 4; ++channels) {
    const std::vector<uint8_t> png = encoded(false, 5, 3, channels);
    write(out / ("c" + std::to_string(channels) + ".png"), png.data(), png.size());
  }
  for (int channels : {1, 3}) {
    const std::vector<uint8_t> jpeg = encoded(true, 9, 7, channels);
    write(out / ("c" + std::to_string(channels) + ".jpg"), jpeg.data(), jpeg.size());
  }
}

// Flat scanlines (narrower than 8) and run-length encoded ones, with a bright sun.
void hdrSeeds(const fs::path& out) {
  for (const auto& [width, height] : {std::pair(4, 2), std::pair(16, 8)}) {
    std::vector<float> rgb;
    for (int i = 0; i < width * height; ++i) {
      const float sky = 0.5f + float(i % width) / float(width);
      rgb.insert(rgb.end(), {sky, sky, i == width + 1 ? 5e4f : 2.0f * sky});
    }
    stbi_write_hdr((out / ("sky" + std::to_string(width) + ".hdr")).c_str(), width, height, 3, rgb.data());
  }
}

// wavepath's own EXR (ZIP, with variance), and the other compressions and half floats
// tinyexr reads.
void exrSeeds(const fs::path& out) {
  wp::RadianceImage image;
  image.width = 8;
  image.height = 4;
  for (uint32_t i = 0; i < image.width * image.height; ++i) {
    image.mean.emplace_back(float(i), 1.0f / float(i + 1), 0.25f);
    image.variance.emplace_back(0.01f * float(i), 0.0f, 1.0f);
  }
  wp::writeImage(out / "wavepath.exr", image);
  for (const auto& [compression, name] : {std::pair(TINYEXR_COMPRESSIONTYPE_NONE, "none"),
                                          std::pair(TINYEXR_COMPRESSIONTYPE_RLE, "rle"),
                                          std::pair(TINYEXR_COMPRESSIONTYPE_ZIPS, "zips"),
                                          std::pair(TINYEXR_COMPRESSIONTYPE_PIZ, "piz")}) {
    for (int pixelType : {TINYEXR_PIXELTYPE_HALF, TINYEXR_PIXELTYPE_FLOAT}) {
      std::vector<float> planes[3];
      for (int c = 0; c < 3; ++c) {
        for (uint32_t i = 0; i < image.width * image.height; ++i) planes[c].push_back(float(i * (c + 1)) * 0.1f);
      }
      float* pointers[3] = {planes[2].data(), planes[1].data(), planes[0].data()};  // B, G, R
      EXRChannelInfo channels[3] = {};
      std::snprintf(channels[0].name, sizeof(channels[0].name), "B");
      std::snprintf(channels[1].name, sizeof(channels[1].name), "G");
      std::snprintf(channels[2].name, sizeof(channels[2].name), "R");
      int inputTypes[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
      int storedTypes[3] = {pixelType, pixelType, pixelType};
      EXRHeader header;
      InitEXRHeader(&header);
      header.num_channels = 3;
      header.channels = channels;
      header.pixel_types = inputTypes;
      header.requested_pixel_types = storedTypes;
      header.compression_type = compression;
      EXRImage exr;
      InitEXRImage(&exr);
      exr.images = reinterpret_cast<unsigned char**>(pointers);
      exr.width = int(image.width);
      exr.height = int(image.height);
      exr.num_channels = 3;
      const std::string file =
          (out / (std::string(name) + (pixelType == TINYEXR_PIXELTYPE_HALF ? "-half" : "-float") + ".exr")).string();
      const char* err = nullptr;
      if (SaveEXRImageToFile(&exr, &header, file.c_str(), &err) != TINYEXR_SUCCESS) FreeEXRErrorMessage(err);
    }
  }
}

// Command lines, one per file, arguments separated by NUL bytes as fuzz_flags splits them.
void flagSeeds(const fs::path& out) {
  const std::vector<std::vector<std::string>> lines = {
      {"render", "scene.gltf", "-o", "out.png", "--width", "64", "--spp", "16", "--max-depth", "4"},
      {"render", "scene.glb", "-o", "out.exr", "--fstop", "2.8", "--focus-distance", "3", "--focal-length", "50",
       "--aperture-blades", "6"},
      {"render", "scene.gltf", "--shutter", "0.01", "--iso", "400", "--tonemap", "filmic", "--gamma", "2.2"},
      {"render", "scene.gltf", "--ev100", "12", "--auto-exposure", "--clamp", "10", "--mode", "nee"},
      {"render", "scene.gltf", "--sky", "sky.hdr", "--sky-intensity", "2", "--sky-rotation", "90", "--sky-sampling",
       "off"},
      {"render", "scene.gltf", "--frames", "0..10", "--fps", "30", "-o", "frame_###.png"},
      {"render", "scene.gltf", "--time", "1.5", "--backend", "opencl", "--cl-dispatch", "max", "--device", "0"},
      {"render", "scene.gltf", "--light-selection", "solid-angle", "--rr-start", "2", "--seed", "7", "--max-paths",
       "4096", "--widen-roughness", "--fixed-lobe-choice"},
      {"view", "scene.gltf", "--frame-budget", "16", "--frames", "3", "--screenshot", "a.png", "--play", "--loop"},
      {"render", "scene.gltf", "--samples", "0..15", "--region", "0,0,32,16", "--checkpoint", "c.ckpt",
       "--checkpoint-every", "30", "--resume"},
      {"render", "scene.gltf", "--sky-color", "0.1,0.2,0.3", "--camera", "Camera", "--scene", "0", "--sky", "none"},
      {"merge", "a.exr", "b.exr", "-o", "out.exr"},
      {"devices"},
      {"render", "--help"},
  };
  for (size_t i = 0; i < lines.size(); ++i) {
    std::string bytes;
    for (size_t a = 0; a < lines[i].size(); ++a) bytes += (a ? std::string(1, '\0') : "") + lines[i][a];
    write(out / ("line" + std::to_string(i)), bytes);
  }
}

// Every subcommand and flag name, and the words some flags take.
void flagDictionary(const fs::path& file) {
  wp::CommandLine line;
  std::ofstream out(file);
  out << "# wavepath's subcommands and flags (written by fuzz_seeds from the command line itself)\n";
  for (const CLI::App* command : line.app.get_subcommands({})) {
    out << '"' << command->get_name() << "\"\n";
    for (const CLI::Option* option : command->get_options()) {
      for (const std::string& name : option->get_lnames()) out << "\"--" << name << "\"\n";
      for (const std::string& name : option->get_snames()) out << "\"-" << name << "\"\n";
    }
  }
  for (const char* word : {"nan", "inf", "-inf", "1e39", "..", "#", "on", "off", "max", "readback", "vulkan", "opencl",
                           "mis", "nee", "bsdf", "power", "solid-angle", "clamp", "reinhard", "filmic", "aces"}) {
    out << '"' << word << "\"\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_seeds SOURCE_DIR OUTPUT_DIR\n");
    return 2;
  }
  const fs::path source = argv[1], out = argv[2];
  for (const char* target : {"gltf", "texture", "hdr", "exr", "flags"}) fs::create_directories(out / target);
  gltfSeeds(source, out / "gltf");
  textureSeeds(out / "texture");
  hdrSeeds(out / "hdr");
  exrSeeds(out / "exr");
  flagSeeds(out / "flags");
  flagDictionary(out / "flags.dict");
  return 0;
}
