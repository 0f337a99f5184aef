// Merging crops: read each tile's record and pixels, check that the tiles make one image,
// copy them into place. Merging sample batches: check that they are of one render, average.
#include "image/merge.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include "errors.h"
#include "image/crop.h"
#include "image/pfm.h"
#include "image/png.h"

namespace vkrt {
namespace {

// A tile of either kind: 8-bit (Image) or linear float from a PFM (RadianceImage).
template <class Pixels>
struct Tile {
  std::string path;
  CropRecord record;
  Pixels image;
};

template <class Pixels>
Tile<Pixels> readTile(const std::string& path) {
  Tile<Pixels> tile{path, {}, {}};
  std::optional<std::string> value;
  for (const auto& [keyword, text] : readImageText(path))
    if (keyword == kCropKeyword) value = text;
  if (!value)
    throw UsageError("tile '" + path + "' has no " + kCropKeyword +
                     " record: it is not an image written with --crop");
  std::optional<CropRecord> record = parseCropRecord(*value);
  if (!record) throw UsageError("tile '" + path + "': malformed " + kCropKeyword + " record '" + *value + "'");
  tile.record = *record;
  if constexpr (std::is_same_v<Pixels, RadianceImage>)
    tile.image = readPfm(path);
  else
    tile.image = readImage(path);
  if (tile.image.width != record->rect.width() || tile.image.height != record->rect.height())
    throw UsageError("tile '" + path + "' is " + std::to_string(tile.image.width) + "x" +
                     std::to_string(tile.image.height) + ", but its record says " + *value);
  return tile;
}

// Reads the tiles, checks that they make one image, and copies each into place.
template <class Pixels>
Pixels placeTiles(const std::vector<std::string>& tilePaths, bool allowGaps, std::vector<Tile<Pixels>>& tiles,
                  MergeReport* report) {
  for (const std::string& path : tilePaths) tiles.push_back(readTile<Pixels>(path));
  if (tiles.empty()) throw UsageError("merge needs at least one tile");
  const int fullWidth = tiles[0].record.fullWidth, fullHeight = tiles[0].record.fullHeight;
  std::uint64_t covered = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const Tile<Pixels>& t = tiles[i];
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
  Pixels merged(fullWidth, fullHeight);
  for (const Tile<Pixels>& t : tiles)
    for (int y = 0; y < t.image.height; ++y)
      std::memcpy(merged.pixel(t.record.rect.x0, t.record.rect.y0 + y), t.image.pixel(0, y),
                  static_cast<std::size_t>(t.image.width) * 3 * sizeof(*t.image.pixel(0, 0)));
  if (report) *report = {static_cast<int>(tiles.size()), gaps, {}};
  return merged;
}

}  // namespace

Image mergeCrops(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report) {
  for (const std::string& path : tilePaths)
    if (isPfmFile(path))
      throw UsageError("tile '" + path + "' is a PFM file: merge tiles of one kind (all PFM, or all PNG or PPM)");
  std::vector<Tile<Image>> tiles;
  return placeTiles(tilePaths, allowGaps, tiles, report);
}

namespace {

std::optional<std::string> recordOf(const std::vector<std::pair<std::string, std::string>>& text,
                                    const std::string& keyword) {
  std::optional<std::string> value;
  for (const auto& [k, v] : text)
    if (k == keyword) value = v;
  return value;
}

std::string gammaText(double gamma) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", gamma);
  return buf;
}

}  // namespace

bool areSampleBatches(const std::vector<std::string>& paths) {
  std::optional<std::optional<std::string>> place;   // the first file's crop record, or none
  for (const std::string& path : paths) {
    auto text = readImageText(path);
    if (!recordOf(text, kSamplesKeyword)) return false;
    std::optional<std::string> crop = recordOf(text, kCropKeyword);
    if (place && *place != crop) return false;
    place = crop;
  }
  return !paths.empty();
}

RadianceImage mergeSampleBatches(const std::vector<std::string>& paths, MergeReport* report) {
  if (paths.empty()) throw UsageError("merge needs at least one batch");
  RadianceImage mean;
  mean.samples = 0;
  SampleRecord merged;
  std::string firstPath;
  std::optional<std::string> firstCrop;
  std::vector<std::pair<std::string, SampleRecord>> seen;
  for (const std::string& path : paths) {
    if (!isPfmFile(path))
      throw UsageError("batch '" + path + "' is not a PFM file: sample batches are averaged from linear float "
                       "images; render each batch with -o NAME.pfm");
    RadianceImage batch = readPfm(path);
    std::optional<std::string> value = recordOf(batch.text, kSamplesKeyword);
    if (!value)
      throw UsageError("batch '" + path + "' has no " + kSamplesKeyword +
                       " record: it is not the image of a path-traced render");
    std::optional<SampleRecord> record = parseSampleRecord(*value);
    if (!record) throw UsageError("batch '" + path + "': malformed " + kSamplesKeyword + " record '" + *value + "'");
    std::optional<std::string> crop = recordOf(batch.text, kCropKeyword);
    if (seen.empty()) {
      firstPath = path;
      firstCrop = crop;
      merged.gamma = record->gamma;
    } else {
      if (batch.width != mean.width || batch.height != mean.height)
        throw UsageError("batches of different sizes: '" + firstPath + "' is " + std::to_string(mean.width) + "x" +
                         std::to_string(mean.height) + ", '" + path + "' " + std::to_string(batch.width) + "x" +
                         std::to_string(batch.height));
      if (crop != firstCrop)
        throw UsageError("batches of different places: '" + firstPath + "' is " +
                         (firstCrop ? "the crop " + *firstCrop : std::string("the whole image")) + ", '" + path +
                         "' " + (crop ? "the crop " + *crop : std::string("the whole image")));
      if (record->gamma != merged.gamma)
        throw UsageError("batches of different gammas: '" + firstPath + "' has gamma " + gammaText(merged.gamma) +
                         ", '" + path + "' gamma " + gammaText(record->gamma));
    }
    for (const auto& [otherPath, other] : seen) {
      std::string shared = sharedSample(other, *record);
      if (!shared.empty())
        throw UsageError("batches '" + otherPath + "' and '" + path + "' hold the same samples (" + shared +
                         "): render each batch with its own --seed");
    }
    seen.emplace_back(path, *record);
    batch.samples = record->total();
    batch.text.clear();
    accumulateMean(mean, std::move(batch));
    merged.ranges.insert(merged.ranges.end(), record->ranges.begin(), record->ranges.end());
  }
  if (firstCrop) mean.text.emplace_back(kCropKeyword, *firstCrop);
  mean.text.emplace_back(kSamplesKeyword, formatSampleRecord(merged));
  if (report) {
    report->tiles = static_cast<int>(paths.size());
    report->gapPixels = 0;
    report->samples = merged;
  }
  return mean;
}

RadianceImage mergeFloatCrops(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report) {
  for (const std::string& path : tilePaths)
    if (!isPfmFile(path))
      throw UsageError("tile '" + path + "' is not a PFM file, and '" + tilePaths.front() +
                       "' is: merge tiles of one kind (all PFM, or all PNG or PPM)");
  std::vector<Tile<RadianceImage>> tiles;
  RadianceImage merged = placeTiles(tilePaths, allowGaps, tiles, report);
  // The tiles of one path-traced render carry one samples record; it goes with the image.
  std::optional<std::string> first = recordOf(tiles.front().image.text, kSamplesKeyword);
  for (const Tile<RadianceImage>& t : tiles) {
    std::optional<std::string> value = recordOf(t.image.text, kSamplesKeyword);
    if (value != first)
      throw UsageError("tiles of different renders: '" + tiles.front().path + "' holds " +
                       (first ? "the samples " + *first : std::string("no samples record")) + ", '" + t.path + "' " +
                       (value ? "the samples " + *value : std::string("no samples record")));
  }
  if (first) {
    std::optional<SampleRecord> record = parseSampleRecord(*first);
    if (!record)
      throw UsageError("tile '" + tiles.front().path + "': malformed " + kSamplesKeyword + " record '" + *first + "'");
    merged.samples = record->total();
    merged.text.emplace_back(kSamplesKeyword, *first);
    if (report) report->samples = *record;
  }
  return merged;
}

}  // namespace vkrt
