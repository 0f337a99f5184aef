// FLIP and HDR-FLIP (host/compare/flip.h), written from the two papers. The arithmetic is in
// single precision, in the order the papers' reference implementation uses, so that the mean
// error agrees with NVIDIA's `flip-evaluator` within 5e-6 (tests/compare/flip_reference).
#include "compare/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace vkrt {

namespace {

constexpr float kPi = 3.14159265358979f;

// The constants of FLIP (HPG 2020): the colour error's exponent qc, the remapping's
// breakpoint pc (a share of the largest colour distance) and the error it maps to, pt; the
// feature detectors' width w (degrees) and the feature error's exponent qf.
constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kFeatureWidthDegrees = 0.082f, kQf = 0.5f;

// The contrast sensitivity of each opponent channel as a filter in the spatial domain:
// a1 sqrt(pi/b1) exp(-pi^2 x^2/b1) + a2 sqrt(pi/b2) exp(-pi^2 x^2/b2), x in degrees (the
// paper's fit of the contrast sensitivity functions). Only the blue-yellow channel's has a second term.
struct Csf {
  float a1, b1, a2, b2;
};
constexpr Csf kCsfAchromatic{1.0f, 0.0047f, 0.0f, 1e-5f};
constexpr Csf kCsfRedGreen{1.0f, 0.0053f, 0.0f, 1e-5f};
constexpr Csf kCsfBlueYellow{34.1f, 0.04f, 13.5f, 0.025f};

// The white point (D65, Y = 1) that YCxCz and L*a*b* are relative to.
constexpr std::array<float, 3> kWhite{0.950428545f, 1.0f, 1.088900371f};

using Rgb = std::array<float, 3>;

// Linear sRGB (D65) to CIE XYZ and back. The forward matrix is the one FLIP uses (as rational
// numbers: image-engineering.de's "How to convert between sRGB and CIE XYZ"); its rows sum to
// kWhite, so that a grey has no chroma at all in YCxCz and L*a*b*. (The textbook matrix's first
// row sums to 0.950456: with it a grey carried a trace of red-green, and where FLIP's colour
// error is tiny, raising it to 1 - feature error made that trace 0.001 of error.)
Rgb linearRgbToXyz(const Rgb& c) {
  return {10135552.0f / 24577794.0f * c[0] + 8788810.0f / 24577794.0f * c[1] + 4435075.0f / 24577794.0f * c[2],
          2613072.0f / 12288897.0f * c[0] + 8788810.0f / 12288897.0f * c[1] + 887015.0f / 12288897.0f * c[2],
          1425312.0f / 73733382.0f * c[0] + 8788810.0f / 73733382.0f * c[1] + 70074185.0f / 73733382.0f * c[2]};
}
Rgb xyzToLinearRgb(const Rgb& c) {
  return {3.241003275f * c[0] - 1.537398934f * c[1] - 0.498615861f * c[2],
          -0.969224334f * c[0] + 1.875930071f * c[1] + 0.041554224f * c[2],
          0.055639423f * c[0] - 0.204011202f * c[1] + 1.057148933f * c[2]};
}

// YCxCz: the linear opponent space of FLIP's spatial filtering (L*a*b*'s formulas without the
// cube root, so that filtering it is filtering light).
Rgb xyzToYcxcz(const Rgb& c) {
  const float x = c[0] / kWhite[0], y = c[1] / kWhite[1], z = c[2] / kWhite[2];
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}
Rgb ycxczToXyz(const Rgb& c) {
  const float y = (c[0] + 16.0f) / 116.0f;
  return {(y + c[1] / 500.0f) * kWhite[0], y * kWhite[1], (y - c[2] / 200.0f) * kWhite[2]};
}

// CIE L*a*b* of an XYZ colour.
Rgb xyzToLab(const Rgb& c) {
  constexpr float delta = 6.0f / 29.0f;
  // (powf rather than cbrtf: glibc's cbrtf took a fifth of FLIP's time, its powf a third of that)
  auto f = [&](float t) {
    return t > delta * delta * delta ? std::pow(t, 1.0f / 3.0f) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
  };
  const float fx = f(c[0] / kWhite[0]), fy = f(c[1] / kWhite[1]), fz = f(c[2] / kWhite[2]);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// The Hunt effect: chroma is seen less at low luminance, so a* and b* are scaled by L*/100.
Rgb huntAdjusted(const Rgb& lab) { return {lab[0], 0.01f * lab[0] * lab[1], 0.01f * lab[0] * lab[2]}; }

// HyAB: city-block distance in L*, Euclidean in the chromatic plane.
float hyab(const Rgb& a, const Rgb& b) {
  return std::fabs(a[0] - b[0]) + std::sqrt((a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The largest colour distance FLIP expects, between pure green and pure blue, raised to qc.
float maxColorDistance() {
  Rgb green = huntAdjusted(xyzToLab(linearRgbToXyz({0.0f, 1.0f, 0.0f})));
  Rgb blue = huntAdjusted(xyzToLab(linearRgbToXyz({0.0f, 0.0f, 1.0f})));
  return std::pow(hyab(green, blue), kQc);
}

float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

using Plane = std::vector<float>;

// A 1-D filter of odd width, centred.
using Kernel = std::vector<float>;

// Convolution along rows or along columns, the image's edge pixels repeated beyond it.
// Each output sums its taps in the kernel's order; the loops run over a whole row at a time,
// so that the compiler can vectorize them.
Plane convolve(const Plane& src, int width, int height, const Kernel& k, bool alongRows) {
  const std::size_t w = static_cast<std::size_t>(width);
  Plane out(src.size(), 0.0f);
  const int r = static_cast<int>(k.size()) / 2;
  if (alongRows) {
    std::vector<float> padded(w + 2 * static_cast<std::size_t>(r));
    for (int y = 0; y < height; ++y) {
      const float* row = src.data() + static_cast<std::size_t>(y) * w;
      for (int x = -r; x < width + r; ++x) padded[static_cast<std::size_t>(x + r)] = row[std::clamp(x, 0, width - 1)];
      float* o = out.data() + static_cast<std::size_t>(y) * w;
      for (std::size_t i = 0; i < k.size(); ++i) {
        const float weight = k[i];
        const float* p = padded.data() + i;
        for (std::size_t x = 0; x < w; ++x) o[x] += weight * p[x];
      }
    }
  } else {
    for (int y = 0; y < height; ++y) {
      float* o = out.data() + static_cast<std::size_t>(y) * w;
      for (int i = -r; i <= r; ++i) {
        const float weight = k[static_cast<std::size_t>(i + r)];
        const float* p = src.data() + static_cast<std::size_t>(std::clamp(y + i, 0, height - 1)) * w;
        for (std::size_t x = 0; x < w; ++x) o[x] += weight * p[x];
      }
    }
  }
  return out;
}

// The spatial filters of the colour pipeline. The achromatic and red-green ones are single
// Gaussians, separable, each normalized to sum 1. The blue-yellow one is a sum of two
// Gaussians, which is not separable: it is filtered as two separable passes whose 1-D kernels
// are the square roots of its terms' weights (so each 2-D term is their outer product), the
// pair scaled together so that the 2-D filter sums to 1.
struct SpatialFilters {
  Kernel achromatic, redGreen, blueYellow1, blueYellow2;
};

SpatialFilters spatialFilters(float ppd) {
  // The radius covers three standard deviations of the widest Gaussian (b = 0.04).
  const float widest = std::max({kCsfAchromatic.b1, kCsfRedGreen.b1, kCsfBlueYellow.b1, kCsfBlueYellow.b2});
  const int radius = static_cast<int>(std::ceil(3.0f * std::sqrt(widest / (2.0f * kPi * kPi)) * ppd));
  const std::size_t width = static_cast<std::size_t>(2 * radius + 1);
  SpatialFilters f{Kernel(width), Kernel(width), Kernel(width), Kernel(width)};
  auto term = [](float x2, float a, float b) { return a * std::sqrt(kPi / b) * std::exp(-kPi * kPi * x2 / b); };
  auto rootTerm = [](float x2, float a, float b) {
    return std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x2 / b);
  };
  float sumY = 0, sumCx = 0, sum1 = 0, sum2 = 0;
  for (std::size_t i = 0; i < width; ++i) {
    const float xDegrees = static_cast<float>(static_cast<int>(i) - radius) / ppd;
    const float x2 = xDegrees * xDegrees;
    sumY += f.achromatic[i] = term(x2, kCsfAchromatic.a1, kCsfAchromatic.b1);
    sumCx += f.redGreen[i] = term(x2, kCsfRedGreen.a1, kCsfRedGreen.b1);
    sum1 += f.blueYellow1[i] = rootTerm(x2, kCsfBlueYellow.a1, kCsfBlueYellow.b1);
    sum2 += f.blueYellow2[i] = rootTerm(x2, kCsfBlueYellow.a2, kCsfBlueYellow.b2);
  }
  const float byScale = 1.0f / std::sqrt(sum1 * sum1 + sum2 * sum2);
  for (std::size_t i = 0; i < width; ++i) {
    f.achromatic[i] /= sumY;
    f.redGreen[i] /= sumCx;
    f.blueYellow1[i] *= byScale;
    f.blueYellow2[i] *= byScale;
  }
  return f;
}

// The feature detectors: a Gaussian of standard deviation w/2 degrees and its first and second
// derivatives, three deviations wide. The Gaussian sums to 1; each derivative's positive
// weights sum to 1 and its negative ones to -1.
struct FeatureFilters {
  Kernel gauss, first, second;
};

FeatureFilters featureFilters(float ppd) {
  const float sigma = 0.5f * kFeatureWidthDegrees * ppd;   // in pixels
  const int radius = static_cast<int>(std::ceil(3.0f * sigma));
  const std::size_t width = static_cast<std::size_t>(2 * radius + 1);
  FeatureFilters f{Kernel(width), Kernel(width), Kernel(width)};
  float sumG = 0, firstPos = 0, firstNeg = 0, secondPos = 0, secondNeg = 0;
  for (std::size_t i = 0; i < width; ++i) {
    const float x = static_cast<float>(static_cast<int>(i) - radius);
    const float g = std::exp(-(x * x) / (2.0f * sigma * sigma));
    const float d1 = -x * g;
    const float d2 = (x * x / (sigma * sigma) - 1.0f) * g;
    f.gauss[i] = g;
    f.first[i] = d1;
    f.second[i] = d2;
    sumG += g;
    (d1 > 0.0f ? firstPos : firstNeg) += std::fabs(d1);
    (d2 > 0.0f ? secondPos : secondNeg) += std::fabs(d2);
  }
  for (std::size_t i = 0; i < width; ++i) {
    f.gauss[i] /= sumG;
    f.first[i] /= f.first[i] > 0.0f ? firstPos : firstNeg;
    f.second[i] /= f.second[i] > 0.0f ? secondPos : secondNeg;
  }
  return f;
}

// One image's share of the colour pipeline: its YCxCz planes filtered by the CSFs, taken back
// to linear RGB and clamped to [0, 1], then to Hunt-adjusted L*a*b*, 3 floats a pixel.
std::vector<Rgb> filteredLab(const std::vector<Rgb>& ycxcz, int width, int height, const SpatialFilters& f) {
  const std::size_t n = ycxcz.size();
  Plane y(n), cx(n), cz(n);
  for (std::size_t i = 0; i < n; ++i) {
    y[i] = ycxcz[i][0];
    cx[i] = ycxcz[i][1];
    cz[i] = ycxcz[i][2];
  }
  auto both = [&](const Plane& p, const Kernel& k) {
    return convolve(convolve(p, width, height, k, true), width, height, k, false);
  };
  Plane fy = both(y, f.achromatic), fcx = both(cx, f.redGreen);
  Plane fcz1 = both(cz, f.blueYellow1), fcz2 = both(cz, f.blueYellow2);
  std::vector<Rgb> lab(n);
  for (std::size_t i = 0; i < n; ++i) {
    Rgb rgb = xyzToLinearRgb(ycxczToXyz({fy[i], fcx[i], fcz1[i] + fcz2[i]}));
    for (float& c : rgb) c = std::clamp(c, 0.0f, 1.0f);
    lab[i] = huntAdjusted(xyzToLab(linearRgbToXyz(rgb)));
  }
  return lab;
}

// One image's edge and point strengths: its luminance (YCxCz's Y scaled to [0, 1]) filtered
// by the first and by the second derivative of the Gaussian in x and y, each the length of
// its (x, y) pair.
void features(const std::vector<Rgb>& ycxcz, int width, int height, const FeatureFilters& f, Plane& edges,
              Plane& points) {
  const std::size_t n = ycxcz.size();
  Plane lum(n);
  for (std::size_t i = 0; i < n; ++i) lum[i] = ycxcz[i][0] / 116.0f + 16.0f / 116.0f;
  Plane gx = convolve(lum, width, height, f.gauss, true);
  Plane d1x = convolve(convolve(lum, width, height, f.first, true), width, height, f.gauss, false);
  Plane d2x = convolve(convolve(lum, width, height, f.second, true), width, height, f.gauss, false);
  Plane d1y = convolve(gx, width, height, f.first, false);
  Plane d2y = convolve(gx, width, height, f.second, false);
  edges.resize(n);
  points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    edges[i] = std::sqrt(d1x[i] * d1x[i] + d1y[i] * d1y[i]);
    points[i] = std::sqrt(d2x[i] * d2x[i] + d2y[i] * d2y[i]);
  }
}

void checkSizes(int aw, int ah, int bw, int bh) {
  if (aw != bw || ah != bh)
    throw std::invalid_argument("image sizes differ: " + std::to_string(aw) + "x" + std::to_string(ah) + " vs " +
                                std::to_string(bw) + "x" + std::to_string(bh));
}

// ACES filmic tone curve as FLIP fits it, x (a channel) to (a x^2 + b x + c) / (d x^2 + e x + f);
// the fit's 0.6 pre-exposure is folded into the coefficients.
constexpr std::array<float, 6> kAces{0.6f * 0.6f * 2.51f, 0.6f * 0.03f, 0.0f, 0.6f * 0.6f * 2.43f, 0.6f * 0.59f, 0.14f};

float aces(float x) {
  return (x * x * kAces[0] + x * kAces[1] + kAces[2]) / (x * x * kAces[3] + x * kAces[4] + kAces[5]);
}

// A channel as HDR-FLIP reads it: NaN as 0, +infinity as the largest half float (and
// -infinity as its negative, which the tone curve and clamp take to 0).
float finiteChannel(float v) {
  if (std::isnan(v)) return 0.0f;
  return std::clamp(v, -65504.0f, 65504.0f);
}

float luminance(const float* rgb) {
  return 0.2126f * finiteChannel(rgb[0]) + 0.7152f * finiteChannel(rgb[1]) + 0.0722f * finiteChannel(rgb[2]);
}

}  // namespace

double flipPixelsPerDegree(double distanceMeters, double widthPixels, double widthMeters) {
  // Pixels per metre at the screen times the metres one degree spans at that distance
  // (tan(x) ~ x for one degree, as the papers take it).
  return distanceMeters * (widthPixels / widthMeters) * (3.14159265358979 / 180.0);
}

FlipMap ldrFlipLinear(const std::vector<float>& testLinear, const std::vector<float>& referenceLinear, int width,
                      int height, double pixelsPerDegree) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (testLinear.size() != n * 3 || referenceLinear.size() != n * 3)
    throw std::invalid_argument("ldrFlipLinear: the images are not width x height x 3 floats");
  FlipMap map;
  map.width = width;
  map.height = height;
  map.error.assign(n, 0.0f);
  // Two equal images filter to equal colours and features everywhere: no error, and nothing
  // to compute (a grade of a class compares many such pairs).
  if (n == 0 || testLinear == referenceLinear) return map;
  const float ppd = static_cast<float>(pixelsPerDegree);
  auto toYcxcz = [&](const std::vector<float>& rgb) {
    std::vector<Rgb> out(n);
    for (std::size_t i = 0; i < n; ++i) {
      Rgb c{std::clamp(rgb[3 * i], 0.0f, 1.0f), std::clamp(rgb[3 * i + 1], 0.0f, 1.0f),
            std::clamp(rgb[3 * i + 2], 0.0f, 1.0f)};
      out[i] = xyzToYcxcz(linearRgbToXyz(c));
    }
    return out;
  };
  const std::vector<Rgb> test = toYcxcz(testLinear), reference = toYcxcz(referenceLinear);

  // Colour pipeline: the distance of the filtered colours, raised to qc and remapped so that
  // distances up to pc of the largest take [0, pt] and the rest (pt, 1].
  const SpatialFilters sf = spatialFilters(ppd);
  const std::vector<Rgb> labTest = filteredLab(test, width, height, sf);
  const std::vector<Rgb> labReference = filteredLab(reference, width, height, sf);
  const float cmax = maxColorDistance(), breakpoint = kPc * cmax;

  // Feature pipeline: the larger of the edge and point differences, over sqrt(2), raised to qf.
  const FeatureFilters ff = featureFilters(ppd);
  Plane edgesTest, pointsTest, edgesReference, pointsReference;
  features(test, width, height, ff, edgesTest, pointsTest);
  features(reference, width, height, ff, edgesReference, pointsReference);

  for (std::size_t i = 0; i < n; ++i) {
    float color = std::pow(hyab(labReference[i], labTest[i]), kQc);
    color = color < breakpoint ? color * (kPt / breakpoint) : kPt + (color - breakpoint) / (cmax - breakpoint) * (1.0f - kPt);
    const float edge = std::fabs(edgesReference[i] - edgesTest[i]);
    const float point = std::fabs(pointsReference[i] - pointsTest[i]);
    const float feature = std::pow(std::max(edge, point) / std::sqrt(2.0f), kQf);
    // Features sharpen the colour error: the larger the feature difference, the nearer
    // the error is raised to 1 (colour^(1 - feature)).
    map.error[i] = std::pow(color, 1.0f - feature);
  }
  return map;
}

FlipMap ldrFlip(const Image& test, const Image& reference, double pixelsPerDegree) {
  checkSizes(test.width, test.height, reference.width, reference.height);
  std::array<float, 256> decode{};
  for (int b = 0; b < 256; ++b) decode[static_cast<std::size_t>(b)] = srgbToLinear(static_cast<float>(b) / 255.0f);
  auto linear = [&](const Image& img) {
    std::vector<float> out(img.rgb.size());
    for (std::size_t i = 0; i < img.rgb.size(); ++i) out[i] = decode[img.rgb[i]];
    return out;
  };
  return ldrFlipLinear(linear(test), linear(reference), test.width, test.height, pixelsPerDegree);
}

FlipExposures hdrFlipExposures(const RadianceImage& reference) {
  // The exposure at which a luminance Y maps to 0.85 by the tone curve: 2^e Y = x, where x is
  // the larger root of (a - t d) x^2 + (b - t e) x + (c - t f) = 0.
  const double t = 0.85;
  const double qa = kAces[0] - t * kAces[3], qb = kAces[1] - t * kAces[4], qc = kAces[2] - t * kAces[5];
  const double half = -0.5 * qb / qa;
  const double xMax = half + std::sqrt(half * half - qc / qa);

  const std::size_t n = static_cast<std::size_t>(reference.width) * static_cast<std::size_t>(reference.height);
  std::vector<float> lum(n);
  float yMax = 0.0f;
  for (std::size_t i = 0; i < n; ++i) {
    lum[i] = luminance(reference.rgb.data() + 3 * i);
    yMax = std::max(yMax, lum[i]);
  }
  FlipExposures e;
  if (n == 0 || !(yMax > 0.0f)) {
    e.count = 1;   // nothing lit: the images as they are, once
    return e;
  }
  auto median = [](std::vector<float>& v) {
    auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
  };
  float yMedian = median(lum);
  if (!(yMedian > 0.0f)) {
    std::vector<float> lit;
    for (float y : lum)
      if (y > 0.0f) lit.push_back(y);
    yMedian = median(lit);
  }
  e.start = std::log2(xMax / yMax);
  e.stop = std::log2(xMax / yMedian);
  e.count = static_cast<int>(std::max(2.0, std::ceil(e.stop - e.start)));
  return e;
}

FlipMap hdrFlip(const RadianceImage& test, const RadianceImage& reference, FlipExposures* exposures,
                double pixelsPerDegree) {
  checkSizes(test.width, test.height, reference.width, reference.height);
  FlipExposures e = exposures && exposures->count > 0 ? *exposures : hdrFlipExposures(reference);
  if (exposures) *exposures = e;
  FlipMap result;
  result.width = test.width;
  result.height = test.height;
  result.error.assign(static_cast<std::size_t>(test.width) * static_cast<std::size_t>(test.height), 0.0f);
  const float start = static_cast<float>(e.start), stop = static_cast<float>(e.stop);
  const float step = e.count > 1 ? (stop - start) / static_cast<float>(e.count - 1) : 0.0f;
  for (int k = 0; k < e.count; ++k) {
    const float scale = std::pow(2.0f, start + static_cast<float>(k) * step);
    auto exposed = [&](const RadianceImage& img) {
      std::vector<float> out(img.rgb.size());
      for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = std::clamp(aces(finiteChannel(img.rgb[i]) * scale), 0.0f, 1.0f);
      return out;
    };
    FlipMap ldr = ldrFlipLinear(exposed(test), exposed(reference), test.width, test.height, pixelsPerDegree);
    for (std::size_t i = 0; i < ldr.error.size(); ++i) result.error[i] = std::max(result.error[i], ldr.error[i]);
  }
  return result;
}

FlipStats flipStats(const FlipMap& map) {
  FlipStats s;
  if (map.error.empty()) return s;
  double sum = 0.0;
  for (float v : map.error) sum += v;
  s.mean = sum / static_cast<double>(map.error.size());
  std::vector<float> values = map.error;
  // Nearest rank: the ceil(p/100 N)-th smallest (1-based).
  auto percentile = [&](double p) {
    const double rank = std::ceil(p / 100.0 * static_cast<double>(values.size()));
    const std::size_t i = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(values.size()))) - 1;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(i), values.end());
    return static_cast<double>(values[i]);
  };
  s.median = percentile(50.0);
  s.p95 = percentile(95.0);
  s.p99 = percentile(99.0);
  s.max = *std::max_element(values.begin(), values.end());
  return s;
}

namespace {

// Matplotlib's magma colour map (Smith and van der Walt, CC0), the one FLIP's error maps use:
// 256 sRGB colours, each channel rounded to 8 bits.
constexpr std::uint8_t kMagma[256][3] = {
    {0, 0, 4}, {1, 0, 5}, {1, 1, 6}, {1, 1, 8}, {2, 1, 9}, {2, 2, 11}, {2, 2, 13}, {3, 3, 15},
    {3, 3, 18}, {4, 4, 20}, {5, 4, 22}, {6, 5, 24}, {6, 5, 26}, {7, 6, 28}, {8, 7, 30}, {9, 7, 32},
    {10, 8, 34}, {11, 9, 36}, {12, 9, 38}, {13, 10, 41}, {14, 11, 43}, {16, 11, 45}, {17, 12, 47}, {18, 13, 49},
    {19, 13, 52}, {20, 14, 54}, {21, 14, 56}, {22, 15, 59}, {24, 15, 61}, {25, 16, 63}, {26, 16, 66}, {28, 16, 68},
    {29, 17, 71}, {30, 17, 73}, {32, 17, 75}, {33, 17, 78}, {34, 17, 80}, {36, 18, 83}, {37, 18, 85}, {39, 18, 88},
    {41, 17, 90}, {42, 17, 92}, {44, 17, 95}, {45, 17, 97}, {47, 17, 99}, {49, 17, 101}, {51, 16, 103}, {52, 16, 105},
    {54, 16, 107}, {56, 16, 108}, {57, 15, 110}, {59, 15, 112}, {61, 15, 113}, {63, 15, 114}, {64, 15, 116}, {66, 15, 117},
    {68, 15, 118}, {69, 16, 119}, {71, 16, 120}, {73, 16, 120}, {74, 16, 121}, {76, 17, 122}, {78, 17, 123}, {79, 18, 123},
    {81, 18, 124}, {82, 19, 124}, {84, 19, 125}, {86, 20, 125}, {87, 21, 126}, {89, 21, 126}, {90, 22, 126}, {92, 22, 127},
    {93, 23, 127}, {95, 24, 127}, {96, 24, 128}, {98, 25, 128}, {100, 26, 128}, {101, 26, 128}, {103, 27, 128}, {104, 28, 129},
    {106, 28, 129}, {107, 29, 129}, {109, 29, 129}, {110, 30, 129}, {112, 31, 129}, {114, 31, 129}, {115, 32, 129}, {117, 33, 129},
    {118, 33, 129}, {120, 34, 129}, {121, 34, 130}, {123, 35, 130}, {124, 35, 130}, {126, 36, 130}, {128, 37, 130}, {129, 37, 129},
    {131, 38, 129}, {132, 38, 129}, {134, 39, 129}, {136, 39, 129}, {137, 40, 129}, {139, 41, 129}, {140, 41, 129}, {142, 42, 129},
    {144, 42, 129}, {145, 43, 129}, {147, 43, 128}, {148, 44, 128}, {150, 44, 128}, {152, 45, 128}, {153, 45, 128}, {155, 46, 127},
    {156, 46, 127}, {158, 47, 127}, {160, 47, 127}, {161, 48, 126}, {163, 48, 126}, {165, 49, 126}, {166, 49, 125}, {168, 50, 125},
    {170, 51, 125}, {171, 51, 124}, {173, 52, 124}, {174, 52, 123}, {176, 53, 123}, {178, 53, 123}, {179, 54, 122}, {181, 54, 122},
    {183, 55, 121}, {184, 55, 121}, {186, 56, 120}, {188, 57, 120}, {189, 57, 119}, {191, 58, 119}, {192, 58, 118}, {194, 59, 117},
    {196, 60, 117}, {197, 60, 116}, {199, 61, 115}, {200, 62, 115}, {202, 62, 114}, {204, 63, 113}, {205, 64, 113}, {207, 64, 112},
    {208, 65, 111}, {210, 66, 111}, {211, 67, 110}, {213, 68, 109}, {214, 69, 108}, {216, 69, 108}, {217, 70, 107}, {219, 71, 106},
    {220, 72, 105}, {222, 73, 104}, {223, 74, 104}, {224, 76, 103}, {226, 77, 102}, {227, 78, 101}, {228, 79, 100}, {229, 80, 100},
    {231, 82, 99}, {232, 83, 98}, {233, 84, 98}, {234, 86, 97}, {235, 87, 96}, {236, 88, 96}, {237, 90, 95}, {238, 91, 94},
    {239, 93, 94}, {240, 95, 94}, {241, 96, 93}, {242, 98, 93}, {242, 100, 92}, {243, 101, 92}, {244, 103, 92}, {244, 105, 92},
    {245, 107, 92}, {246, 108, 92}, {246, 110, 92}, {247, 112, 92}, {247, 114, 92}, {248, 116, 92}, {248, 118, 92}, {249, 120, 93},
    {249, 121, 93}, {249, 123, 93}, {250, 125, 94}, {250, 127, 94}, {250, 129, 95}, {251, 131, 95}, {251, 133, 96}, {251, 135, 97},
    {252, 137, 97}, {252, 138, 98}, {252, 140, 99}, {252, 142, 100}, {252, 144, 101}, {253, 146, 102}, {253, 148, 103}, {253, 150, 104},
    {253, 152, 105}, {253, 154, 106}, {253, 155, 107}, {254, 157, 108}, {254, 159, 109}, {254, 161, 110}, {254, 163, 111}, {254, 165, 113},
    {254, 167, 114}, {254, 169, 115}, {254, 170, 116}, {254, 172, 118}, {254, 174, 119}, {254, 176, 120}, {254, 178, 122}, {254, 180, 123},
    {254, 182, 124}, {254, 183, 126}, {254, 185, 127}, {254, 187, 129}, {254, 189, 130}, {254, 191, 132}, {254, 193, 133}, {254, 194, 135},
    {254, 196, 136}, {254, 198, 138}, {254, 200, 140}, {254, 202, 141}, {254, 204, 143}, {254, 205, 144}, {254, 207, 146}, {254, 209, 148},
    {254, 211, 149}, {254, 213, 151}, {254, 215, 153}, {254, 216, 154}, {253, 218, 156}, {253, 220, 158}, {253, 222, 160}, {253, 224, 161},
    {253, 226, 163}, {253, 227, 165}, {253, 229, 167}, {253, 231, 169}, {253, 233, 170}, {253, 235, 172}, {252, 236, 174}, {252, 238, 176},
    {252, 240, 178}, {252, 242, 180}, {252, 244, 182}, {252, 246, 184}, {252, 247, 185}, {252, 249, 187}, {252, 251, 189}, {252, 253, 191},
};

}  // namespace

Image flipMagmaImage(const FlipMap& map) {
  Image out(map.width, map.height);
  for (std::size_t i = 0; i < map.error.size(); ++i) {
    const float e = std::isfinite(map.error[i]) ? std::clamp(map.error[i], 0.0f, 1.0f) : 1.0f;
    const std::uint8_t* c = kMagma[static_cast<int>(e * 255.0f + 0.5f)];
    std::copy(c, c + 3, out.rgb.data() + 3 * i);
  }
  return out;
}

std::string flipStatsText(const FlipStats& s) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "mean %.4f, median %.4f, p95 %.4f, p99 %.4f, max %.4f", s.mean, s.median, s.p95,
                s.p99, s.max);
  return buf;
}

}  // namespace vkrt
