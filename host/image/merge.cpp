// Merging crops: read each tile's records, check that the tiles make one image of one render,
// then read each tile's pixels and copy them into place. Merging sample batches: check that
// they are of one render, average. Every record is validated before it sizes anything.
#include "image/merge.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <type_traits>

#include "util/counted.h"
#include "util/errors.h"
#include "image/crop.h"
#include "image/image_file.h"
#include "image/render_identity.h"
#include "image/row_sink.h"
#include "platform/file_status.h"


namespace vkrt {
namespace {

using Records = std::vector<std::pair<std::string, std::string>>;

std::optional<std::string> recordOf(const Records& text, const std::string& keyword) {
  std::optional<std::string> value;
  for (const auto& [k, v] : text)
    if (k == keyword) value = v;
  return value;
}

// A part's record `keyword`, which it may carry at most once (UsageError naming the file
// otherwise: a forged or doctored file, whose two values cannot both be right).
std::optional<std::string> onlyRecord(const Records& text, const std::string& keyword, const std::string& what,
                                      const std::string& path) {
  std::optional<std::string> value;
  for (const auto& [k, v] : text) {
    if (k != keyword) continue;
    if (value)
      throw UsageError(what + " '" + path + "' carries two " + keyword + " records ('" + *value + "' and '" + v +
                       "')");
    value = v;
  }
  return value;
}

std::string gammaText(double gamma) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", gamma);
  return buf;
}

// The render identities of the parts (`what`, `whats`: "tile", "tiles" or "batch",
// "batches"): each part that carries one must carry the first one's (UsageError naming both
// files otherwise); a part without one (written before vkrt recorded identities) is merged
// unchecked, with a warning. Returns the identity when every part carries it, for the
// merged image.
std::optional<std::string> checkIdentities(const std::vector<std::string>& paths, const std::vector<Records>& texts,
                                           const std::string& what, const std::string& whats,
                                           std::vector<std::string>& warnings) {
  std::optional<std::string> first;
  std::size_t firstIndex = 0;
  bool all = true;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    std::optional<std::string> value = onlyRecord(texts[i], kRenderKeyword, what, paths[i]);
    if (!value) {
      all = false;
      warnings.push_back(what + " '" + paths[i] + "' has no " + kRenderKeyword +
                         " record (written by an older vkrt): merged without checking that it is of the same scene "
                         "and settings");
      continue;
    }
    if (!parseRenderIdentity(*value))
      throw UsageError(what + " '" + paths[i] + "': malformed " + kRenderKeyword + " record '" + *value +
                       "' (16 hex digits expected)");
    if (!first) {
      first = value;
      firstIndex = i;
    } else if (*value != *first) {
      throw UsageError(whats + " of different renders: '" + paths[firstIndex] + "' and '" + paths[i] +
                       "' differ in their scene file or settings (" + kRenderKeyword + " " + *first + " and " +
                       *value + ")");
    }
  }
  return all ? first : std::nullopt;
}

// A tile's records and size, read and checked before any pixel is: the crop record (its
// fields in range), the image's size against the record's rectangle.
struct Tile {
  std::string path;
  CropRecord record;
  Records text;
};

Tile readTileRecords(const std::string& path, bool floatTiles) {
  Tile tile{path, {}, readImageText(path)};   // IoError: unreadable, empty, cut short
  int width = 0, height = 0;
  if (floatTiles) {
    RadianceImage info = readFloatImageInfo(path);
    width = info.width;
    height = info.height;
  } else {
    readImageSize(path, width, height);   // IoError: not an image stb_image reads
  }
  std::optional<std::string> value = onlyRecord(tile.text, kCropKeyword, "tile", path);
  if (!value)
    throw UsageError("tile '" + path + "' has no " + kCropKeyword + " record: it is not an image written with --crop" +
                     (recordOf(tile.text, kSamplesKeyword)
                          ? " (it is a whole image of a path-traced render: sample batches merge with batches of the "
                            "same place, the whole image or one crop, and tiles with tiles)"
                          : ""));
  std::string why;
  std::optional<CropRecord> record = parseCropRecord(*value, &why);
  if (!record)
    throw UsageError("tile '" + path + "': malformed " + kCropKeyword + " record '" + *value + "' (" + why + ")");
  tile.record = *record;
  if (width != record->rect.width() || height != record->rect.height())
    throw UsageError("tile '" + path + "' is " + std::to_string(width) + "x" + std::to_string(height) +
                     ", but its record says " + *value);
  return tile;
}

template <class Pixels>
Pixels readTilePixels(const Tile& tile) {
  Pixels image;
  if constexpr (std::is_same_v<Pixels, RadianceImage>)
    image = readFloatImage(tile.path);
  else
    image = readImage(tile.path);
  // The file was checked a moment ago; one changed since is refused, not copied out of bounds.
  if (image.width != tile.record.rect.width() || image.height != tile.record.rect.height())
    throw imageReadError(tile.path, "it changed while being merged");
  return image;
}

// A set of tiles checked to make one image of one render, with what the merged image carries:
// the tiles' samples record (path-traced tiles) and their render identity, as a full render.
struct CheckedTiles {
  std::vector<Tile> tiles;
  int fullWidth = 0, fullHeight = 0;
  std::uint64_t gaps = 0;
  std::optional<SampleRecord> samples;
  Records text;
  std::vector<std::string> warnings;
};

// Reads the tiles' records (no pixels) and checks them.
CheckedTiles checkTiles(const std::vector<std::string>& tilePaths, bool allowGaps, bool floatTiles) {
  if (tilePaths.empty()) throw UsageError("merge needs at least one tile");
  CheckedTiles checked;
  std::vector<Tile>& tiles = checked.tiles;
  for (const std::string& path : tilePaths) tiles.push_back(readTileRecords(path, floatTiles));
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
      if (std::max(a.x0, b.x0) < std::min(a.x1, b.x1) && std::max(a.y0, b.y0) < std::min(a.y1, b.y1)) {
        // The same crop twice, each holding samples: batches of that crop, given with another's.
        const bool batches = a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1 &&
                             recordOf(tiles[j].text, kSamplesKeyword) && recordOf(t.text, kSamplesKeyword);
        throw UsageError("tiles overlap: '" + tiles[j].path + "' (" + formatPixelRect(a) + ") and '" + t.path + "' (" +
                         formatPixelRect(b) + ")" +
                         (batches ? "; they are sample batches of one crop: merge each crop's batches first (vkrt "
                                    "merge -o CROP.pfm BATCH.pfm ...), then the crops"
                                  : ""));
      }
    }
    covered += static_cast<std::uint64_t>(t.record.rect.width()) * static_cast<std::uint64_t>(t.record.rect.height());
  }
  std::vector<Records> texts;
  for (const Tile& t : tiles) texts.push_back(t.text);
  std::optional<std::string> identity = checkIdentities(tilePaths, texts, "tile", "tiles", checked.warnings);
  // The tiles of one path-traced render carry one samples record; it goes with the image.
  std::optional<std::string> samples = onlyRecord(tiles.front().text, kSamplesKeyword, "tile", tiles.front().path);
  for (const Tile& t : tiles) {
    std::optional<std::string> value = onlyRecord(t.text, kSamplesKeyword, "tile", t.path);
    if (value != samples)
      throw UsageError("tiles of different renders: '" + tiles.front().path + "' holds " +
                       (samples ? "the samples " + *samples : std::string("no samples record")) + ", '" + t.path +
                       "' " + (value ? "the samples " + *value : std::string("no samples record")));
  }
  if (samples) {
    checked.samples = parseSampleRecord(*samples);
    if (!checked.samples)
      throw UsageError("tile '" + tiles.front().path + "': malformed " + kSamplesKeyword + " record '" + *samples + "'");
    checked.text.emplace_back(kSamplesKeyword, *samples);
    if (identity) checked.text.emplace_back(kRenderKeyword, *identity);
  }
  // The tiles do not overlap, so they cover every pixel exactly when their areas add up.
  checked.gaps = static_cast<std::uint64_t>(fullWidth) * static_cast<std::uint64_t>(fullHeight) - covered;
  if (checked.gaps > 0 && !allowGaps)
    throw UsageError(counted(checked.gaps, "pixel", "pixels") + " of the " + std::to_string(fullWidth) + "x" +
                     std::to_string(fullHeight) + (checked.gaps == 1 ? " image is" : " image are") + " in no tile (a tile missing?); --allow-gaps leaves "
                     "them black");
  checked.fullWidth = fullWidth;
  checked.fullHeight = fullHeight;
  return checked;
}

void fillReport(CheckedTiles& checked, MergeReport* report) {
  if (!report) return;
  report->tiles = static_cast<int>(checked.tiles.size());
  report->gapPixels = checked.gaps;
  report->samples = checked.samples ? *checked.samples : SampleRecord{};
  report->warnings = std::move(checked.warnings);
  report->width = checked.fullWidth;
  report->height = checked.fullHeight;
}

// Copies rows [y0, y0 + band.height) of `tile`'s image (rows of the full image) into `band`.
template <class Pixels>
void copyRows(const Tile& tile, const Pixels& image, int y0, Pixels& band) {
  const PixelRect& r = tile.record.rect;
  const int from = std::max(y0, r.y0), to = std::min(y0 + band.height, r.y1);
  for (int y = from; y < to; ++y)
    std::memcpy(band.pixel(r.x0, y - y0), image.pixel(0, y - r.y0),
                static_cast<std::size_t>(image.width) * 3 * sizeof(*image.pixel(0, 0)));
}

// The checked tiles, read one at a time and copied into the whole merged image.
template <class Pixels>
Pixels placeTiles(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report) {
  constexpr bool floatTiles = std::is_same_v<Pixels, RadianceImage>;
  CheckedTiles checked = checkTiles(tilePaths, allowGaps, floatTiles);
  Pixels merged(checked.fullWidth, checked.fullHeight);
  for (const Tile& t : checked.tiles) copyRows(t, readTilePixels<Pixels>(t), 0, merged);
  if (checked.samples) {
    if constexpr (floatTiles) merged.samples = checked.samples->total();
  }
  merged.text = checked.text;
  fillReport(checked, report);
  return merged;
}

// The checked tiles as bands of rows, top to bottom, to `sink`: a tile is read when the rows
// reach its top and dropped after its bottom, so memory is the tiles that share a row and a
// band of at most kMergeBandRows rows, not the merged image.
constexpr int kMergeBandRows = 64;

template <class Pixels>
void streamTiles(const CheckedTiles& checked, const std::function<void(int, const Pixels&)>& sink) {
  std::vector<const Tile*> order;
  for (const Tile& t : checked.tiles) order.push_back(&t);
  std::sort(order.begin(), order.end(),
            [](const Tile* a, const Tile* b) { return a->record.rect.y0 < b->record.rect.y0; });
  std::vector<std::pair<const Tile*, Pixels>> active;
  std::size_t next = 0;
  Pixels band;
  for (int y = 0; y < checked.fullHeight;) {
    while (next < order.size() && order[next]->record.rect.y0 <= y) {
      active.emplace_back(order[next], readTilePixels<Pixels>(*order[next]));
      ++next;
    }
    // The band ends before the next tile starts and where an active one ends.
    int end = std::min(checked.fullHeight, y + kMergeBandRows);
    if (next < order.size()) end = std::min(end, order[next]->record.rect.y0);
    for (const auto& [tile, image] : active) end = std::min(end, tile->record.rect.y1);
    band = Pixels(checked.fullWidth, end - y);   // black where no tile is
    for (const auto& [tile, image] : active) copyRows(*tile, image, y, band);
    sink(y, band);
    y = end;
    std::erase_if(active, [y](const auto& a) { return a.first->record.rect.y1 <= y; });
  }
}

// The name of the linear float format of `path` ("PFM"), read again: a file that has changed
// since is no longer one.
std::string floatFormatName(const std::string& path) {
  const ImageFormat* format = floatImageFormatOf(path);
  if (!format) throw imageReadError(path, "it changed while being merged");
  return std::string(format->name);
}

// "WHY: merge tiles of one kind (all PFM, or all PNG or PPM)".
std::string mixedTiles(const std::string& why) {
  return why + ": merge tiles of one kind (all " + imageFormatNamesText(FormatsOf::LinearFloat) + ", or all " +
         imageFormatNamesText(FormatsOf::Bytes) + ")";
}

}  // namespace

Image mergeCrops(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report) {
  for (const std::string& path : tilePaths)
    if (isFloatImageFile(path))
      throw UsageError(mixedTiles("tile '" + path + "' is " + withArticle(floatFormatName(path)) + " file"));
  return placeTiles<Image>(tilePaths, allowGaps, report);
}

RadianceImage mergeFloatCrops(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report) {
  for (const std::string& path : tilePaths)
    if (!isFloatImageFile(path))
      throw UsageError(mixedTiles("tile '" + path + "' is not a " + imageFormatNamesText(FormatsOf::LinearFloat) +
                                  " file, and '" + tilePaths.front() + "' is"));
  return placeTiles<RadianceImage>(tilePaths, allowGaps, report);
}

void writeMergedCrops(const std::vector<std::string>& tilePaths, bool allowGaps, const std::string& outputPath,
                      MergeReport* report) {
  // All linear float: float tiles; else 8-bit ones, and a float tile among them is refused
  // (mergeCrops).
  const bool floatTiles = !tilePaths.empty() && std::all_of(tilePaths.begin(), tilePaths.end(), isFloatImageFile);
  for (const std::string& path : tilePaths)
    if (!floatTiles && isFloatImageFile(path))
      throw UsageError(mixedTiles("tile '" + path + "' is " + withArticle(floatFormatName(path)) + " file"));
  CheckedTiles checked = checkTiles(tilePaths, allowGaps, floatTiles);
  if (floatTiles) {
    const double gamma = checked.samples ? checked.samples->gamma : 1.0;
    writeImageStreamed(outputPath, gamma, checked.fullWidth, checked.fullHeight, checked.text,
                       [&](const RowSink& sink) { streamTiles<RadianceImage>(checked, sink); });
  } else {
    writeBytesStreamed(outputPath, checked.fullWidth, checked.fullHeight, checked.text,
                       [&](const ByteRowSink& sink) { streamTiles<Image>(checked, sink); });
  }
  fillReport(checked, report);
}

void checkMergeInputsAreFiles(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    const platform::FileStatus st = platform::statusOf(path);
    if (!st.found()) throw imageReadError(path, std::strerror(st.error));
    if (st.is(platform::FileKind::Directory)) throw imageReadError(path, std::strerror(EISDIR));
    if (!st.is(platform::FileKind::Regular))
      throw imageReadError(path, "it is not a regular file (a pipe, FIFO or device), and merge reads each input more "
                                 "than once (its records first, then its pixels); save it to a file first");
  }
}

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

namespace {

// A sample batch's records, read and checked before any raster is.
struct Batch {
  std::string path;
  int width = 0, height = 0;
  SampleRecord record;
  std::optional<std::string> crop;
};

// The batch at `path`: a linear-float image whose samples (and crop) records are well formed
// and agree with its size; its records into `text`. Throws UsageError, IoError.
Batch readBatch(const std::string& path, Records& text) {
  if (!isFloatImageFile(path))
    throw UsageError("batch '" + path + "' is not a " + imageFormatNamesText(FormatsOf::LinearFloat) +
                     " file: sample batches are averaged from linear float images; render each batch with -o NAME" +
                     imageExtensionsText(FormatsOf::LinearFloat));
  RadianceImage info = readFloatImageInfo(path);   // IoError: unreadable or cut short
  Batch batch{path, info.width, info.height, {}, onlyRecord(info.text, kCropKeyword, "batch", path)};
  std::optional<std::string> value = onlyRecord(info.text, kSamplesKeyword, "batch", path);
  if (!value)
    throw UsageError("batch '" + path + "' has no " + kSamplesKeyword +
                     " record: it is not the image of a path-traced render");
  std::optional<SampleRecord> record = parseSampleRecord(*value);
  if (!record) throw UsageError("batch '" + path + "': malformed " + kSamplesKeyword + " record '" + *value + "'");
  batch.record = *record;
  if (batch.width > kMaxRecordedImageEdge || batch.height > kMaxRecordedImageEdge)
    throw UsageError("batch '" + path + "' is " + std::to_string(batch.width) + "x" + std::to_string(batch.height) +
                     ", larger than " + std::to_string(kMaxRecordedImageEdge) + " on a side");
  if (batch.crop) {
    std::string why;
    std::optional<CropRecord> crop = parseCropRecord(*batch.crop, &why);
    if (!crop)
      throw UsageError("batch '" + path + "': malformed " + kCropKeyword + " record '" + *batch.crop + "' (" + why +
                       ")");
    if (crop->rect.width() != batch.width || crop->rect.height() != batch.height)
      throw UsageError("batch '" + path + "' is " + std::to_string(batch.width) + "x" +
                       std::to_string(batch.height) + ", but its record says " + *batch.crop);
  }
  text = std::move(info.text);
  return batch;
}

// Throws UsageError where `batch` cannot be averaged with the batches before it: another size,
// place, gamma or sampler than the first's, or a sample that one of them holds too.
void checkAgainst(const std::vector<Batch>& before, const Batch& batch) {
  const std::string& path = batch.path;
  if (!before.empty()) {
    const Batch& first = before.front();
    if (batch.width != first.width || batch.height != first.height)
      throw UsageError("batches of different sizes: '" + first.path + "' is " + std::to_string(first.width) + "x" +
                       std::to_string(first.height) + ", '" + path + "' " + std::to_string(batch.width) + "x" +
                       std::to_string(batch.height));
    if (batch.crop != first.crop)
      throw UsageError("batches of different places: '" + first.path + "' is " +
                       (first.crop ? "the crop " + *first.crop : std::string("the whole image")) + ", '" + path +
                       "' " + (batch.crop ? "the crop " + *batch.crop : std::string("the whole image")));
    if (batch.record.gamma != first.record.gamma)
      throw UsageError("batches of different gammas: '" + first.path + "' has gamma " +
                       gammaText(first.record.gamma) + ", '" + path + "' gamma " + gammaText(batch.record.gamma));
    auto sampler = [](const SampleRecord& r) { return r.stratified ? "stratified" : "independent"; };
    if (batch.record.stratified != first.record.stratified)
      throw UsageError("batches of different samplers: '" + first.path + "' holds " + sampler(first.record) +
                       " samples, '" + path + "' " + sampler(batch.record) + " ones (--sampler)");
  }
  for (const Batch& other : before) {
    std::string shared = sharedSample(other.record, batch.record);
    if (!shared.empty())
      throw UsageError("batches '" + other.path + "' and '" + path + "' hold the same samples (" + shared +
                       "): render each batch with its own --seed");
  }
}

}  // namespace

RadianceImage mergeSampleBatches(const std::vector<std::string>& paths, MergeReport* report) {
  if (paths.empty()) throw UsageError("merge needs at least one batch");
  // The records of every batch first, checked before any raster is read.
  std::vector<Batch> batches;
  std::vector<Records> texts;
  SampleRecord merged;
  std::uint64_t total = 0;
  for (const std::string& path : paths) {
    Records text;
    Batch batch = readBatch(path, text);
    checkAgainst(batches, batch);
    if (batch.record.total() > std::numeric_limits<std::uint64_t>::max() - total)
      throw UsageError("batch '" + path + "': the batches hold more than 2^64 samples per pixel in all");
    total += batch.record.total();
    merged.ranges.insert(merged.ranges.end(), batch.record.ranges.begin(), batch.record.ranges.end());
    texts.push_back(std::move(text));
    batches.push_back(std::move(batch));
  }
  std::vector<std::string> warnings;
  std::optional<std::string> identity = checkIdentities(paths, texts, "batch", "batches", warnings);
  merged.gamma = batches.front().record.gamma;
  merged.stratified = batches.front().record.stratified;
  // One order whatever the command line's (a shell's glob puts batch-10 before batch-2): the
  // batches by their first samples, seed then index, so that the mean's rounding, and so its
  // bits, are those of the batches taken in sample order (as --watch and --time add them), and
  // the record lists its ranges in that order.
  auto byFirstSample = [](const SampleRange& a, const SampleRange& b) {
    return a.seed != b.seed ? a.seed < b.seed : a.first < b.first;
  };
  auto firstSample = [&](const Batch& b) {
    return *std::min_element(b.record.ranges.begin(), b.record.ranges.end(), byFirstSample);
  };
  std::stable_sort(batches.begin(), batches.end(),
                   [&](const Batch& a, const Batch& b) { return byFirstSample(firstSample(a), firstSample(b)); });
  std::sort(merged.ranges.begin(), merged.ranges.end(), byFirstSample);

  // The rasters, one at a time, into the running mean.
  RadianceImage mean;
  mean.samples = 0;
  for (const Batch& b : batches) {
    RadianceImage pixels = readFloatImage(b.path);
    if (pixels.width != b.width || pixels.height != b.height)
      throw imageReadError(b.path, "it changed while being merged");
    pixels.samples = b.record.total();
    pixels.text.clear();
    accumulateMean(mean, std::move(pixels));
  }
  mean.text.clear();
  if (batches.front().crop) mean.text.emplace_back(kCropKeyword, *batches.front().crop);
  mean.text.emplace_back(kSamplesKeyword, formatSampleRecord(merged));
  if (identity) mean.text.emplace_back(kRenderKeyword, *identity);
  if (report) {
    report->tiles = static_cast<int>(paths.size());
    report->gapPixels = 0;
    report->samples = merged;
    report->warnings = std::move(warnings);
  }
  return mean;
}

}  // namespace vkrt
