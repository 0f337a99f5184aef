// Crop rectangles, their record, and reading the text records of image files (through
// image/image_file.h).
#include "image/crop.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "util/errors.h"
#include "image/image_file.h"

namespace vkrt {
namespace {

// A whole decimal integer in [0, 2^31), with nothing else.
bool parseCount(const std::string& s, int& out) {
  if (s.empty() || s.size() > 10) return false;
  long long v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  if (v > 0x7fffffffLL) return false;
  out = static_cast<int>(v);
  return true;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    std::size_t at = s.find(sep, start);
    parts.push_back(s.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

}  // namespace

std::string formatPixelRect(const PixelRect& r) {
  return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," + std::to_string(r.y1);
}

std::string formatCropRecord(const CropRecord& r) {
  return formatPixelRect(r.rect) + " of " + std::to_string(r.fullWidth) + " " + std::to_string(r.fullHeight);
}

std::optional<PixelRect> parseCropOption(const std::string& text) {
  std::vector<std::string> parts = split(text, ',');
  if (parts.size() != 4) return std::nullopt;
  PixelRect r;
  if (!parseCount(parts[0], r.x0) || !parseCount(parts[1], r.y0) || !parseCount(parts[2], r.x1) ||
      !parseCount(parts[3], r.y1))
    return std::nullopt;
  return r;
}

std::string cropProblem(const PixelRect& r, int fullWidth, int fullHeight) {
  std::string size = std::to_string(fullWidth) + "x" + std::to_string(fullHeight);
  if (r.x1 <= r.x0 || r.y1 <= r.y0)
    return "the rectangle is empty (X1 must be greater than X0, and Y1 than Y0)";
  if (r.x1 > fullWidth || r.y1 > fullHeight) return "the rectangle is not inside the " + size + " image";
  return "";
}

std::optional<CropRecord> parseCropRecord(const std::string& value, std::string* why) {
  auto fail = [why](const std::string& reason) -> std::optional<CropRecord> {
    if (why) *why = reason;
    return std::nullopt;
  };
  std::vector<std::string> words = split(value, ' ');
  if (words.size() != 4 || words[1] != "of") return fail("not \"X0,Y0,X1,Y1 of W H\"");
  std::optional<PixelRect> rect = parseCropOption(words[0]);
  CropRecord record;
  if (!rect || !parseCount(words[2], record.fullWidth) || !parseCount(words[3], record.fullHeight))
    return fail("not \"X0,Y0,X1,Y1 of W H\" with whole numbers");
  if (record.fullWidth < 1 || record.fullHeight < 1 || record.fullWidth > kMaxRecordedImageEdge ||
      record.fullHeight > kMaxRecordedImageEdge)
    return fail("the full image is not from 1 to " + std::to_string(kMaxRecordedImageEdge) + " pixels on a side");
  record.rect = *rect;
  if (std::string problem = cropProblem(record.rect, record.fullWidth, record.fullHeight); !problem.empty())
    return fail(problem);
  return record;
}

std::vector<std::pair<std::string, std::string>> readImageText(const std::string& path) {
  return readImageFileText(path);
}

}  // namespace vkrt
