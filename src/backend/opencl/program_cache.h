// On-disk cache of compiled OpenCL program binaries, so a second run does not recompile.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace wp {

// 64-bit FNV-1a: names cache entries; not a cryptographic hash (the entry also stores its
// whole key, so a collision costs a rebuild, never a wrong binary).
uint64_t fnv1a64(std::string_view text);

class ProgramCache {
public:
  // Where entries live: WAVEPATH_CACHE_DIR, else $XDG_CACHE_HOME/wavepath, else
  // $HOME/.cache/wavepath; empty when none of these is set.
  static std::filesystem::path defaultDirectory();

  // An entry in `directory` for `key`, which must name everything the binary depends on
  // (device, driver version, build options, a hash of the full source).
  ProgramCache(std::filesystem::path directory, std::string key);

  // The stored binary, or an empty vector when there is none or it is unreadable, corrupt
  // or stored under another key: every such case means "build from source".
  std::vector<unsigned char> load() const;
  // Writes the entry through a temporary file and a rename, so readers never see half an
  // entry. Failures are ignored: the cache only saves time.
  void store(const std::vector<unsigned char>& binary) const;

  const std::filesystem::path& file() const { return file_; }

private:
  std::filesystem::path directory_;
  std::string key_;
  std::filesystem::path file_;
};

}  // namespace wp
