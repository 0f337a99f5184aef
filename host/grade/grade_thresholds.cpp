// Thresholds of `vkrt grade`, from the command line and from a thresholds file.
#include "grade/grade_thresholds.h"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "util/errors.h"
#include "grade/grade_inputs.h"
#include "platform/file_status.h"
#include "util/text.h"   // echoed, abbreviated

namespace vkrt {

namespace {

double nonNegative(const std::string& name, const std::string& v) {
  double f = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), f);
  if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(f) || f < 0)
    throw UsageError(name + " expects a number of 0 or more (" +
                     (name == "--max-bias-z"   ? "standard errors"
                      : name == "--points"     ? "points"
                      : name == "--limit-time" ? "seconds; 0: no limit"
                                               : "8-bit units") + "), got '" + echoed(v) + "'");
  return f;
}

// A whole number from 0 to `most` for a limit option.
std::uint64_t limitCount(const std::string& name, const std::string& v, std::uint64_t most) {
  std::uint64_t n = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || end != v.data() + v.size() || n > most)
    throw UsageError(name + " expects a whole number from 0 (no limit) to " + std::to_string(most) + ", got '" +
                     echoed(v) + "'");
  return n;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

std::string GradeThresholds::text() const {
  if (!any()) return "any difference fails";
  std::string s;
  auto add = [&](const std::string& part) { s += (s.empty() ? "" : " ") + part; };
  for (const PixelThreshold& p : pixels.pixelsOver) add("--max-pixels-over " + p.text);
  if (pixels.maxDiff >= 0) add("--max-diff " + std::to_string(pixels.maxDiff));
  if (pixels.maxFlip >= 0.0) add("--max-flip " + number(pixels.maxFlip));
  if (maxBias) add("--max-bias " + number(*maxBias));
  if (maxVariance) add("--max-variance " + number(*maxVariance));
  if (maxBiasZ) add("--max-bias-z " + number(*maxBiasZ));
  if (monteCarloDefault) s += " (the default of a path-traced scene)";
  return s;
}

const GradeThresholds& ThresholdTable::forScene(const std::string& key) const {
  auto at = byScene.find(key);
  return at == byScene.end() ? all : at->second;
}

bool applyThresholdOption(const std::string& name, const std::string& value, GradeThresholds& t) {
  if (name == "--max-pixels-over") {
    t.pixels.pixelsOver.push_back(parsePixelThreshold(value));
  } else if (name == "--max-diff") {
    int n = 0;
    auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc() || end != value.data() + value.size() || n < 0 || n > 255)
      throw UsageError("--max-diff expects an integer from 0 to 255, got '" + echoed(value) + "'");
    t.pixels.maxDiff = n;
  } else if (name == "--max-flip") {
    t.pixels.maxFlip = parseFlipThreshold(value);
  } else if (name == "--pixels-per-degree") {
    t.pixels.pixelsPerDegree = parsePixelsPerDegree(value);
  } else if (name == "--max-bias") {
    t.maxBias = nonNegative(name, value);
  } else if (name == "--max-variance") {
    t.maxVariance = nonNegative(name, value);
  } else if (name == "--max-bias-z") {
    t.maxBiasZ = nonNegative(name, value);
  } else if (name == "--points") {
    t.points = nonNegative(name, value);
  } else if (name == "--limit-time") {
    t.limits.seconds = nonNegative(name, value);
  } else if (name == "--limit-spp") {
    t.limits.spp = limitCount(name, value, std::uint64_t{1} << 40);
  } else if (name == "--limit-pixels") {
    t.limits.pixels = limitCount(name, value, std::uint64_t{1} << 40);
  } else if (name == "--limit-depth") {
    t.limits.depth = static_cast<int>(limitCount(name, value, 1'000'000));
  } else {
    return false;
  }
  return true;
}

ThresholdTable readThresholdFile(const std::string& path, const GradeThresholds& commandLine,
                                 const std::vector<std::string>& knownKeys) {
  auto unreadable = [&](int error) {
    return IoError("cannot read the thresholds file '" + abbreviated(path) + "': " + std::strerror(error));
  };
  const platform::FileStatus st = platform::statusOf(path);
  if (!st.found()) throw unreadable(st.error);
  if (st.is(platform::FileKind::Directory)) throw unreadable(EISDIR);
  std::ifstream in(path);
  if (!in) throw unreadable(errno);
  ThresholdTable table;
  table.all = commandLine;
  int lineNumber = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    if (lineNumber == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);   // a byte-order mark
    auto fail = [&](const std::string& what) {
      return UsageError(abbreviated(path) + ":" + std::to_string(lineNumber) + ": " + what);   // after "vkrt: error: "
    };
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string scene;
    if (!(words >> scene)) continue;
    if (scene[0] == '"') {   // "a scene name with spaces"
      const std::size_t open = line.find('"'), close = line.find('"', open + 1);
      if (close == std::string::npos) throw fail("the scene's name has no closing '\"'");
      scene = line.substr(open + 1, close - open - 1);
      words.str(line.substr(close + 1));
      words.clear();
    }
    const std::string key = sceneKey(scene);
    if (std::find(knownKeys.begin(), knownKeys.end(), key) == knownKeys.end())
      throw fail("no reference image for the scene '" + echoed(scene) + "'");
    if (table.byScene.count(key))
      throw fail("the scene '" + echoed(scene) + "' was given on line " + std::to_string(table.lineOf[key]));
    GradeThresholds t;
    t.limits = commandLine.limits;
    bool judges = false;   // a threshold or --points on the line (not only limits)
    std::vector<std::string> rest;
    for (std::string w; words >> w;) rest.push_back(w);
    if (rest.empty()) throw fail("no threshold for " + echoed(scene) + " (e.g. --max-pixels-over 2:0.1%)");
    for (std::size_t i = 0; i < rest.size(); ++i) {
      std::string name = rest[i], value;
      if (auto eq = name.find('='); eq != std::string::npos) {
        value = name.substr(eq + 1);
        name.resize(eq);
      } else if (i + 1 < rest.size()) {
        value = rest[++i];
      } else {
        throw fail("'" + echoed(name) + "' needs a value");
      }
      if (name.rfind("--limit-", 0) != 0) judges = true;
      try {
        if (!applyThresholdOption(name, value, t))
          throw fail("unknown threshold or limit '" + echoed(name) +
                     "' (expected --max-pixels-over, --max-diff, --max-flip, --max-bias, --max-variance, --max-bias-z, "
                     "--pixels-per-degree, --points, --limit-time, --limit-spp, --limit-pixels or --limit-depth)");
      } catch (const UsageError& e) {
        if (std::string(e.what()).rfind(abbreviated(path) + ":", 0) == 0) throw;
        throw fail(e.what());
      }
    }
    if (!judges) {   // limits alone: the command line's thresholds, with these limits
      const GradeLimits limits = t.limits;
      t = commandLine;
      t.limits = limits;
    }
    table.byScene.emplace(key, t);
    table.lineOf[key] = lineNumber;
  }
  if (in.bad()) throw unreadable(EIO);
  return table;
}

}  // namespace vkrt
