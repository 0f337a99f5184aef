// Option values, read and checked (host/cli/option_values.h).
#include "cli/option_values.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <string_view>

#include "util/errors.h"             // UsageError
#include "platform/path_text.h"
#include "util/text.h"   // echoed, abbreviated
#include "scene/parse.h"        // kMaxImageEdge

namespace vkrt {

std::string floatExtension() {
  for (const ImageFormat& format : imageFormats())
    if (format.linearFloat) return "." + std::string(format.extensions.front());
  return "";
}

// An integer option value in [lo, hi].
int integerValue(const std::string& option, const std::string& v, int lo, int hi) {
  int n = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || end != v.data() + v.size() || n < lo || n > hi)
    throw UsageError(option + " expects an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     ", got '" + echoed(v) + "'");
  return n;
}

// --size WxH, each side from 1 to kMaxImageEdge.
void sizeValue(const std::string& v, int& width, int& height) {
  auto x = v.find('x');
  auto side = [&](const std::string& s) {
    int n = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    return ec == std::errc() && end == s.data() + s.size() && n >= 1 && n <= kMaxImageEdge ? n : 0;
  };
  if (x != std::string::npos) {
    width = side(v.substr(0, x));
    height = side(v.substr(x + 1));
  }
  if (x == std::string::npos || width == 0 || height == 0)
    throw UsageError("--size expects WIDTHxHEIGHT, each from 1 to " + std::to_string(kMaxImageEdge) +
                     " (e.g. 320x240), got '" + echoed(v) + "'");
}

// --scale F: a finite number greater than 0.
double scaleValue(const std::string& v) {
  double f = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), f);
  if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(f) || !(f > 0))
    throw UsageError("--scale expects a number greater than 0 (e.g. 0.5), got '" + echoed(v) + "'");
  return f;
}

// --seed N: a whole number from 0 to 2^32 - 1.
std::uint32_t seedValue(const std::string& v) {
  std::uint32_t n = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || end != v.data() + v.size())
    throw UsageError("--seed expects a whole number from 0 to 4294967295, got '" + echoed(v) + "'");
  return n;
}

// --time SECONDS: a finite number greater than 0, at most a year.
double timeValue(const std::string& v) {
  double f = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), f);
  if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(f) || !(f > 0) || f > 31536000.0)
    throw UsageError("--time expects seconds, a number greater than 0 and at most a year, 31536000 (e.g. 2.5), got '" +
                     echoed(v) + "'");
  return f;
}

// An output named '-': vkrt writes images into files only (its reports go to stdout).
void refuseStandardOutput(const std::string& option, const std::string& path) {
  if (path == "-")
    throw UsageError(option + " -: vkrt writes images into files, not to standard output (where its reports go); "
                     "name a file ('./-' for a file named '-')");
}

bool endsInSeparator(const std::string& path) {
  return !path.empty() && std::string_view(platform::kPathSeparators).find(path.back()) != std::string_view::npos;
}

// "output file 'x.bmp' is not named .png, .ppm or .pfm: vkrt writes PNG, under that name":
// `what` at `path`, which may be named as any of `which`.
std::string unnamedWarning(const std::string& what, const std::string& path, FormatsOf which) {
  return what + " '" + abbreviated(path) + "' is not named " + imageExtensionsText(which) + ": vkrt writes " +
         std::string(imageFormats().front().name) + ", under that name";
}

// Whether an output path gets unnamedWarning: named as no image format, and not a folder
// (ends in '/', or is one) or a scene file, whose refusal by the write says so alone.
bool warnsOfItsName(const std::string& path) {
  std::error_code ec;
  return !hasImageExtension(path) && !endsInSeparator(path) &&
         !std::filesystem::is_directory(platform::pathFromUtf8(path), ec) && !namedAsSceneFile(path);
}

void warnOfItsName(const std::string& what, const std::string& path, FormatsOf which, bool strict,
                   std::vector<std::string>& warnings) {
  if (!warnsOfItsName(path)) return;
  std::string w = unnamedWarning(what, path, which);
  if (strict) throw UsageError(w + " [--strict]");
  warnings.push_back(w);
}

}  // namespace vkrt
