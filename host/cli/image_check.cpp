// Metrics, thresholds and reports of `vkrt diff` and `vkrt SCENE --check`.
#include "cli/image_check.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "counted.h"
#include "cli/options.h"
#include "scene/diagnostic.h"   // echoed

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

std::vector<std::string> failedThresholds(const ImageDiff& diff, const CheckThresholds& thresholds) {
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
  return failures;
}

std::string diffReportText(const ImageDiff& d) {
  long long over1 = d.countOver(1), over2 = d.countOver(2);
  std::string psnr = std::isinf(d.psnr()) ? "inf (identical)" : format("%.2f dB", d.psnr());
  return "  size        " + std::to_string(d.width) + "x" + std::to_string(d.height) + "\n" +
         "  RMSE        " + format("%.4f/255", d.rmse) + "\n" + "  PSNR        " + psnr + "\n" +
         "  max diff    " + std::to_string(d.maxChannelDiff) + "/255\n" + "  differing   " +
         counted(d.differing.size(), "pixel", "pixels") +
         format(" (%.4g%%)", share(static_cast<long long>(d.differing.size()), d.pixels)) + "\n" + "  over 1/255  " +
         counted(over1, "pixel", "pixels") + format(" (%.4g%%)", share(over1, d.pixels)) + "\n" + "  over 2/255  " +
         counted(over2, "pixel", "pixels") + format(" (%.4g%%)", share(over2, d.pixels)) + "\n";
}

namespace {

// The length of the well-formed UTF-8 sequence at s[i] (1-4), or 0 where the bytes are not
// one (a stray continuation byte, a sequence cut short, an overlong form, a surrogate, a
// code point beyond U+10FFFF).
std::size_t utf8Length(const std::string& s, std::size_t i) {
  const unsigned char c = static_cast<unsigned char>(s[i]);
  if (c < 0x80) return 1;
  std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? (c <= 0xEF ? 3 : 0) : c >= 0xC2 && c <= 0xDF ? 2 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  const unsigned char d = static_cast<unsigned char>(s[i + 1]);
  if ((c == 0xE0 && d < 0xA0) || (c == 0xED && d > 0x9F) || (c == 0xF0 && d < 0x90) || (c == 0xF4 && d > 0x8F))
    return 0;
  return n;
}

}  // namespace

std::string jsonQuoted(const std::string& s) {
  std::string q = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const std::size_t n = utf8Length(s, i);
    if (n == 0) {   // not UTF-8 (a file name from another system): the replacement character
      q += "\\ufffd";
      ++i;
      continue;
    }
    if (c == '"' || c == '\\') {
      q += '\\';
      q += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      q += buf;
    } else {
      q.append(s, i, n);
    }
    i += n;
  }
  return q + "\"";
}

std::string diffReportJson(const ImageDiff& d, const std::vector<std::string>& failures) {
  long long over1 = d.countOver(1), over2 = d.countOver(2);
  std::string psnr = std::isinf(d.psnr()) ? "null" : format("%.6g", d.psnr());
  std::string s = "{\"width\":" + std::to_string(d.width) + ",\"height\":" + std::to_string(d.height) +
                  ",\"rmse\":" + format("%.6g", d.rmse) + ",\"psnr_db\":" + psnr +
                  ",\"max_channel_diff\":" + std::to_string(d.maxChannelDiff) +
                  ",\"pixels_differing\":" + std::to_string(d.differing.size()) +
                  ",\"pixels_over_1\":" + std::to_string(over1) + ",\"share_over_1\":" +
                  format("%.6g", share(over1, d.pixels) / 100.0) + ",\"pixels_over_2\":" + std::to_string(over2) +
                  ",\"share_over_2\":" + format("%.6g", share(over2, d.pixels) / 100.0) + ",\"pass\":" +
                  (failures.empty() ? "true" : "false") + ",\"failures\":[";
  for (std::size_t i = 0; i < failures.size(); ++i) s += (i ? "," : "") + jsonQuoted(failures[i]);
  return s + "]}";
}

}  // namespace vkrt
