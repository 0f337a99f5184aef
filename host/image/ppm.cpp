// PPM writing: the header, then the image's rows as they are in memory (Image is already
// 8-bit RGB, top row first, as P6 wants), a band of rows per write() so that a Ctrl-C is
// seen during a large image; reading the header's records; and reading binary Netpbm images
// (stb_image's reader keeps the low byte of a 16-bit sample and does not scale a maxval
// below 255, so vkrt reads them itself).
#include "image/ppm.h"


#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>

#include "util/errors.h"
#include "image/atomic_file.h"
#include "platform/file_status.h"
#include "util/interrupt.h"

namespace vkrt {
namespace {

class PpmRowWriter : public RowWriter {
 public:
  PpmRowWriter(ByteSink& sink, int width, int height, const ImageRecords& records) : sink_(sink), height_(height) {
    std::string header = "P6\n";
    for (const auto& [keyword, value] : records) header += "# " + keyword + " " + value + "\n";
    header += std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    sink.write(reinterpret_cast<const std::uint8_t*>(header.data()), header.size());
  }

  void byteRows(int, const Image& band) override {
    constexpr int kRowsPerWrite = 64;
    for (int y = 0; y < band.height; y += kRowsPerWrite) {
      throwIfInterrupted();
      int rows = std::min(kRowsPerWrite, band.height - y);
      sink_.write(band.pixel(0, y), static_cast<std::size_t>(rows) * static_cast<std::size_t>(band.width) * 3);
    }
    rows_ += band.height;
  }

  void finish() override {
    if (rows_ != height_)
      throw InternalError("PpmRowWriter: " + std::to_string(rows_) + " rows of " + std::to_string(height_));
  }

 private:
  ByteSink& sink_;
  int height_, rows_ = 0;
};

}  // namespace

std::unique_ptr<RowWriter> openPpmRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string&) {
  return std::make_unique<PpmRowWriter>(sink, width, height, records);
}

void writePpmAtomic(const Image& image, const std::string& path) {
  writeFileAtomic(path, ".ppm.tmp", [&](ByteSink& file) {
    PpmRowWriter ppm(file, image.width, image.height, image.text);
    ppm.byteRows(0, image);
    ppm.finish();
  });
}

bool isPpmFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[2] = {};
  in.read(magic, 2);
  return in.gcount() == 2 && magic[0] == 'P' && magic[1] == '6';
}

namespace {

// Why a read of `in` stopped short: the system's reason for a failed read (a FIFO's read cut
// short by a signal: "Interrupted system call"), else `atEnd`, the file having ended.
IoError stoppedShort(std::FILE* in, const std::string& path, const std::string& atEnd) {
  return imageReadError(path, std::ferror(in) ? std::strerror(errno) : atEnd);
}

// Netpbm's whitespace (the C locale's isspace).
bool isBlank(int c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f'; }

struct NetpbmHeader {
  std::uint64_t width = 0, height = 0, maxval = 0;
  int channels = 3;     // 3 for P6, 1 for P5
  ImageRecords text;    // the comment lines "# KEYWORD TEXT"
  // One sample's bytes: a maxval above 255 takes two, most significant first.
  std::uint64_t sampleBytes() const { return maxval > 255 ? 2 : 1; }
  std::uint64_t rowBytes() const { return width * static_cast<std::uint64_t>(channels) * sampleBytes(); }
};

// The header after the magic number: width, height and maxval, words of digits with
// whitespace and "#" comment lines (records when "# KEYWORD TEXT") between them, read up to
// and including the single whitespace byte after the maxval, where the raster starts.
NetpbmHeader readHeader(std::FILE* in, char kind, const std::string& path) {
  NetpbmHeader h;
  h.channels = kind == '5' ? 1 : 3;
  std::uint64_t* numbers[3] = {&h.width, &h.height, &h.maxval};
  int count = 0;
  int c = std::getc(in);
  while (count < 3) {
    if (c == EOF) throw stoppedShort(in, path, "the PPM header is truncated");
    if (c == '#') {
      std::string line = "#";
      while ((c = std::getc(in)) != EOF && c != '\n') line += static_cast<char>(c);
      std::size_t space = line.find(' ', 2);
      if (line.size() > 2 && line[1] == ' ' && space != std::string::npos)
        h.text.emplace_back(line.substr(2, space - 2), line.substr(space + 1));
    } else if (isBlank(c)) {
      c = std::getc(in);
    } else {
      // At most 10 characters are kept: the 9 digits a number may have and one more to refuse.
      std::string word;
      for (; c != EOF && !isBlank(c); c = std::getc(in))
        if (word.size() < 10) word += static_cast<char>(c);
      if (word.size() > 9 || word.find_first_not_of("0123456789") != std::string::npos)
        throw imageReadError(path, "the PPM header is malformed ('" + word + "')");
      *numbers[count++] = std::stoull(word);
    }
  }
  if (c == EOF && std::ferror(in)) throw stoppedShort(in, path, "");
  return h;
}

// What every read checks before the raster: the maxval in the Netpbm spec's range, at
// least one pixel, and samples that fit in memory as stb_image allowed them (2^31 bytes).
void checkHeader(const NetpbmHeader& h, const std::string& path) {
  if (h.maxval < 1 || h.maxval > 65535)
    throw imageReadError(path, "its maxval is " + std::to_string(h.maxval) + ", and a PPM's maxval is 1 to 65535");
  checkImageHasPixels(path, static_cast<std::int64_t>(h.width), static_cast<std::int64_t>(h.height));
  if (h.width * h.height * 3 * h.sampleBytes() > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
    throw imageReadError(path, "it is " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                         " pixels, more than vkrt reads from a PPM (2 GiB of samples)");
}

// A regular file's raster must be all there, checked before it is allocated (a header may
// claim a billion pixels); a FIFO's ends where it ends, found as it is read.
void checkRasterIsThere(std::FILE* in, const NetpbmHeader& h, const std::string& path) {
  const long at = std::ftell(in);
  const platform::FileStatus st = platform::statusOfOpen(in);
  if (!st.is(platform::FileKind::Regular) || at < 0) return;
  const std::uint64_t raster = h.rowBytes() * h.height;
  if (static_cast<std::uint64_t>(at) + raster > st.size)
    throw imageReadError(path, "the PPM raster is truncated (" + std::to_string(h.width) + "x" +
                         std::to_string(h.height) + " pixels need " + std::to_string(raster) + " bytes)");
}

// Each sample value 0..maxval as a byte, round(v * 255 / maxval).
std::vector<std::uint8_t> byteOfSample(std::uint64_t maxval) {
  std::vector<std::uint8_t> table(maxval + 1);
  for (std::uint64_t v = 0; v <= maxval; ++v) table[v] = static_cast<std::uint8_t>((v * 255 + maxval / 2) / maxval);
  return table;
}

// The raster after the header, as 8-bit RGB.
Image readRaster(std::FILE* in, const NetpbmHeader& h, const std::string& path) {
  checkRasterIsThere(in, h, path);
  const std::vector<std::uint8_t> toByte = byteOfSample(h.maxval);
  const auto samplesPerRow = static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.channels);
  const bool wide = h.sampleBytes() == 2;
  Image image(static_cast<int>(h.width), static_cast<int>(h.height));
  std::vector<std::uint8_t> row(static_cast<std::size_t>(h.rowBytes()));
  for (int y = 0; y < image.height; ++y) {
    if (std::fread(row.data(), 1, row.size(), in) != row.size())
      throw stoppedShort(in, path, "the PPM raster is truncated");
    std::uint8_t* out = image.pixel(0, y);
    for (std::size_t i = 0; i < samplesPerRow; ++i) {
      const std::uint64_t v = wide ? std::uint64_t{row[2 * i]} << 8 | row[2 * i + 1] : row[i];
      const std::uint8_t b = v > h.maxval ? 255 : toByte[v];   // above maxval: invalid, read as full scale
      if (h.channels == 3)
        out[i] = b;
      else
        out[3 * i] = out[3 * i + 1] = out[3 * i + 2] = b;
    }
  }
  return image;
}

}  // namespace

ImageRecords readPpmText(const std::string& path) {
  ImageFileHandle in = openImageFile(path);
  char magic[2] = {};
  if (std::fread(magic, 1, 2, in.get()) != 2 || magic[0] != 'P' || magic[1] != '6')
    throw stoppedShort(in.get(), path, "not a binary PPM (no P6)");
  // The header's comment lines, "# KEY VALUE", up to the maxval; then the raster, which
  // must be all there.
  NetpbmHeader h = readHeader(in.get(), magic[1], path);
  checkHeader(h, path);
  checkRasterIsThere(in.get(), h, path);
  return std::move(h.text);
}

bool isBinaryNetpbm(const unsigned char* head, std::size_t size) {
  return size >= 2 && head[0] == 'P' && (head[1] == '6' || head[1] == '5');
}

Image readBinaryNetpbm(std::FILE* in, char kind, const std::string& path) {
  NetpbmHeader h = readHeader(in, kind, path);
  checkHeader(h, path);
  return readRaster(in, h, path);   // the records are readPpmText's (readAnyImage reads them)
}

void readBinaryNetpbmSize(std::FILE* in, char kind, const std::string& path, int& width, int& height) {
  const NetpbmHeader h = readHeader(in, kind, path);
  checkHeader(h, path);
  width = static_cast<int>(h.width);
  height = static_cast<int>(h.height);
}

}  // namespace vkrt
