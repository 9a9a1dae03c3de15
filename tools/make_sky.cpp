// wavepath-make-sky: writes a clear daytime sky with a sun as an equirectangular Radiance
// .hdr in the frame of shaders/common/environment.h: the Preetham et al. sky, the sun's disc
// seen through the same atmosphere, and a grey Lambertian ground below the horizon.
//
// Model and units:
// - Sky: Preetham, Shirley & Smits 1999, "A practical analytic model for daylight", appendix
//   A.2: luminance Y and chromaticity (x, y) from the Perez et al. sky distribution, whose
//   coefficients are linear in turbidity T, scaled by the zenith values fitted in T and the
//   sun's zenith angle. Fitted for 2 <= T <= 10 and the sun above the horizon.
// - Sun: a disc 0.53 degrees across (the Sun's mean angular diameter) radiating as a 5778 K
//   black body, the Sun's effective temperature; that gives 1.35 kW/m^2 at normal incidence
//   above the atmosphere, within 1% of the solar constant. It is attenuated along the
//   relative air mass of appendix A.1 by Rayleigh scattering (0.008735 lambda^-4.08) and by
//   haze after Angstrom (beta = 0.04608 T - 0.04586, alpha = 1.3), lambda in micrometres.
//   Ozone, water vapour and mixed-gas absorption, a few percent of visible light, are left
//   out, as is limb darkening.
// - Colour: spectra are weighed by the CIE 1931 2-degree colour matching functions in the
//   multi-lobe fit of Wyman, Sloan & Shirley 2013 (JCGT 2(2)), 683 lm/W; xyY and XYZ become
//   linear Rec. 709 / sRGB primaries (D65), negative components clipped.
// - Units: rgb whose Rec. 709 luminance is the luminance in cd/m^2, the units the physical
//   camera's exposure (shaders/common/exposure.h) expects: a clear zenith is a few thousand,
//   the sun about 1e9.
// - Ground: radiance albedo / pi times the illuminance of the horizontal plane by the sun and
//   the sky (neither shadowed), as a flat world to the horizon would send.
// - Texels hold the mean radiance over their solid angle (4 x 4 sin(theta)-weighted samples).
//   The sun is smaller than a texel below about 2000 texels across, so its texels get its
//   flux, L_sun times the solid angle of the disc, shared in proportion to how much of each
//   texel it covers: the irradiance it gives is right at any resolution.
// The shipped assets/sky.hdr is the default: `wavepath-make-sky -o assets/sky.hdr` (512 x 256,
// T = 3, the sun 35 degrees up at bearing 210, behind and to the left of a default camera).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>
#include <stb_image_write.h>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSunDiameterDegrees = 0.53;
constexpr double kSunTemperature = 5778.0;  // K
constexpr double kMaxLuminousEfficacy = 683.0;  // lm/W
constexpr int kSupersampling = 4;  // per texel side, for the sky
constexpr int kSunSupersampling = 64;  // per texel side, for the sun's coverage

double radians(double degrees) { return degrees * kPi / 180.0; }

// XYZ to linear sRGB (IEC 61966-2-1: Rec. 709 primaries, D65 white).
glm::dvec3 xyzToRgb(glm::dvec3 c) {
  glm::dvec3 rgb(3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
                 -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
                 0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z);
  return glm::max(rgb, glm::dvec3(0.0));
}

// One lobe of the Wyman-Sloan-Shirley fit: a Gaussian with different widths either side.
double lobe(double lambda, double mu, double sigmaBelow, double sigmaAbove) {
  double t = (lambda - mu) / (lambda < mu ? sigmaBelow : sigmaAbove);
  return std::exp(-0.5 * t * t);
}

// CIE 1931 2-degree colour matching functions at `lambda` nm (Wyman et al. 2013, multi-lobe).
glm::dvec3 cieXyz(double lambda) {
  return {1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7) -
              0.065 * lobe(lambda, 501.1, 20.4, 26.2),
          0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1),
          1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8)};
}

// Planck's law: spectral radiance of a black body, W / (m^2 sr nm), at `lambda` nm.
double planck(double lambda, double temperature) {
  const double h = 6.62607015e-34, c = 2.99792458e8, k = 1.380649e-23;
  double l = lambda * 1e-9;
  return 2.0 * h * c * c / (l * l * l * l * l) / (std::exp(h * c / (l * k * temperature)) - 1.0) * 1e-9;
}

// Relative optical air mass towards a sun `zenith` radians from the zenith (Preetham A.1,
// after Kasten 1966): 1 overhead, about 38 at the horizon.
double airMass(double zenith) {
  return 1.0 / (std::cos(zenith) + 0.15 * std::pow(93.885 - zenith * 180.0 / kPi, -1.253));
}

struct Sun {
  glm::dvec3 direction;  // unit, towards the sun
  glm::dvec3 radiance;   // rgb, cd/m^2 by luminance
  double solidAngle;     // of the disc, sr
  double cosRadius;      // cos of its angular radius
};

// The sun's disc as seen from the ground through turbidity T (see the file comment).
Sun makeSun(glm::dvec3 direction, double turbidity) {
  double m = airMass(std::acos(direction.y));
  double beta = 0.04608 * turbidity - 0.04586;
  glm::dvec3 xyz(0.0);
  for (double lambda = 360.0; lambda <= 830.0; lambda += 1.0) {
    double micrometres = lambda * 1e-3;
    double rayleigh = std::exp(-0.008735 * std::pow(micrometres, -4.08) * m);
    double haze = std::exp(-beta * std::pow(micrometres, -1.3) * m);
    xyz += cieXyz(lambda) * (planck(lambda, kSunTemperature) * rayleigh * haze);
  }
  double radius = radians(0.5 * kSunDiameterDegrees);
  Sun sun;
  sun.direction = direction;
  sun.radiance = xyzToRgb(xyz * kMaxLuminousEfficacy);
  sun.cosRadius = std::cos(radius);
  sun.solidAngle = 2.0 * kPi * (1.0 - sun.cosRadius);
  return sun;
}

// The Preetham sky for a sun `sunZenith` radians from the zenith and turbidity T.
class PreethamSky {
public:
  PreethamSky(double sunZenith, double turbidity) : sunZenith_(sunZenith) {
    double t = turbidity, s = sunZenith, s2 = s * s, s3 = s2 * s;
    perezY_ = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
               -0.0670 * t + 0.3703};
    perezX_ = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
               -0.0033 * t + 0.0452};
    perezYChroma_ = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
                     -0.0109 * t + 0.0529};
    double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * s);
    zenithY_ = 1000.0 * ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192);  // kcd/m^2 to cd/m^2
    zenithX_ = (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s) * t * t +
               (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s + 0.00394) * t +
               (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s + 0.25886);
    zenithYChroma_ = (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s) * t * t +
                     (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s + 0.00516) * t +
                     (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s + 0.26688);
  }

  double zenithLuminance() const { return zenithY_; }

  // Radiance (rgb) towards a view `theta` from the zenith (< pi / 2) and `gamma` from the sun.
  glm::dvec3 radiance(double theta, double gamma) const {
    double luminance = zenithY_ * relative(perezY_, theta, gamma);
    double x = zenithX_ * relative(perezX_, theta, gamma), y = zenithYChroma_ * relative(perezYChroma_, theta, gamma);
    return xyzToRgb({x / y * luminance, luminance, (1.0 - x - y) / y * luminance});
  }

private:
  struct Perez {
    double a, b, c, d, e;
  };

  static double perez(const Perez& p, double theta, double gamma) {
    double cosGamma = std::cos(gamma);
    return (1.0 + p.a * std::exp(p.b / std::cos(theta))) *
           (1.0 + p.c * std::exp(p.d * gamma) + p.e * cosGamma * cosGamma);
  }

  // The distribution relative to the zenith: F(theta, gamma) / F(0, sun zenith).
  double relative(const Perez& p, double theta, double gamma) const {
    return perez(p, theta, gamma) / perez(p, 0.0, sunZenith_);
  }

  double sunZenith_;
  Perez perezY_, perezX_, perezYChroma_;
  double zenithY_, zenithX_, zenithYChroma_;
};

// The direction at map coordinates (u, v), as environmentDirection without rotation.
glm::dvec3 mapDirection(double u, double v) {
  double phi = 2.0 * kPi * (u - 0.5), theta = kPi * v;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

struct Options {
  double elevation = 35.0;  // degrees above the horizon
  double azimuth = 210.0;   // degrees, compass bearing: 0 = -z, 90 = +x
  double turbidity = 3.0;
  double groundAlbedo = 0.2;
  int width = 512;
  std::string output = "sky.hdr";
};

int run(const Options& o) {
  int width = o.width, height = o.width / 2;
  double el = radians(o.elevation), az = radians(o.azimuth);
  glm::dvec3 sunDirection(std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el));
  double sunZenith = 0.5 * kPi - el;
  PreethamSky sky(sunZenith, o.turbidity);
  Sun sun = makeSun(sunDirection, o.turbidity);

  // The sky above the horizon, each texel the sin(theta)-weighted mean of its samples; the
  // ground is filled in once the sky's illuminance is known.
  std::vector<glm::dvec3> texels(size_t(width) * height, glm::dvec3(0.0));
  glm::dvec3 skyIlluminance(0.0);
  for (int y = 0; y < height / 2; ++y)
    for (int x = 0; x < width; ++x) {
      glm::dvec3 sum(0.0);
      double weight = 0.0;
      for (int j = 0; j < kSupersampling; ++j)
        for (int i = 0; i < kSupersampling; ++i) {
          double u = (x + (i + 0.5) / kSupersampling) / width, v = (y + (j + 0.5) / kSupersampling) / height;
          glm::dvec3 d = mapDirection(u, v);
          double gamma = std::acos(std::clamp(glm::dot(d, sunDirection), -1.0, 1.0));
          double w = std::sin(kPi * v);
          sum += w * sky.radiance(kPi * v, gamma);
          weight += w;
        }
      glm::dvec3& texel = texels[size_t(y) * width + x];
      texel = sum / weight;
      double theta0 = kPi * y / height, theta1 = kPi * (y + 1) / height;
      double solidAngle = 2.0 * kPi / width * (std::cos(theta0) - std::cos(theta1));
      skyIlluminance += texel * solidAngle * std::cos(kPi * (y + 0.5) / height);
    }

  glm::dvec3 sunIlluminance = sun.radiance * sun.solidAngle * sunDirection.y;
  glm::dvec3 ground = o.groundAlbedo / kPi * (sunIlluminance + skyIlluminance);
  for (size_t i = size_t(width) * (height / 2); i < texels.size(); ++i) texels[i] = ground;

  // The sun's flux, shared among the texels near it by the solid angle of each that it
  // covers. Texels whose centre is further from the sun than its radius plus a texel's
  // height cannot touch it (a texel is never wider than it is tall in angle).
  double texelAngle = kPi / height, sunRadius = std::acos(sun.cosRadius);
  int reach = 1 + int(std::ceil(sunRadius / texelAngle));
  int cy = int(sunZenith / texelAngle);
  double sampleArea = (2.0 * kPi / width / kSunSupersampling) * (kPi / height / kSunSupersampling);  // in (phi, theta)
  std::vector<std::pair<size_t, double>> covered;
  double coveredTotal = 0.0;
  for (int y = std::max(0, cy - reach); y <= std::min(height / 2 - 1, cy + reach); ++y)
    for (int x = 0; x < width; ++x) {
      glm::dvec3 centre = mapDirection((x + 0.5) / width, (y + 0.5) / height);
      if (std::acos(std::clamp(glm::dot(centre, sunDirection), -1.0, 1.0)) > sunRadius + texelAngle) continue;
      double solidAngle = 0.0;
      for (int j = 0; j < kSunSupersampling; ++j)
        for (int i = 0; i < kSunSupersampling; ++i) {
          double u = (x + (i + 0.5) / kSunSupersampling) / width, v = (y + (j + 0.5) / kSunSupersampling) / height;
          if (glm::dot(mapDirection(u, v), sunDirection) >= sun.cosRadius)
            solidAngle += std::sin(kPi * v) * sampleArea;
        }
      if (solidAngle > 0.0) covered.emplace_back(size_t(y) * width + x, solidAngle);
      coveredTotal += solidAngle;
    }
  for (auto [index, solidAngle] : covered) {
    double y = double(index / width);
    double texelSolidAngle = 2.0 * kPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
    texels[index] += sun.radiance * (sun.solidAngle * solidAngle / coveredTotal / texelSolidAngle);
  }

  std::vector<float> rgb;
  rgb.reserve(texels.size() * 3);
  for (const glm::dvec3& t : texels) {
    rgb.push_back(float(t.x));
    rgb.push_back(float(t.y));
    rgb.push_back(float(t.z));
  }
  if (!stbi_write_hdr(o.output.c_str(), width, height, 3, rgb.data())) {
    std::fprintf(stderr, "wavepath-make-sky: error: cannot write '%s'; check the directory and its permissions\n",
                 o.output.c_str());
    return 1;
  }
  auto luminance = [](glm::dvec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
  std::printf("wrote %s: %dx%d, sun at elevation %.2f, azimuth %.2f degrees, direction (%.4f, %.4f, %.4f)\n",
              o.output.c_str(), width, height, o.elevation, o.azimuth, sunDirection.x, sunDirection.y,
              sunDirection.z);
  std::printf("turbidity %.2f: zenith %.0f cd/m^2, sun %.3g cd/m^2 over %.3g sr\n", o.turbidity,
              sky.zenithLuminance(), luminance(sun.radiance), sun.solidAngle);
  std::printf("horizontal illuminance: sun %.0f lx, sky %.0f lx; ground %.0f cd/m^2 (albedo %.2f)\n",
              luminance(sunIlluminance), luminance(skyIlluminance), luminance(ground), o.groundAlbedo);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"wavepath-make-sky: writes a clear sky with a sun (Preetham et al. 1999) as an equirectangular "
               ".hdr in cd/m^2"};
  Options o;
  app.add_option("-o,--output", o.output, "the .hdr file to write")->capture_default_str();
  app.add_option("--elevation", o.elevation, "sun elevation above the horizon, degrees")
      ->check(CLI::Range(0.5, 90.0))
      ->capture_default_str();
  app.add_option("--azimuth", o.azimuth, "sun bearing, degrees: 0 = -z (the map's middle), 90 = +x")
      ->check(CLI::Range(-360.0, 360.0))
      ->capture_default_str();
  app.add_option("--turbidity", o.turbidity, "haze: 2 very clear, 3 clear, 6 hazy, 10 thin fog")
      ->check(CLI::Range(2.0, 10.0))
      ->capture_default_str();
  app.add_option("--ground-albedo", o.groundAlbedo, "reflectance of the ground below the horizon")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--width", o.width, "texels across; the height is half")
      ->check(CLI::Range(8, 16384))
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "wavepath-make-sky: error: %s; run 'wavepath-make-sky --help' for usage\n", e.what());
    return 2;
  }
  // CLI11's range checks let NaN through (every comparison with it is false).
  for (double value : {o.elevation, o.azimuth, o.turbidity, o.groundAlbedo}) {
    if (std::isnan(value)) {
      std::fprintf(stderr, "wavepath-make-sky: error: an angle, the turbidity or the albedo is NaN; give numbers\n");
      return 2;
    }
  }
  if (o.width % 2 != 0) {
    std::fprintf(stderr, "wavepath-make-sky: error: --width %d is odd; give an even width so the horizon "
                         "falls between rows\n", o.width);
    return 2;
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wavepath-make-sky: internal error: %s\n", e.what());
    return 3;
  }
}
