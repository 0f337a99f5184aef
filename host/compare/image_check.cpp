// Metrics, thresholds and reports of `vkrt diff` and `vkrt SCENE --check`.
#include "compare/image_check.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "util/counted.h"
#include "util/errors.h"   // UsageError
#include "util/json.h"   // jsonQuoted
#include "util/text.h"   // echoed

namespace vkrt {

PixelThreshold parsePixelThreshold(const std::string& text) {
  PixelThreshold t;
  t.text = text;
  auto bad = [&] {
    return UsageError("--max-pixels-over expects STEPS:COUNT or STEPS:PERCENT% (e.g. 2:0.1%), got '" + echoed(text) + "'");
  };
  auto colon = text.find(':');
  if (colon == std::string::npos) throw bad();
  const char* s = text.data();
  auto [end, ec] = std::from_chars(s, s + colon, t.steps);
  if (ec != std::errc() || end != s + colon || t.steps < 0 || t.steps > 255) throw bad();
  std::string limit = text.substr(colon + 1);
  if (!limit.empty() && limit.back() == '%') {
    t.percent = true;
    limit.pop_back();
  }
  auto [end2, ec2] = std::from_chars(limit.data(), limit.data() + limit.size(), t.limit);
  if (limit.empty() || ec2 != std::errc() || end2 != limit.data() + limit.size() || !(t.limit >= 0.0) ||
      (t.percent && t.limit > 100.0))
    throw bad();
  return t;
}

double parseFlipThreshold(const std::string& text) {
  double v = 0.0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !(v >= 0.0 && v <= 1.0))
    throw UsageError("--max-flip expects a number from 0 to 1 (the largest mean FLIP error that passes), got '" +
                     echoed(text) + "'");
  return v;
}

double parsePixelsPerDegree(const std::string& text) {
  double v = 0.0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !(v > 0.0 && v <= 1000.0))
    throw UsageError("--pixels-per-degree expects a number above 0 and at most 1000 (67 for a 0.7 m wide 4K monitor "
                     "seen from 0.7 m), got '" + echoed(text) + "'");
  return v;
}

namespace {

double share(long long count, long long pixels) {
  return pixels > 0 ? 100.0 * static_cast<double>(count) / static_cast<double>(pixels) : 0.0;
}

std::string format(const char* fmt, double a, double b = 0.0) {
  char buf[128];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

}  // namespace

std::vector<std::string> failedThresholds(const ImageDiff& diff, const FlipStats& flip,
                                          const CheckThresholds& thresholds) {
  std::vector<std::string> failures;
  if (!thresholds.any()) {
    if (!diff.differing.empty())
      failures.push_back(counted(diff.differing.size(), "pixel differs", "pixels differ") +
                         " (no threshold given: any difference fails)");
    return failures;
  }
  for (const PixelThreshold& t : thresholds.pixelsOver) {
    long long over = diff.countOver(t.steps);
    double allowed = t.percent ? t.limit / 100.0 * static_cast<double>(diff.pixels) : t.limit;
    if (static_cast<double>(over) > allowed)
      failures.push_back(counted(over, "pixel", "pixels") + " (" + format("%.4g%%", share(over, diff.pixels)) +
                         (over == 1 ? ") differs" : ") differ") + " by more than " + std::to_string(t.steps) + "/255; allowed: " +
                         (t.percent ? format("%.4g%%", t.limit) : format("%.0f", t.limit)) + " (--max-pixels-over " +
                         t.text + ")");
  }
  if (thresholds.maxDiff >= 0 && diff.maxChannelDiff > thresholds.maxDiff)
    failures.push_back("largest channel difference " + std::to_string(diff.maxChannelDiff) + "/255 exceeds " +
                       std::to_string(thresholds.maxDiff) + "/255 (--max-diff)");
  if (thresholds.maxFlip >= 0.0 && flip.mean > thresholds.maxFlip)
    failures.push_back(std::string(flip.hdr ? "HDR-FLIP" : "LDR-FLIP") + " mean error " + format("%.4g", flip.mean) +
                       " exceeds " + format("%g", thresholds.maxFlip) + " (--max-flip)");
  return failures;
}

std::string flipReportText(const FlipStats& f) {
  std::string s = std::string(f.hdr ? "HDR-FLIP " : "LDR-FLIP ") + flipStatsText(f);
  if (f.hdr)
    s += format(" (%.3g to %.3g stops, ", f.exposures.start, f.exposures.stop) +
         counted(f.exposures.count, "exposure", "exposures") + ")";
  if (f.pixelsPerDegree != kFlipDefaultPixelsPerDegree) s += format(", at %.4g pixels per degree", f.pixelsPerDegree);
  return s;
}

std::string flipReportJson(const FlipStats& f) {
  std::string s = std::string("{\"kind\":") + (f.hdr ? "\"hdr\"" : "\"ldr\"") + ",\"mean\":" + format("%.6g", f.mean) +
                  ",\"median\":" + format("%.6g", f.median) + ",\"p95\":" + format("%.6g", f.p95) +
                  ",\"p99\":" + format("%.6g", f.p99) + ",\"max\":" + format("%.6g", f.max) +
                  ",\"pixels_per_degree\":" + format("%.6g", f.pixelsPerDegree);
  if (f.hdr)
    s += ",\"start_exposure\":" + format("%.6g", f.exposures.start) + ",\"stop_exposure\":" +
         format("%.6g", f.exposures.stop) + ",\"exposures\":" + std::to_string(f.exposures.count);
  return s + "}";
}

std::string diffReportText(const ImageDiff& d, const FlipStats& flip) {
  long long over1 = d.countOver(1), over2 = d.countOver(2);
  std::string psnr = std::isinf(d.psnr()) ? "inf (identical)" : format("%.2f dB", d.psnr());
  return "  size        " + std::to_string(d.width) + "x" + std::to_string(d.height) + "\n" +
         "  RMSE        " + format("%.4f/255", d.rmse) + "\n" + "  PSNR        " + psnr + "\n" +
         "  max diff    " + std::to_string(d.maxChannelDiff) + "/255\n" + "  differing   " +
         counted(d.differing.size(), "pixel", "pixels") +
         format(" (%.4g%%)", share(static_cast<long long>(d.differing.size()), d.pixels)) + "\n" + "  over 1/255  " +
         counted(over1, "pixel", "pixels") + format(" (%.4g%%)", share(over1, d.pixels)) + "\n" + "  over 2/255  " +
         counted(over2, "pixel", "pixels") + format(" (%.4g%%)", share(over2, d.pixels)) + "\n" + "  FLIP        " +
         flipReportText(flip) + "\n";
}

std::string diffReportJson(const ImageDiff& d, const FlipStats& flip, const std::vector<std::string>& failures) {
  long long over1 = d.countOver(1), over2 = d.countOver(2);
  std::string psnr = std::isinf(d.psnr()) ? "null" : format("%.6g", d.psnr());
  std::string s = "{\"width\":" + std::to_string(d.width) + ",\"height\":" + std::to_string(d.height) +
                  ",\"rmse\":" + format("%.6g", d.rmse) + ",\"psnr_db\":" + psnr +
                  ",\"max_channel_diff\":" + std::to_string(d.maxChannelDiff) +
                  ",\"pixels_differing\":" + std::to_string(d.differing.size()) +
                  ",\"pixels_over_1\":" + std::to_string(over1) + ",\"share_over_1\":" +
                  format("%.6g", share(over1, d.pixels) / 100.0) + ",\"pixels_over_2\":" + std::to_string(over2) +
                  ",\"share_over_2\":" + format("%.6g", share(over2, d.pixels) / 100.0) + ",\"flip\":" + flipReportJson(flip) + ",\"pass\":" +
                  (failures.empty() ? "true" : "false") + ",\"failures\":[";
  for (std::size_t i = 0; i < failures.size(); ++i) s += (i ? "," : "") + jsonQuoted(failures[i]);
  return s + "]}";
}

}  // namespace vkrt
