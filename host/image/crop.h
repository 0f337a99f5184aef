// Crops: a pixel rectangle of a full image, and the record a cropped image carries so that
// `vkrt merge` can put it back in place with nothing else. Knows nothing of rendering.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vkrt {

// The pixels [x0, x1) x [y0, y1); column 0 at the left, row 0 at the top.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

// Where a cropped image lies in its full image.
struct CropRecord {
  PixelRect rect;
  int fullWidth = 0, fullHeight = 0;
};

// The keyword of the record: a PNG tEXt chunk, or a PPM header comment "# vkrt-crop VALUE".
inline constexpr const char* kCropKeyword = "vkrt-crop";

// The largest full image a record may describe, on either side: the renderer's image size
// limit (scene/parse.h kMaxImageEdge; render.cpp asserts that they agree). Records beyond it
// are malformed, so that `vkrt merge` never allocates an image no render could have made.
inline constexpr int kMaxRecordedImageEdge = 16384;

// "X0,Y0,X1,Y1"
std::string formatPixelRect(const PixelRect& rect);

// "X0,Y0,X1,Y1 of W H"
std::string formatCropRecord(const CropRecord& record);

// The record's value back; nullopt when malformed, empty, not inside W x H, or W or H beyond
// kMaxRecordedImageEdge (then `why`, when given, says which).
std::optional<CropRecord> parseCropRecord(const std::string& value, std::string* why = nullptr);

// --crop X0,Y0,X1,Y1: four integers; nullopt when malformed (the bounds are checked later,
// against the image size).
std::optional<PixelRect> parseCropOption(const std::string& text);

// Why `rect` is not a crop of a W x H image ("" when it is one): empty or outside.
std::string cropProblem(const PixelRect& rect, int fullWidth, int fullHeight);

// The text records of an image file, as its format keeps them (readImageFileText,
// image/image_file.h). Throws IoError when the file cannot be read, is empty, or is cut short
// (ends before what its header says); a file of no format vkrt writes gives none.
std::vector<std::pair<std::string, std::string>> readImageText(const std::string& path);

}  // namespace vkrt
