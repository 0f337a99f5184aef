// PPM writing: the header, then the image's rows as they are in memory (Image is already
// 8-bit RGB, top row first, as P6 wants), a band of rows per write() so that a Ctrl-C is
// seen during a large image; and reading the header's records.
#include "image/ppm.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "errors.h"
#include "image/atomic_file.h"
#include "interrupt.h"

namespace vkrt {
namespace {

class PpmRowWriter : public RowWriter {
 public:
  PpmRowWriter(int fd, int width, int height, const ImageRecords& records, const std::string& path)
      : fd_(fd), height_(height), path_(path) {
    std::string header = "P6\n";
    for (const auto& [keyword, value] : records) header += "# " + keyword + " " + value + "\n";
    header += std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    writeAll(fd, reinterpret_cast<const std::uint8_t*>(header.data()), header.size(), path);
  }

  void byteRows(int, const Image& band) override {
    constexpr int kRowsPerWrite = 64;
    for (int y = 0; y < band.height; y += kRowsPerWrite) {
      throwIfInterrupted();
      int rows = std::min(kRowsPerWrite, band.height - y);
      writeAll(fd_, band.pixel(0, y), static_cast<std::size_t>(rows) * static_cast<std::size_t>(band.width) * 3,
               path_);
    }
    rows_ += band.height;
  }

  void finish() override {
    if (rows_ != height_)
      throw InternalError("PpmRowWriter: " + std::to_string(rows_) + " rows of " + std::to_string(height_));
  }

 private:
  int fd_, height_, rows_ = 0;
  std::string path_;
};

}  // namespace

std::unique_ptr<RowWriter> openPpmRows(int fd, int width, int height, const ImageRecords& records,
                                       const std::string& path) {
  return std::make_unique<PpmRowWriter>(fd, width, height, records, path);
}

void writePpmAtomic(const Image& image, const std::string& path) {
  writeFileAtomic(path, ".ppm.tmp", [&](int fd) {
    PpmRowWriter ppm(fd, image.width, image.height, image.text, path);
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

ImageRecords readPpmText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read image '" + path + "': " + std::strerror(errno));
  auto cutShort = [&](const std::string& what) { return IoError("cannot read image '" + path + "': " + what); };
  in.seekg(0, std::ios::end);
  const auto fileSize = static_cast<std::uint64_t>(std::max<std::streamoff>(0, in.tellg()));
  // The header's comment lines, "# KEY VALUE", up to the maxval; then the raster, which
  // must be all there.
  in.seekg(2);
  ImageRecords text;
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
  return text;
}

}  // namespace vkrt
