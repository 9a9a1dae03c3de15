// Program binary cache entries: "WPCLBIN1", the key, the binary and its hash, with every
// length stored so that truncated or altered files are recognised and ignored.
#include "backend/opencl/program_cache.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace wp {
namespace {

constexpr std::string_view kMagic = "WPCLBIN1";

void appendU64(std::string& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) {
    out.push_back(char((v >> (8 * i)) & 0xff));
  }
}

// Reads a little-endian u64 at `pos`, advancing it; false past the end.
bool readU64(const std::string& in, size_t& pos, uint64_t& v) {
  if (in.size() < 8 || pos > in.size() - 8) {
    return false;
  }
  v = 0;
  for (int i = 0; i < 8; ++i) {
    v |= uint64_t(static_cast<unsigned char>(in[pos + i])) << (8 * i);
  }
  pos += 8;
  return true;
}

std::string hex(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(v));
  return text;
}

}  // namespace

uint64_t fnv1a64(std::string_view text) {
  uint64_t hash = 14695981039346656037ull;
  for (char c : text) {
    hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  }
  return hash;
}

std::filesystem::path ProgramCache::defaultDirectory() {
  if (const char* dir = std::getenv("WAVEPATH_CACHE_DIR"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "wavepath";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "wavepath";
  }
  return {};
}

ProgramCache::ProgramCache(std::filesystem::path directory, std::string key)
    : directory_(std::move(directory)), key_(std::move(key)) {
  if (!directory_.empty()) {
    file_ = directory_ / ("opencl-" + hex(fnv1a64(key_)) + ".bin");
  }
}

std::vector<unsigned char> ProgramCache::load() const {
  if (file_.empty()) {
    return {};
  }
  std::ifstream in(file_, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t pos = kMagic.size();
  uint64_t keySize = 0;
  uint64_t binarySize = 0;
  uint64_t hash = 0;
  if (data.compare(0, kMagic.size(), kMagic) != 0 || !readU64(data, pos, keySize) || keySize > data.size() - pos ||
      data.compare(pos, keySize, key_) != 0 || keySize != key_.size()) {
    return {};
  }
  pos += keySize;
  if (!readU64(data, pos, binarySize) || binarySize == 0 || binarySize > data.size() - pos) {
    return {};
  }
  std::string_view binary(data.data() + pos, binarySize);
  pos += binarySize;
  if (!readU64(data, pos, hash) || pos != data.size() || hash != fnv1a64(binary)) {
    return {};
  }
  return std::vector<unsigned char>(binary.begin(), binary.end());
}

void ProgramCache::store(const std::vector<unsigned char>& binary) const {
  if (file_.empty() || binary.empty()) {
    return;
  }
  std::string_view bytes(reinterpret_cast<const char*>(binary.data()), binary.size());
  std::string data(kMagic);
  appendU64(data, key_.size());
  data += key_;
  appendU64(data, bytes.size());
  data += bytes;
  appendU64(data, fnv1a64(bytes));

  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  std::filesystem::path temporary = file_;
  temporary += ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(data.data(), std::streamsize(data.size()));
    if (!out.flush()) {
      out.close();
      std::filesystem::remove(temporary, error);
      return;
    }
  }
  std::filesystem::rename(temporary, file_, error);
  if (error) {
    std::filesystem::remove(temporary, error);
  }
}

}  // namespace wp
