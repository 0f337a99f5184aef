// Merging crops: read each tile's record and pixels, check that the tiles make one image,
// copy them into place.
#include "image/merge.h"

#include <algorithm>
#include <cstring>

#include "errors.h"
#include "image/crop.h"
#include "image/png.h"

namespace vkrt {
namespace {

struct Tile {
  std::string path;
  CropRecord record;
  Image image;
};

Tile readTile(const std::string& path) {
  Tile tile{path, {}, {}};
  std::optional<std::string> value;
  for (const auto& [keyword, text] : readImageText(path))
    if (keyword == kCropKeyword) value = text;
  if (!value)
    throw UsageError("tile '" + path + "' has no " + kCropKeyword +
                     " record: it is not an image written with --crop");
  std::optional<CropRecord> record = parseCropRecord(*value);
  if (!record) throw UsageError("tile '" + path + "': malformed " + kCropKeyword + " record '" + *value + "'");
  tile.record = *record;
  tile.image = readImage(path);
  if (tile.image.width != record->rect.width() || tile.image.height != record->rect.height())
    throw UsageError("tile '" + path + "' is " + std::to_string(tile.image.width) + "x" +
                     std::to_string(tile.image.height) + ", but its record says " + *value);
  return tile;
}

}  // namespace

Image mergeCrops(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report) {
  std::vector<Tile> tiles;
  for (const std::string& path : tilePaths) tiles.push_back(readTile(path));
  if (tiles.empty()) throw UsageError("merge needs at least one tile");
  const int fullWidth = tiles[0].record.fullWidth, fullHeight = tiles[0].record.fullHeight;
  std::uint64_t covered = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const Tile& t = tiles[i];
    if (t.record.fullWidth != fullWidth || t.record.fullHeight != fullHeight)
      throw UsageError("tiles of different images: '" + tiles[0].path + "' is a crop of a " +
                       std::to_string(fullWidth) + "x" + std::to_string(fullHeight) + " image, '" + t.path +
                       "' of a " + std::to_string(t.record.fullWidth) + "x" + std::to_string(t.record.fullHeight) +
                       " one");
    for (std::size_t j = 0; j < i; ++j) {
      const PixelRect &a = tiles[j].record.rect, &b = t.record.rect;
      if (std::max(a.x0, b.x0) < std::min(a.x1, b.x1) && std::max(a.y0, b.y0) < std::min(a.y1, b.y1))
        throw UsageError("tiles overlap: '" + tiles[j].path + "' (" + formatPixelRect(a) + ") and '" + t.path + "' (" +
                         formatPixelRect(b) + ")");
    }
    covered += static_cast<std::uint64_t>(t.record.rect.width()) * static_cast<std::uint64_t>(t.record.rect.height());
  }
  // The tiles do not overlap, so they cover every pixel exactly when their areas add up.
  const std::uint64_t gaps = static_cast<std::uint64_t>(fullWidth) * static_cast<std::uint64_t>(fullHeight) - covered;
  if (gaps > 0 && !allowGaps)
    throw UsageError(std::to_string(gaps) + " pixels of the " + std::to_string(fullWidth) + "x" +
                     std::to_string(fullHeight) + " image are in no tile (a tile missing?); --allow-gaps leaves "
                     "them black");
  Image merged(fullWidth, fullHeight);
  for (const Tile& t : tiles)
    for (int y = 0; y < t.image.height; ++y)
      std::memcpy(merged.pixel(t.record.rect.x0, t.record.rect.y0 + y), t.image.pixel(0, y),
                  static_cast<std::size_t>(t.image.width) * 3);
  if (report) *report = {static_cast<int>(tiles.size()), gaps};
  return merged;
}

}  // namespace vkrt
