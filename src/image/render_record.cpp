// The render record as EXR header attributes, written and read back.
#include "image/render_record.h"


#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "image/exr_writer.h"

namespace wp {

namespace {

HeaderAttribute ints(const char* name, const char* type, std::initializer_list<uint32_t> values) {
  return {name, type, exrBytes<uint32_t>(values)};
}

HeaderAttribute text(const char* name, const std::string& value) {
  return {name, "string", std::vector<unsigned char>(value.begin(), value.end())};
}

std::string displayText(const RenderRecord& r) {
  char text[160];
  char exposure[32] = "auto";
  if (!r.autoExposure) std::snprintf(exposure, sizeof(exposure), "%.9g", double(r.display.exposure));
  std::snprintf(text, sizeof(text), "exposure %s tone %u transfer %u gamma %.9g", exposure, r.display.toneMapper,
                r.display.transfer, double(r.display.gamma));
  return text;
}

// Parses displayText's form into `r`; false when it is not that.
bool parseDisplay(const std::string& text, RenderRecord& r) {
  std::istringstream in(text);
  std::string exposureKey, exposure, toneKey, transferKey, gammaKey;
  if (!(in >> exposureKey >> exposure >> toneKey >> r.display.toneMapper >> transferKey >> r.display.transfer >>
        gammaKey >> r.display.gamma) ||
      exposureKey != "exposure" || toneKey != "tone" || transferKey != "transfer" || gammaKey != "gamma")
    return false;
  r.autoExposure = exposure == "auto";
  if (!r.autoExposure && !(std::istringstream(exposure) >> r.display.exposure)) return false;
  return true;
}

}  // namespace

std::vector<HeaderAttribute> recordAttributes(const RenderRecord& r) {
  return {ints("wavepath.format", "int", {uint32_t(kRenderRecordFormat)}),
          ints("wavepath.frame", "v2i", {r.frameWidth, r.frameHeight}),
          ints("wavepath.spp", "int", {r.samplesPerPixel}),
          ints("wavepath.samples", "v2i", {r.firstSample, r.lastSample}),
          ints("wavepath.region", "box2i", {r.x0, r.y0, r.x1 - 1, r.y1 - 1}),
          text("wavepath.seed", std::to_string(r.seed)),
          text("wavepath.sceneHash", r.sceneHash),
          text("wavepath.settings", r.settings),
          text("wavepath.display", displayText(r))};
}

std::optional<RenderRecord> recordFromAttributes(const std::vector<HeaderAttribute>& attributes,
                                                 const std::string& file) {
  auto find = [&](const char* name) -> const HeaderAttribute* {
    for (const HeaderAttribute& a : attributes)
      if (a.name == name) return &a;
    return nullptr;
  };
  auto damaged = [&](const std::string& name) {
    return Error("'" + file + "': its " + name + " header attribute is missing or damaged; render the part again");
  };
  // The attribute's `count` little-endian ints.
  auto readInts = [&](const char* name, const char* type, size_t count) {
    const HeaderAttribute* a = find(name);
    if (a == nullptr || a->type != type || a->value.size() != 4 * count) throw damaged(name);
    std::vector<uint32_t> values(count);
    for (size_t i = 0; i < count; ++i)
      for (int b = 0; b < 4; ++b) values[i] |= uint32_t(a->value[4 * i + b]) << (8 * b);
    return values;
  };
  auto readText = [&](const char* name) {
    const HeaderAttribute* a = find(name);
    if (a == nullptr || a->type != "string") throw damaged(name);
    return std::string(a->value.begin(), a->value.end());
  };
  if (find("wavepath.format") == nullptr) return std::nullopt;
  const uint32_t format = readInts("wavepath.format", "int", 1)[0];
  if (format > uint32_t(kRenderRecordFormat))
    throw Error("'" + file + "' was written by a newer wavepath (record format " + std::to_string(format) +
                "); merge it with that version");
  RenderRecord r;
  std::vector<uint32_t> frame = readInts("wavepath.frame", "v2i", 2);
  r.frameWidth = frame[0];
  r.frameHeight = frame[1];
  r.samplesPerPixel = readInts("wavepath.spp", "int", 1)[0];
  std::vector<uint32_t> samples = readInts("wavepath.samples", "v2i", 2);
  r.firstSample = samples[0];
  r.lastSample = samples[1];
  std::vector<uint32_t> box = readInts("wavepath.region", "box2i", 4);
  r.x0 = box[0];
  r.y0 = box[1];
  r.x1 = box[2] + 1;
  r.y1 = box[3] + 1;
  const std::string seed = readText("wavepath.seed");
  try {
    size_t used = 0;
    unsigned long value = std::stoul(seed, &used);
    if (used != seed.size() || value > 0xffffffffu) throw damaged("wavepath.seed");
    r.seed = uint32_t(value);
  } catch (const std::logic_error&) {
    throw damaged("wavepath.seed");
  }
  r.sceneHash = readText("wavepath.sceneHash");
  r.settings = readText("wavepath.settings");
  if (!parseDisplay(readText("wavepath.display"), r)) throw damaged("wavepath.display");
  if (r.frameWidth == 0 || r.frameHeight == 0 || r.firstSample > r.lastSample || r.lastSample >= r.samplesPerPixel ||
      r.x0 >= r.x1 || r.y0 >= r.y1 || r.x1 > r.frameWidth || r.y1 > r.frameHeight)
    throw damaged("wavepath.* (inconsistent frame, samples or region)");
  return r;
}

}  // namespace wp
