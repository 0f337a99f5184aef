// Crop rectangles, their record, and reading the text records of PNG, PPM and PFM files.
#include "image/crop.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "errors.h"
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

std::uint32_t bigEndian(const unsigned char* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | std::uint32_t{p[3]};
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
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read image '" + path + "': " + std::strerror(errno));
  auto cutShort = [&](const std::string& what) { return IoError("cannot read image '" + path + "': " + what); };
  in.seekg(0, std::ios::end);
  const auto fileSize = static_cast<std::uint64_t>(std::max<std::streamoff>(0, in.tellg()));
  in.seekg(0);
  if (fileSize == 0) throw cutShort("the file is empty");
  if (isFloatImageFile(path)) return readFloatImageText(path);
  std::vector<std::pair<std::string, std::string>> text;
  unsigned char signature[8] = {};
  in.read(reinterpret_cast<char*>(signature), 8);
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (in.gcount() == 8 && std::memcmp(signature, kPng, 8) == 0) {
    // Chunks: length, type, data, CRC. The text comes before IDAT in our files, but a PNG may
    // put it anywhere before IEND; the image data is skipped, not read. A file that ends
    // before IEND is cut short.
    unsigned char head[8];
    std::uint64_t at = 8;
    for (;;) {
      if (at + 8 > fileSize || !in.read(reinterpret_cast<char*>(head), 8))
        throw cutShort("the PNG is truncated (it ends before its IEND chunk)");
      const std::uint64_t length = bigEndian(head);
      std::string type(reinterpret_cast<char*>(head) + 4, 4);
      if (length > 0x7fffffffu) throw cutShort("the PNG is malformed (a chunk length beyond 2^31)");
      at += 8 + length + 4;
      if (at > fileSize) throw cutShort("the PNG is truncated (its " + type + " chunk is cut short)");
      if (type == "IEND") break;
      if (type == "tEXt" && length <= (1u << 20)) {
        std::string data(length, '\0');
        if (!in.read(data.data(), static_cast<std::streamsize>(length))) throw cutShort("the PNG is truncated");
        std::size_t nul = data.find('\0');
        if (nul != std::string::npos) text.emplace_back(data.substr(0, nul), data.substr(nul + 1));
        in.seekg(4, std::ios::cur);
      } else {
        in.seekg(static_cast<std::streamoff>(length) + 4, std::ios::cur);
      }
    }
  } else if (in.gcount() >= 2 && signature[0] == 'P' && signature[1] == '6') {
    // The header's comment lines, "# KEY VALUE", up to the maxval; then the raster, which
    // must be all there.
    in.clear();
    in.seekg(2);
    std::uint64_t numbers[3] = {};
    int count = 0;
    while (count < 3) {
      int c = in.peek();
      if (c == EOF) throw cutShort("the PPM header is truncated");
      if (c == '#') {
        std::string line;
        std::getline(in, line);
        std::size_t space = line.find(' ', 2);
        if (line.size() > 2 && line[1] == ' ' && space != std::string::npos)
          text.emplace_back(line.substr(2, space - 2), line.substr(space + 1));
      } else if (c == ' ' || c == '\n' || c == '\r' || c == '\t') {
        in.get();
      } else {
        std::string word;
        in >> word;
        if (word.empty() || word.size() > 9 || word.find_first_not_of("0123456789") != std::string::npos)
          throw cutShort("the PPM header is malformed ('" + word + "')");
        numbers[count++] = std::stoull(word);
      }
    }
    in.get();   // the single whitespace byte after the maxval
    const std::uint64_t raster = numbers[0] * numbers[1] * 3 * (numbers[2] > 255 ? 2 : 1);
    const auto rasterStart = static_cast<std::uint64_t>(std::max<std::streamoff>(0, in.tellg()));
    if (!in || rasterStart + raster > fileSize) throw cutShort("the PPM raster is truncated");
  }
  return text;
}

}  // namespace vkrt
