// PNG through libpng and JPEG through libjpeg-turbo, both with their errors caught by setjmp in
// functions that keep no C++ objects of their own, so that a longjmp skips no destructor; WebP
// through libwebp.
#include "image/texture_decoder.h"

#include <png.h>
// jpeglib.h needs FILE and size_t declared first.
#include <cstdio>
#include <jpeglib.h>
#include <webp/decode.h>

#include <csetjmp>
#include <cstring>
#include <string>

#include "core/error.h"
#include "image/image_io.h"

namespace wp {
namespace {

// No format wavepath reads packs an RGBA8 pixel into fewer than 1/4096 of a byte: zlib's best
// ratio is 1032:1, and a JPEG block takes some bits. More pixels than that is a damaged file
// (a bomb), refused before anything is allocated.
constexpr uint64_t kMaxPixelsPerByte = 4096 / 4;
// Lossless WebP packs far more: measured, a uniform 16383x16383 image takes 10 KB, 26000
// pixels a byte (libwebp 1.2.4). Beyond 65536 a file is a bomb.
constexpr uint64_t kMaxWebpPixelsPerByte = 65536;
// Progressive JPEGs from real encoders have about ten scans; thousands of tiny ones make
// libjpeg take quadratic time (libjpeg-turbo's own fuzzers stop at 500).
constexpr int kMaxJpegScans = 500;

// Whether `width` x `height` may be allocated for a file of `fileBytes`; if not, says why in
// `message` (the decoders' frames hold no C++ objects, so this one writes a char array).
bool sizeAllowed(uint64_t width, uint64_t height, size_t fileBytes, char* message, size_t messageSize,
                 uint64_t maxPixelsPerByte = kMaxPixelsPerByte) {
  if (width == 0 || height == 0 || width * height > kMaxImagePixels) {
    std::snprintf(message, messageSize, "it is %llux%llu pixels, empty or more than the %llu wavepath reads",
                  static_cast<unsigned long long>(width), static_cast<unsigned long long>(height),
                  static_cast<unsigned long long>(kMaxImagePixels));
    return false;
  }
  if (width * height > maxPixelsPerByte * fileBytes) {
    std::snprintf(message, messageSize, "it declares %llux%llu pixels, more than its %zu bytes can hold",
                  static_cast<unsigned long long>(width), static_cast<unsigned long long>(height), fileBytes);
    return false;
  }
  return true;
}

// --- PNG ---

struct PngState {
  const uint8_t* bytes;
  size_t size;
  size_t at;
  char message[256];
};

void pngRead(png_structp png, png_bytep out, png_size_t length) {
  auto* state = static_cast<PngState*>(png_get_io_ptr(png));
  if (length > state->size - state->at) png_error(png, "the file ends too early");
  std::memcpy(out, state->bytes + state->at, length);
  state->at += length;
}

void pngError(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof(state->message), "%s", message);
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

// Decodes into `out`; false with state.message set on failure. No C++ objects live in this
// frame: libpng leaves it by longjmp.
bool decodePng(PngState& state, Rgba8Image& out) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, pngError, pngWarning);
  if (png == nullptr) {
    std::snprintf(state.message, sizeof(state.message), "libpng could not start");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, &state, pngRead);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (!sizeAllowed(width, height, state.size, state.message, sizeof(state.message))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  // To 8-bit RGBA as stb_image decoded it: palette and grey to RGB, tRNS to alpha, 16 bits to
  // their high byte, and no gamma correction.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  out.width = width;
  out.height = height;
  out.rgba.assign(size_t(width) * height * 4, 0);
  for (int pass = 0; pass < passes; ++pass) {
    for (png_uint_32 y = 0; y < height; ++y) png_read_row(png, out.rgba.data() + size_t(y) * width * 4, nullptr);
  }
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

// --- JPEG ---

struct JpegState {
  jpeg_error_mgr errors;  // first, so that libjpeg's pointer to it is one to the whole
  jpeg_progress_mgr progress;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void jpegError(j_common_ptr info) {
  auto* state = reinterpret_cast<JpegState*>(info->err);
  info->err->format_message(info, state->message);
  std::longjmp(state->jump, 1);
}

// Corrupt data is only a warning to libjpeg, which then fills in grey: an error here.
void jpegMessage(j_common_ptr info, int level) {
  if (level < 0) jpegError(info);
}

void jpegProgress(j_common_ptr info) {
  auto* decompress = reinterpret_cast<j_decompress_ptr>(info);
  if (decompress->input_scan_number > kMaxJpegScans) {
    auto* state = reinterpret_cast<JpegState*>(info->err);
    std::snprintf(state->message, sizeof(state->message), "it has more than %d scans", kMaxJpegScans);
    std::longjmp(state->jump, 1);
  }
}

// Decodes into `out`; false with state.message set on failure. No C++ objects live in this
// frame: libjpeg leaves it by longjmp.
bool decodeJpeg(const uint8_t* bytes, size_t size, JpegState& state, Rgba8Image& out) {
  jpeg_decompress_struct info;
  info.err = jpeg_std_error(&state.errors);
  state.errors.error_exit = jpegError;
  state.errors.emit_message = jpegMessage;
  if (setjmp(state.jump)) {
    jpeg_destroy_decompress(&info);
    return false;
  }
  jpeg_create_decompress(&info);
  state.progress.progress_monitor = jpegProgress;
  info.progress = &state.progress;
  jpeg_mem_src(&info, bytes, static_cast<unsigned long>(size));
  jpeg_read_header(&info, TRUE);
  if (!sizeAllowed(info.image_width, info.image_height, size, state.message, sizeof(state.message))) {
    jpeg_destroy_decompress(&info);
    return false;
  }
  info.out_color_space = JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  out.width = info.output_width;
  out.height = info.output_height;
  out.rgba.assign(size_t(out.width) * out.height * 4, 0);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out.rgba.data() + size_t(info.output_scanline) * out.width * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return true;
}

// --- WebP ---

void decodeWebp(const uint8_t* bytes, size_t size, Rgba8Image& out) {
  int width = 0;
  int height = 0;
  if (!WebPGetInfo(bytes, size, &width, &height)) throw Error("WebP: the header is damaged");
  char message[160];
  if (!sizeAllowed(uint64_t(width), uint64_t(height), size, message, sizeof(message), kMaxWebpPixelsPerByte)) {
    throw Error(std::string("WebP: ") + message);
  }
  out.width = uint32_t(width);
  out.height = uint32_t(height);
  out.rgba.assign(size_t(width) * size_t(height) * 4, 0);
  if (WebPDecodeRGBAInto(bytes, size, out.rgba.data(), out.rgba.size(), width * 4) == nullptr) {
    throw Error("WebP: the image data is damaged or truncated");
  }
}

}  // namespace

ImageFormat imageFormatOf(const uint8_t* bytes, size_t size) {
  static const uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static const uint8_t kJpeg[3] = {0xff, 0xd8, 0xff};
  static const uint8_t kKtx2[12] = {0xab, 'K', 'T', 'X', ' ', '2', '0', 0xbb, '\r', '\n', 0x1a, '\n'};
  if (size >= 8 && std::memcmp(bytes, kPng, 8) == 0) return ImageFormat::Png;
  if (size >= 3 && std::memcmp(bytes, kJpeg, 3) == 0) return ImageFormat::Jpeg;
  if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0) return ImageFormat::Webp;
  if (size >= 12 && std::memcmp(bytes, kKtx2, 12) == 0) return ImageFormat::Ktx2;
  return ImageFormat::Unknown;
}

Rgba8Image decodeTexture(const uint8_t* bytes, size_t size) {
  Rgba8Image image;
  switch (imageFormatOf(bytes, size)) {
    case ImageFormat::Png: {
      PngState state{bytes, size, 0, {}};
      if (!decodePng(state, image)) throw Error(std::string("PNG: ") + state.message);
      break;
    }
    case ImageFormat::Jpeg: {
      JpegState state{};
      if (!decodeJpeg(bytes, size, state, image)) throw Error(std::string("JPEG: ") + state.message);
      break;
    }
    case ImageFormat::Webp: decodeWebp(bytes, size, image); break;
    case ImageFormat::Ktx2: throw Error("a KTX2 image (KHR_texture_basisu), which wavepath cannot decode");
    case ImageFormat::Unknown: throw Error("not a PNG, JPEG or WebP image");
  }
  return image;
}

}  // namespace wp
