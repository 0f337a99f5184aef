// Grading one image against its reference.
#include "grade/grade_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>


namespace vkrt {

namespace {

constexpr int kRegionCell = 16;         // pixels on a side of the squares joined into regions
constexpr std::size_t kMaxRegions = 24;

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string countAndShare(long long n, long long pixels) {
  return std::to_string(n) + format(" (%.3g%%)", pixels > 0 ? 100.0 * static_cast<double>(n) / static_cast<double>(pixels) : 0.0);
}

// The step above which a pixel fails, for the regions: the smallest --max-pixels-over step,
// else --max-diff, else 0 (any difference); none when only bias and variance judge.
int failingStep(const GradeThresholds& t) {
  if (!t.pixels.pixelsOver.empty()) {
    int s = 255;
    for (const PixelThreshold& p : t.pixels.pixelsOver) s = std::min(s, p.steps);
    return s;
  }
  if (t.pixels.maxDiff >= 0) return t.pixels.maxDiff;
  return t.any() ? -1 : 0;
}

KeyFigure keyFigure(const GradeThresholds& t, const ImageDiff& d, const GraderStats& s, const FlipStats& flip,
                    const BiasTest& bias) {
  KeyFigure k;
  k.label = keyFigureLabel(t);
  if (!t.pixels.pixelsOver.empty()) {
    long long n = d.countOver(t.pixels.pixelsOver.front().steps);
    k.value = static_cast<double>(n), k.text = countAndShare(n, d.pixels);
  } else if (t.pixels.maxDiff >= 0) {
    k.value = d.maxChannelDiff, k.text = std::to_string(d.maxChannelDiff);
  } else if (t.pixels.maxFlip >= 0.0) {
    k.value = flip.mean, k.text = format("%.4f", flip.mean);
  } else if (t.maxVariance) {
    k.value = s.variance, k.text = format("%.4g", s.variance);
  } else if (t.maxBias) {
    k.value = std::fabs(s.bias), k.text = format("%.4g", s.bias);
  } else if (t.maxBiasZ) {
    k.value = bias.worst.z, k.text = format("%.3g", bias.worst.z);
  } else {
    long long n = static_cast<long long>(d.differing.size());
    k.value = static_cast<double>(n), k.text = countAndShare(n, d.pixels);
  }
  return k;
}

// What the square test found: how many squares, the worst one, where and in which channel.
std::string biasFailure(const BiasTest& b, double maxZ) {
  static const char* const kChannels[] = {"red", "green", "blue"};
  const SquareBias& w = b.over.front();
  return std::to_string(b.over.size()) + " of " + std::to_string(3 * b.squares) +
         " squares and channels biased beyond " + format("%g", maxZ) + " standard errors (--max-bias-z): the worst, " +
         kChannels[w.channel] + " in the " + std::to_string(w.square.width()) + "x" + std::to_string(w.square.height()) +
         " square at (" + std::to_string(w.square.x0) + "," + std::to_string(w.square.y0) + "), " +
         format("%+.3g", w.mean) + " levels against a standard error of " + format("%.3g", w.standardError) +
         " (z " + format("%.3g", w.z) + ")";
}

}  // namespace

const char* outcomeName(GradeOutcome o) {
  switch (o) {
    case GradeOutcome::Pass: return "pass";
    case GradeOutcome::Fail: return "fail";
    case GradeOutcome::Missing: return "missing";
    case GradeOutcome::Unreadable: return "unreadable";
  }
  return "?";
}

std::string keyFigureLabel(const GradeThresholds& t) {
  if (!t.pixels.pixelsOver.empty()) return "pixels over " + std::to_string(t.pixels.pixelsOver.front().steps) + "/255";
  if (t.pixels.maxDiff >= 0) return "largest difference (/255)";
  if (t.pixels.maxFlip >= 0.0) return "mean FLIP error";
  if (t.maxVariance) return "variance";
  if (t.maxBias) return "bias";
  if (t.maxBiasZ) return "bias z (largest square)";
  return "pixels that differ";
}

Grade sizeDiffers(int width, int height, int referenceWidth, int referenceHeight, const GradeThresholds& t) {
  Grade g;
  g.width = width, g.height = height;
  g.key.label = keyFigureLabel(t);
  g.outcome = GradeOutcome::Fail;
  g.failures.push_back("the image is " + std::to_string(width) + "x" + std::to_string(height) + ", the reference " +
                       std::to_string(referenceWidth) + "x" + std::to_string(referenceHeight));
  g.key.value = HUGE_VAL, g.key.text = "size differs";
  return g;
}

Grade gradeImage(const Image& submission, const Image& reference, const GradeThresholds& t, ImageDiff* diff,
                 FlipMap* flipMap, const RadianceImage* submissionLinear, const RadianceImage* referenceLinear) {
  if (submission.width != reference.width || submission.height != reference.height)
    return sizeDiffers(submission.width, submission.height, reference.width, reference.height, t);
  Grade g;
  g.width = submission.width, g.height = submission.height;
  g.key.label = keyFigureLabel(t);
  ImageDiff d = compare(submission, reference);
  g.maxDiff = d.maxChannelDiff, g.rmse = d.rmse, g.psnr = d.psnr();
  g.differing = static_cast<long long>(d.differing.size()), g.over1 = d.countOver(1), g.over2 = d.countOver(2);
  g.stats = graderStats(submission, reference);
  const bool hdr = submissionLinear && referenceLinear && submissionLinear->width == reference.width &&
                   submissionLinear->height == reference.height && referenceLinear->width == reference.width &&
                   referenceLinear->height == reference.height;
  FlipExposures exposures;
  const double ppd = t.pixels.pixelsPerDegree;
  FlipMap map = hdr ? hdrFlip(*submissionLinear, *referenceLinear, &exposures, ppd) : ldrFlip(submission, reference, ppd);
  g.flip = flipStats(map);
  g.flip.pixelsPerDegree = ppd;
  g.flip.hdr = hdr;
  g.flip.exposures = exposures;
  g.bias = biasTest(submission, reference, t.gamma, t.maxBiasZ.value_or(HUGE_VAL));
  g.key = keyFigure(t, d, g.stats, g.flip, g.bias);
  if (t.pixels.any() || !t.any()) g.failures = failedThresholds(d, g.flip, t.pixels);
  if (t.maxBias && std::fabs(g.stats.bias) > *t.maxBias)
    g.failures.push_back("bias " + format("%.4g", g.stats.bias) + " exceeds " + format("%g", *t.maxBias) +
                         " in magnitude (--max-bias)");
  if (t.maxVariance && g.stats.variance > *t.maxVariance)
    g.failures.push_back("variance " + format("%.4g", g.stats.variance) + " exceeds " + format("%g", *t.maxVariance) +
                         " (--max-variance)");
  if (t.maxBiasZ && !g.bias.over.empty())
    g.failures.push_back(biasFailure(g.bias, *t.maxBiasZ));
  g.outcome = g.failures.empty() ? GradeOutcome::Pass : GradeOutcome::Fail;
  if (int step = failingStep(t); step >= 0 && g.outcome == GradeOutcome::Fail)
    g.regions = failingRegions(d, step, kRegionCell, kMaxRegions, &g.moreRegions);
  else if (g.outcome == GradeOutcome::Fail && !g.bias.over.empty())
    g.regions = biasedRegions(g.bias, g.width, g.height, kMaxRegions, &g.moreRegions);
  if (diff) *diff = std::move(d);
  if (flipMap) *flipMap = std::move(map);
  return g;
}

namespace {

// The boxes around the marked squares of a `cw` x `ch` grid of `cell`-pixel squares over a
// `width` x `height` image (`count` per square, 0 unmarked): the marked squares joined where
// they touch (sides or corners), each group's bounding box; at most `limit`, those of the
// largest counts first (`more` receives how many were left out).
std::vector<PixelRect> joinedCells(const std::vector<long long>& count, int cw, int ch, int cell, int width,
                                   int height, std::size_t limit, long long* more) {
  struct Region {
    PixelRect box;
    long long pixels = 0;
  };
  std::vector<Region> regions;
  std::vector<char> seen(count.size(), 0);
  std::vector<int> stack;
  for (int start = 0; start < cw * ch; ++start) {
    if (count[start] == 0 || seen[start]) continue;
    Region r{{width, height, 0, 0}, 0};
    stack.push_back(start);
    seen[start] = 1;
    while (!stack.empty()) {
      int c = stack.back();
      stack.pop_back();
      int cx = c % cw, cy = c / cw;
      r.pixels += count[c];
      r.box.x0 = std::min(r.box.x0, cx * cell), r.box.y0 = std::min(r.box.y0, cy * cell);
      r.box.x1 = std::max(r.box.x1, std::min(width, (cx + 1) * cell));
      r.box.y1 = std::max(r.box.y1, std::min(height, (cy + 1) * cell));
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = cx + dx, ny = cy + dy;
          if (nx < 0 || ny < 0 || nx >= cw || ny >= ch) continue;
          int n = ny * cw + nx;
          if (count[n] > 0 && !seen[n]) seen[n] = 1, stack.push_back(n);
        }
    }
    regions.push_back(r);
  }
  std::stable_sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) { return a.pixels > b.pixels; });
  if (more) *more = regions.size() > limit ? static_cast<long long>(regions.size() - limit) : 0;
  std::vector<PixelRect> boxes;
  for (std::size_t i = 0; i < regions.size() && i < limit; ++i) boxes.push_back(regions[i].box);
  return boxes;
}

}  // namespace

std::vector<PixelRect> failingRegions(const ImageDiff& diff, int steps, int cell, std::size_t limit, long long* more) {
  const int cw = (diff.width + cell - 1) / cell, ch = (diff.height + cell - 1) / cell;
  std::vector<long long> count(static_cast<std::size_t>(cw) * ch, 0);   // failing pixels per square
  for (const PixelDiff& p : diff.differing)
    if (p.maxChannelDiff > steps) ++count[static_cast<std::size_t>(p.y / cell) * cw + p.x / cell];
  return joinedCells(count, cw, ch, cell, diff.width, diff.height, limit, more);
}

std::vector<PixelRect> biasedRegions(const BiasTest& bias, int width, int height, std::size_t limit, long long* more) {
  const int cell = kBiasSquare;
  const int cw = (width + cell - 1) / cell, ch = (height + cell - 1) / cell;
  std::vector<long long> count(static_cast<std::size_t>(cw) * ch, 0);   // biased channels per square
  for (const SquareBias& s : bias.over) ++count[static_cast<std::size_t>(s.square.y0 / cell) * cw + s.square.x0 / cell];
  return joinedCells(count, cw, ch, cell, width, height, limit, more);
}

}  // namespace vkrt
