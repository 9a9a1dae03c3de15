// wavepath-make-bsdf-tables: integrates single-scattering GGX reflection (ggx_reflection.h)
// and the sheen lobe (sheen.h), the code the GPU runs, into the directional-albedo tables of
// bsdf_table_lookup.h and writes them as shaders/common/bsdf_tables.h.
//
// Rows are perceptual roughness r = j / (N - 1), columns cos(theta_o) = i / (N - 1), N = 32
// (the grazing column is evaluated at cos = 1e-4, its limit within float precision):
// - white: E(cos, r), the albedo with F = 1;
// - schlick: the albedo with F = (1 - i.h)^5, Schlick's weight, so that with F0 the albedo is
//   F0 white + (1 - F0) schlick (Schlick's F is linear in F0);
// - their cosine-weighted hemispherical means E_avg(r) = 2 int E mu dmu, taken exactly over
//   the piecewise-linear interpolation of the column values that the shaders use, so the
//   compensation lobes integrate to what they claim (energy_compensation.h).
// - sheen: the sheen lobe's E(cos, r) with colour 1, its rows sheen roughness j / (N - 1)
//   (below WP_SHEEN_MIN_ALPHA the lobe is clamped there).
// Each GGX entry is the mean sample weight over a stratified 512 x 512 grid of visible
// normals (weights F G2 / G1 are smooth, so the error is below 1e-5); roughness 0 is the
// smooth limit: E = 1 and the Schlick weight itself. Each sheen entry is the integral of
// f cos over a stratified 512 x 512 grid of cosine-distributed directions.
// Usage: wavepath-make-bsdf-tables -o shaders/common/bsdf_tables.h; `bsdf_test` checks the
// committed tables against fresh integrals.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "shaders/common/ggx_reflection.h"
#include "shaders/common/sheen.h"

namespace {

constexpr int kSize = 32;
constexpr int kGrid = 512;

using wp::gpu::vec2;
using wp::gpu::vec3;

double integrate(float roughness, float cosTheta, float f0) {
  if (roughness == 0.0f) {
    return f0 + (1.0f - f0) * wp::gpu::schlickWeight(cosTheta);
  }
  const float alpha = wp::gpu::alphaFromRoughness(roughness);
  const vec3 o(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
  double sum = 0.0;
  for (int a = 0; a < kGrid; ++a) {
    for (int b = 0; b < kGrid; ++b) {
      const vec2 u((a + 0.5f) / kGrid, (b + 0.5f) / kGrid);
      const vec3 wi = wp::gpu::sampleGgxReflection(alpha, o, u);
      const wp::gpu::BsdfEval e = wp::gpu::evalGgxReflection(vec3(f0), 1.0f, alpha, o, wi);
      if (e.pdf > 0.0f) sum += double(e.fCos.x) / double(e.pdf);
    }
  }
  return sum / (double(kGrid) * kGrid);
}

double integrateSheen(float roughness, float cosTheta) {
  const vec3 o(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
  double sum = 0.0;
  for (int a = 0; a < kGrid; ++a) {
    for (int b = 0; b < kGrid; ++b) {
      const vec3 wi = wp::gpu::sampleSheen(vec2((a + 0.5f) / kGrid, (b + 0.5f) / kGrid));
      const wp::gpu::BsdfEval e = wp::gpu::evalSheen(vec3(1.0f), roughness, o, wi);
      if (e.pdf > 0.0f) sum += double(e.fCos.x) / double(e.pdf);
    }
  }
  return sum / (double(kGrid) * kGrid);
}

float cosineOfColumn(int i) { return std::max(1e-4f, float(i) / float(kSize - 1)); }

// 2 int_0^1 E(mu) mu dmu for E linear between the columns at mu_i = i / (N - 1).
double hemisphericalMean(const std::vector<double>& row) {
  const double h = 1.0 / (kSize - 1);
  double sum = 0.0;
  for (int i = 0; i + 1 < kSize; ++i) {
    const double m0 = i * h;
    const double m1 = m0 + h;
    const double slope = (row[i + 1] - row[i]) / h;
    // int_{m0}^{m1} (row[i] + slope (mu - m0)) mu dmu
    sum += row[i] * (m1 * m1 - m0 * m0) / 2 + slope * ((m1 * m1 * m1 - m0 * m0 * m0) / 3 - m0 * (m1 * m1 - m0 * m0) / 2);
  }
  return 2.0 * sum;
}

void writeValues(FILE* out, const std::vector<double>& values, bool last) {
  for (size_t k = 0; k < values.size(); ++k) {
    const bool lineEnd = k % 6 == 5 || k + 1 == values.size();
    const char* separator = last && k + 1 == values.size() ? "\n" : lineEnd ? ",\n" : ",";
    std::fprintf(out, "%s%.7ef%s", k % 6 == 0 ? "  " : " ", values[k], separator);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || std::string(argv[1]) != "-o") {
    std::fprintf(stderr, "usage: wavepath-make-bsdf-tables -o FILE.h\n");
    return 2;
  }
  std::vector<double> white, schlick, whiteMean, schlickMean, sheen;
  for (int j = 0; j < kSize; ++j) {
    const float roughness = float(j) / float(kSize - 1);
    std::vector<double> whiteRow, schlickRow;
    for (int i = 0; i < kSize; ++i) {
      whiteRow.push_back(integrate(roughness, cosineOfColumn(i), 1.0f));
      schlickRow.push_back(integrate(roughness, cosineOfColumn(i), 0.0f));
    }
    white.insert(white.end(), whiteRow.begin(), whiteRow.end());
    schlick.insert(schlick.end(), schlickRow.begin(), schlickRow.end());
    whiteMean.push_back(hemisphericalMean(whiteRow));
    schlickMean.push_back(hemisphericalMean(schlickRow));
    for (int i = 0; i < kSize; ++i) sheen.push_back(integrateSheen(roughness, cosineOfColumn(i)));
  }
  FILE* out = std::fopen(argv[2], "w");
  if (!out) {
    std::fprintf(stderr, "wavepath-make-bsdf-tables: error: cannot write %s\n", argv[2]);
    return 1;
  }
  std::fprintf(out,
               "// Generated by tools/make_bsdf_tables.cpp (wavepath-make-bsdf-tables); do not edit.\n"
               "// Directional albedos read through bsdf_table_lookup.h: of single-scattering GGX reflection,\n"
               "// [0, 1024) with F = 1 and [1024, 2048) with F = Schlick's weight, rows roughness j / 31,\n"
               "// columns cos(theta) i / 31; [2048, 2080) and [2080, 2112) their hemispherical means per\n"
               "// row; [2112, 3136) of the sheen lobe with colour 1, rows sheen roughness j / 31.\n"
               "#ifndef WP_BSDF_TABLES_H\n#define WP_BSDF_TABLES_H\n\n#include \"portable.h\"\n\nWP_BEGIN\n\n"
               "WP_FLOAT_TABLE(kBsdfTables, %d)\n",
               3 * kSize * kSize + 2 * kSize);
  writeValues(out, white, false);
  writeValues(out, schlick, false);
  writeValues(out, whiteMean, false);
  writeValues(out, schlickMean, false);
  writeValues(out, sheen, true);
  std::fprintf(out, "WP_FLOAT_TABLE_END\n\nWP_END\n\n#endif\n");
  return std::fclose(out) == 0 ? 0 : 1;
}
