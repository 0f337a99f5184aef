// PFM writing and reading: a header of three text lines, the raster bottom row first, then
// vkrt's trailer of records.
#include "image/pfm.h"

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

#include "util/errors.h"
#include "image/atomic_file.h"
#include "util/interrupt.h"

namespace vkrt {
namespace {

constexpr const char* kTrailer = "#vkrt-records\n";

std::uint32_t byteSwap(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

// The header's next whitespace-separated word (the three lines are read as words, the
// format's own rule; a single whitespace byte ends the scale).
bool readWord(std::istream& in, std::string& word) {
  word.clear();
  int c;
  while ((c = in.get()) != EOF && (c == ' ' || c == '\n' || c == '\r' || c == '\t')) {}
  if (c == EOF) return false;
  word += static_cast<char>(c);
  while ((c = in.peek()) != EOF && !(c == ' ' || c == '\n' || c == '\r' || c == '\t')) word += static_cast<char>(in.get());
  return true;
}

struct Header {
  int width = 0, height = 0, channels = 3;
  bool littleEndian = true;
};

Header readHeader(std::istream& in, const std::string& path) {
  Header h;
  std::string magic, w, ht, scale;
  auto bad = [&](const std::string& why) { return imageReadError(path, why); };
  if (!readWord(in, magic) || (magic != "PF" && magic != "Pf")) throw bad("not a PFM file (no PF or Pf)");
  h.channels = magic == "PF" ? 3 : 1;
  if (!readWord(in, w) || !readWord(in, ht) || !readWord(in, scale)) throw bad("truncated PFM header");
  try {
    std::size_t used = 0;
    long long lw = std::stoll(w, &used);
    if (used != w.size()) throw std::invalid_argument(w);
    long long lh = std::stoll(ht, &used);
    if (used != ht.size()) throw std::invalid_argument(ht);
    double s = std::stod(scale, &used);
    if (used != scale.size() || s == 0.0 || !std::isfinite(s)) throw std::invalid_argument(scale);
    if (lw == 0 || lh == 0) checkImageHasPixels(path, lw, lh);
    if (lw < 1 || lh < 1 || lw > (1 << 20) || lh > (1 << 20)) throw std::invalid_argument(w);
    h.width = static_cast<int>(lw);
    h.height = static_cast<int>(lh);
    h.littleEndian = s < 0.0;
  } catch (const std::logic_error&) {
    throw bad("malformed PFM header ('" + w + " " + ht + " " + scale + "')");
  }
  in.get();   // the single whitespace byte after the scale
  return h;
}

}  // namespace

PfmRowWriter::PfmRowWriter(ByteSink& sink, int width, int height,
                           const std::vector<std::pair<std::string, std::string>>& records)
    : sink_(sink), width_(width), height_(height), records_(records) {
  static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559);
  std::string header = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
  sink.write(reinterpret_cast<const std::uint8_t*>(header.data()), header.size());
  headerBytes_ = header.size();
}

void PfmRowWriter::radianceRows(int y0, const RadianceImage& band) {
  if (band.width != width_ || y0 < 0 || band.height > height_ - y0)
    throw InternalError("PfmRowWriter: rows " + std::to_string(y0) + "+" + std::to_string(band.height) + " of a " +
                        std::to_string(width_) + "x" + std::to_string(height_) + " image");
  const std::size_t rowFloats = static_cast<std::size_t>(width_) * 3;
  row_.resize(rowFloats);
  for (int y = 0; y < band.height; ++y) {
    if ((y & 63) == 0) throwIfInterrupted();
    std::memcpy(row_.data(), band.pixel(0, y), rowFloats * 4);
    if constexpr (std::endian::native == std::endian::big)
      for (std::uint32_t& v : row_) v = byteSwap(v);
    // Image row y0 + y is file row height - 1 - (y0 + y): the raster is bottom row first.
    const auto fileRow = static_cast<std::uint64_t>(height_ - 1 - (y0 + y));
    sink_.writeAt(reinterpret_cast<const std::uint8_t*>(row_.data()), rowFloats * 4,
                  headerBytes_ + fileRow * rowFloats * 4);
  }
  written_ += static_cast<std::uint64_t>(band.height);
}

void PfmRowWriter::finish() {
  if (written_ != static_cast<std::uint64_t>(height_))
    throw InternalError("PfmRowWriter: " + std::to_string(written_) + " rows of " + std::to_string(height_));
  if (records_.empty()) return;
  std::string trailer = kTrailer;
  for (const auto& [keyword, value] : records_) trailer += keyword + " " + value + "\n";
  const std::uint64_t end = headerBytes_ + static_cast<std::uint64_t>(width_) * 12 * static_cast<std::uint64_t>(height_);
  sink_.writeAt(reinterpret_cast<const std::uint8_t*>(trailer.data()), trailer.size(), end);
}

std::unique_ptr<RowWriter> openPfmRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string&) {
  return std::make_unique<PfmRowWriter>(sink, width, height, records);
}

void writePfmAtomic(const RadianceImage& image, const std::string& path) {
  writeFileAtomic(path, ".pfm.tmp", [&](ByteSink& file) {
    PfmRowWriter pfm(file, image.width, image.height, image.text);
    pfm.radianceRows(0, image);
    pfm.finish();
  });
}

namespace {

// Reads the raster (when `pixels`) and the trailer's records.
RadianceImage readPfmParts(const std::string& path, bool pixels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw imageReadError(path, std::strerror(errno));
  Header h = readHeader(in, path);
  RadianceImage image;
  const std::size_t values = static_cast<std::size_t>(h.width) * h.height * h.channels;
  // The raster must be all there: checked before allocating (a header may claim 2^20 x 2^20).
  const std::streamoff rasterStart = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff fileSize = in.tellg();
  in.seekg(rasterStart);
  if (rasterStart < 0 || fileSize < 0 ||
      static_cast<std::uint64_t>(fileSize - rasterStart) < static_cast<std::uint64_t>(values) * 4)
    throw imageReadError(path, "the PFM raster is truncated (" +
                         std::to_string(h.width) + "x" + std::to_string(h.height) + " pixels need " +
                  std::to_string(static_cast<std::uint64_t>(values) * 4) + " bytes)");
  if (pixels) {
    image = RadianceImage(h.width, h.height);
    std::vector<std::uint32_t> row(static_cast<std::size_t>(h.width) * h.channels);
    for (int y = h.height - 1; y >= 0; --y) {
      if (!in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size() * 4)))
        throw imageReadError(path, "the PFM raster is truncated");
      const bool swap = h.littleEndian != (std::endian::native == std::endian::little);
      float* out = image.pixel(0, y);
      for (int x = 0; x < h.width; ++x)
        for (int c = 0; c < 3; ++c) {
          std::uint32_t v = row[static_cast<std::size_t>(x) * h.channels + (h.channels == 3 ? c : 0)];
          out[3 * x + c] = std::bit_cast<float>(swap ? byteSwap(v) : v);
        }
    }
  } else {
    image.width = h.width;
    image.height = h.height;
    in.seekg(static_cast<std::streamoff>(values * 4), std::ios::cur);
  }
  std::string line;
  if (in && std::getline(in, line) && line + "\n" == kTrailer) {
    while (std::getline(in, line)) {
      std::size_t space = line.find(' ');
      if (space == std::string::npos || space == 0) continue;
      image.text.emplace_back(line.substr(0, space), line.substr(space + 1));
    }
  }
  return image;
}

}  // namespace

RadianceImage readPfm(const std::string& path) { return readPfmParts(path, true); }

RadianceImage readPfmInfo(const std::string& path) { return readPfmParts(path, false); }

std::vector<std::pair<std::string, std::string>> readPfmText(const std::string& path) {
  return readPfmParts(path, false).text;
}

bool isPfmFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[3] = {};
  in.read(head, 3);
  return in.gcount() == 3 && head[0] == 'P' && (head[1] == 'F' || head[1] == 'f') &&
         (head[2] == '\n' || head[2] == '\r' || head[2] == ' ');
}

}  // namespace vkrt
