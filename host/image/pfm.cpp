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

#include "errors.h"
#include "image/atomic_file.h"
#include "interrupt.h"

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
  auto bad = [&](const std::string& why) { return IoError("cannot read image '" + path + "': " + why); };
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

void writePfmAtomic(const RadianceImage& image, const std::string& path) {
  static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559);
  writeFileAtomic(path, ".pfm.tmp", [&](int fd) {
    std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    writeAll(fd, reinterpret_cast<const std::uint8_t*>(header.data()), header.size(), path);
    const std::size_t rowFloats = static_cast<std::size_t>(image.width) * 3;
    std::vector<std::uint32_t> row(rowFloats);
    for (int y = image.height - 1; y >= 0; --y) {   // bottom row first
      if ((y & 63) == 0) throwIfInterrupted();
      std::memcpy(row.data(), image.pixel(0, y), rowFloats * 4);
      if constexpr (std::endian::native == std::endian::big)
        for (std::uint32_t& v : row) v = byteSwap(v);
      writeAll(fd, reinterpret_cast<const std::uint8_t*>(row.data()), rowFloats * 4, path);
    }
    if (!image.text.empty()) {
      std::string trailer = kTrailer;
      for (const auto& [keyword, value] : image.text) trailer += keyword + " " + value + "\n";
      writeAll(fd, reinterpret_cast<const std::uint8_t*>(trailer.data()), trailer.size(), path);
    }
  });
}

namespace {

// Reads the raster (when `pixels`) and the trailer's records.
RadianceImage readPfmParts(const std::string& path, bool pixels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read image '" + path + "': " + std::strerror(errno));
  Header h = readHeader(in, path);
  RadianceImage image;
  const std::size_t values = static_cast<std::size_t>(h.width) * h.height * h.channels;
  if (pixels) {
    image = RadianceImage(h.width, h.height);
    std::vector<std::uint32_t> row(static_cast<std::size_t>(h.width) * h.channels);
    for (int y = h.height - 1; y >= 0; --y) {
      if (!in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size() * 4)))
        throw IoError("cannot read image '" + path + "': the PFM raster is truncated");
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
