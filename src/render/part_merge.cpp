// Merging parts of a frame: checks that they fit together, then combines them per pixel.
#include "render/part_merge.h"

#include <algorithm>

#include "core/error.h"
#include "render/render_identity.h"

namespace wp {

namespace {

std::string samplesText(const RenderRecord& r) {
  return std::to_string(r.firstSample) + ".." + std::to_string(r.lastSample);
}

std::string regionText(const RenderRecord& r) {
  return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," + std::to_string(r.y1);
}

// The feature passes an image holds, for messages: "albedo, normal, depth" or "none".
std::string passesOf(const RadianceImage& image) {
  std::string names;
  auto add = [&](bool present, const char* name) {
    if (present) names += (names.empty() ? "" : ", ") + std::string(name);
  };
  add(!image.albedo.empty(), "albedo");
  add(!image.normal.empty(), "normal");
  add(!image.depth.empty(), "depth");
  return names.empty() ? "none" : names;
}

// Throws unless `part` is a well-formed piece of the frame `first` belongs to.
void checkPart(const FramePart& part, const FramePart& first) {
  if (!part.image.record)
    throw Error("'" + part.name + "' has no wavepath render record in its header; merge the EXR files that "
                "'wavepath render' wrote");
  const RenderRecord& r = *part.image.record;
  if (part.image.width != r.x1 - r.x0 || part.image.height != r.y1 - r.y0 || part.image.variance.empty())
    throw Error("'" + part.name + "' is " + std::to_string(part.image.width) + "x" +
                std::to_string(part.image.height) + " but its record says region " + regionText(r) +
                " (or it lacks variance.R/G/B); render the part again");
  const RenderRecord& f = *first.image.record;
  auto mismatch = [&](const std::string& what) {
    return Error("'" + part.name + "' is not a part of the same frame as '" + first.name + "': " + what +
                 "; merge parts rendered with the same scene and flags");
  };
  if (r.frameWidth != f.frameWidth || r.frameHeight != f.frameHeight)
    throw mismatch("the frame is " + std::to_string(r.frameWidth) + "x" + std::to_string(r.frameHeight) +
                   " there, " + std::to_string(f.frameWidth) + "x" + std::to_string(f.frameHeight) + " here");
  if (r.samplesPerPixel != f.samplesPerPixel)
    throw mismatch("--spp is " + std::to_string(r.samplesPerPixel) + " there, " +
                   std::to_string(f.samplesPerPixel) + " here");
  const size_t pixels = part.image.mean.size();
  auto fits = [pixels](size_t size) { return size == 0 || size == pixels; };
  if (!fits(part.image.albedo.size()) || !fits(part.image.normal.size()) || !fits(part.image.depth.size()) ||
      !fits(part.image.sampleCount.size()))
    throw Error("'" + part.name + "' has feature passes of another size than its image; render the part again");
  if (passesOf(part.image) != passesOf(first.image))
    throw mismatch("it holds the feature passes " + passesOf(part.image) + ", '" + first.name + "' " +
                   passesOf(first.image) + "; render the parts with the same --passes");
  std::string difference = identityDifference({r.sceneHash, r.settings}, {f.sceneHash, f.settings});
  if (!difference.empty()) throw mismatch(difference);
}

bool overlap(const RenderRecord& a, const RenderRecord& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1 && a.firstSample <= b.lastSample &&
         b.firstSample <= a.lastSample;
}

}  // namespace

RadianceImage mergeParts(const std::vector<FramePart>& parts) {
  if (parts.empty()) throw Error("merge needs at least one part; give the EXR files to merge");
  for (const FramePart& part : parts) checkPart(part, parts.front());
  for (size_t a = 0; a < parts.size(); ++a) {
    for (size_t b = a + 1; b < parts.size(); ++b) {
      const RenderRecord &ra = *parts[a].image.record, &rb = *parts[b].image.record;
      if (overlap(ra, rb))
        throw Error("'" + parts[a].name + "' (samples " + samplesText(ra) + ", region " + regionText(ra) +
                    ") and '" + parts[b].name + "' (samples " + samplesText(rb) + ", region " + regionText(rb) +
                    ") hold the same samples of some pixels; merge each batch and region once");
    }
  }
  // Parts in sample order, so each pixel's parts are combined in the order of its samples.
  std::vector<const FramePart*> ordered;
  for (const FramePart& part : parts) ordered.push_back(&part);
  std::stable_sort(ordered.begin(), ordered.end(), [](const FramePart* a, const FramePart* b) {
    return a->image.record->firstSample < b->image.record->firstSample;
  });

  const RenderRecord& frame = *parts.front().image.record;
  RadianceImage merged;
  merged.width = frame.frameWidth;
  merged.height = frame.frameHeight;
  const size_t pixels = size_t(merged.width) * merged.height;
  merged.mean.assign(pixels, glm::vec3(0.0f));
  merged.variance.assign(pixels, glm::vec3(0.0f));
  const RadianceImage& firstImage = parts.front().image;
  if (!firstImage.albedo.empty()) merged.albedo.assign(pixels, glm::vec3(0.0f));
  if (!firstImage.normal.empty()) merged.normal.assign(pixels, glm::vec3(0.0f));
  if (!firstImage.depth.empty()) merged.depth.assign(pixels, 0.0f);
  if (std::any_of(parts.begin(), parts.end(), [](const FramePart& p) { return !p.image.sampleCount.empty(); }))
    merged.sampleCount.assign(pixels, 0.0f);
  std::vector<const FramePart*> holding;
  for (uint32_t y = 0; y < merged.height; ++y) {
    for (uint32_t x = 0; x < merged.width; ++x) {
      holding.clear();
      uint64_t samples = 0;
      for (const FramePart* part : ordered) {
        const RenderRecord& r = *part->image.record;
        if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) {
          holding.push_back(part);
          samples += r.sampleCount();
        }
      }
      if (samples != frame.samplesPerPixel)
        throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") has " + std::to_string(samples) +
                    " of its " + std::to_string(frame.samplesPerPixel) +
                    " samples in these parts; add the parts that hold the rest");
      // The samples each part holds of the pixel: those of its range, or fewer where adaptive
      // sampling stopped the pixel early (its samples.X).
      auto indexIn = [x, y](const FramePart* part) {
        const RenderRecord& r = *part->image.record;
        return (y - r.y0) * part->image.width + (x - r.x0);
      };
      auto held = [&](const FramePart* part) {
        return part->image.sampleCount.empty() ? double(part->image.record->sampleCount())
                                               : double(part->image.sampleCount[indexIn(part)]);
      };
      double n = 0.0;
      glm::dvec3 sum(0.0);
      for (const FramePart* part : holding) {
        n += held(part);
        sum += held(part) * glm::dvec3(part->image.mean[indexIn(part)]);
      }
      n = std::max(n, 1.0);
      const glm::dvec3 mean = sum / n;
      const size_t out = size_t(y) * merged.width + x;
      // The feature passes: means over all samples, each part's weighted by its samples.
      glm::dvec3 albedo(0.0), normal(0.0);
      double depth = 0.0;
      for (const FramePart* part : holding) {
        const size_t i = indexIn(part);
        const double k = held(part) / n;
        if (!merged.albedo.empty()) albedo += k * glm::dvec3(part->image.albedo[i]);
        if (!merged.normal.empty()) normal += k * glm::dvec3(part->image.normal[i]);
        if (!merged.depth.empty()) depth += k * double(part->image.depth[i]);
      }
      if (!merged.albedo.empty()) merged.albedo[out] = glm::vec3(albedo);
      if (!merged.normal.empty()) merged.normal[out] = glm::vec3(normal);
      if (!merged.depth.empty()) merged.depth[out] = float(depth);
      if (!merged.sampleCount.empty()) merged.sampleCount[out] = float(n);
      glm::dvec3 m2(0.0);
      for (const FramePart* part : holding) {
        const size_t i = indexIn(part);
        const double k = held(part);
        const glm::dvec3 deviation = glm::dvec3(part->image.mean[i]) - mean;
        m2 += glm::dvec3(part->image.variance[i]) * (k * (k - 1.0)) + k * deviation * deviation;
      }
      merged.mean[out] = glm::vec3(mean);
      merged.variance[out] = n > 1.0 ? glm::vec3(m2 / (n * (n - 1.0))) : glm::vec3(0.0f);
    }
  }
  RenderRecord record = frame;
  record.firstSample = 0;
  record.lastSample = frame.samplesPerPixel - 1;
  record.x0 = record.y0 = 0;
  record.x1 = frame.frameWidth;
  record.y1 = frame.frameHeight;
  merged.record = record;
  return merged;
}

}  // namespace wp
