// PNG writing, streamed row by row through zlib (memory: the image plus about a megabyte, so
// a 16384x16384 image needs no second copy; and a Ctrl-C is seen between rows), and reading
// with stb_image. stb_image_write cannot stream: it builds the filtered image and the whole
// compressed stream in memory, three times the image in all.
#include "image/png.h"

#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

#include <zlib.h>

#include "image/atomic_file.h"
#include "image/encode.h"
#include "interrupt.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace vkrt {
namespace {

void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// One PNG chunk: length, type, data, CRC of type and data.
void writeChunk(int fd, const char type[4], const std::uint8_t* data, std::size_t size, const std::string& path) {
  std::vector<std::uint8_t> head;
  putBigEndian(head, static_cast<std::uint32_t>(size));
  head.insert(head.end(), type, type + 4);
  uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type), 4);
  if (size > 0) crc = crc32(crc, data, static_cast<uInt>(size));
  writeAll(fd, head.data(), head.size(), path);
  writeAll(fd, data, size, path);
  std::vector<std::uint8_t> tail;
  putBigEndian(tail, static_cast<std::uint32_t>(crc));
  writeAll(fd, tail.data(), tail.size(), path);
}

int paeth(int a, int b, int c) {
  int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
}

// Filters one row (PNG filter types 0-4) with the type whose output has the least sum of
// absolute values, the usual heuristic; out[0] gets the type.
void filterRow(const std::uint8_t* row, const std::uint8_t* above, std::size_t bytes, std::vector<std::uint8_t>& out,
               std::vector<std::uint8_t>& trial) {
  constexpr std::size_t bpp = 3;
  long best = -1;
  for (std::uint8_t type = 0; type <= 4; ++type) {
    trial[0] = type;
    long cost = 0;
    for (std::size_t i = 0; i < bytes; ++i) {
      int a = i >= bpp ? row[i - bpp] : 0, b = above ? above[i] : 0, c = above && i >= bpp ? above[i - bpp] : 0;
      int predicted = type == 0 ? 0 : type == 1 ? a : type == 2 ? b : type == 3 ? (a + b) / 2 : paeth(a, b, c);
      auto v = static_cast<std::uint8_t>(row[i] - predicted);
      trial[i + 1] = v;
      cost += v < 128 ? v : 256 - v;
    }
    if (best < 0 || cost < best) {
      best = cost;
      out.swap(trial);
    }
  }
}

// `row(y, out)` fills out (width * 3 bytes) with row y, top first, each row once in order.
void writePngStream(int fd, int width, int height, const std::vector<std::pair<std::string, std::string>>& records,
                    const std::function<void(int, std::uint8_t*)>& row, const std::string& path) {
  static const std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  writeAll(fd, kSignature, sizeof kSignature, path);
  std::vector<std::uint8_t> header;
  putBigEndian(header, static_cast<std::uint32_t>(width));
  putBigEndian(header, static_cast<std::uint32_t>(height));
  header.insert(header.end(), {8, 2, 0, 0, 0});   // 8 bits, RGB, deflate, filters, no interlace
  writeChunk(fd, "IHDR", header.data(), header.size(), path);
  for (const auto& [keyword, value] : records) {
    std::vector<std::uint8_t> text(keyword.begin(), keyword.end());
    text.push_back(0);
    text.insert(text.end(), value.begin(), value.end());
    writeChunk(fd, "tEXt", text.data(), text.size(), path);
  }

  z_stream z{};
  if (int rc = deflateInit(&z, 1); rc != Z_OK) {
    if (rc == Z_MEM_ERROR) throw OutOfMemory("no memory for the PNG compressor writing '" + path + "'");
    throw IoError("cannot write '" + path + "': zlib failed to start");
  }
  std::vector<std::uint8_t> compressed(1u << 20);
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 3;
  std::vector<std::uint8_t> filtered(rowBytes + 1), trial(rowBytes + 1), current(rowBytes), above(rowBytes);
  auto pump = [&](int flush) {
    do {
      z.next_out = compressed.data();
      z.avail_out = static_cast<uInt>(compressed.size());
      int rc = deflate(&z, flush);
      if (rc == Z_STREAM_ERROR) throw IoError("cannot write '" + path + "': zlib failed");
      std::size_t produced = compressed.size() - z.avail_out;
      if (produced > 0) writeChunk(fd, "IDAT", compressed.data(), produced, path);
    } while (z.avail_out == 0);
  };
  try {
    for (int y = 0; y < height; ++y) {
      throwIfInterrupted();
      row(y, current.data());
      filterRow(current.data(), y > 0 ? above.data() : nullptr, rowBytes, filtered, trial);
      current.swap(above);
      z.next_in = filtered.data();
      z.avail_in = static_cast<uInt>(filtered.size());
      pump(Z_NO_FLUSH);
    }
    pump(Z_FINISH);
  } catch (...) {
    deflateEnd(&z);
    throw;
  }
  deflateEnd(&z);
  writeChunk(fd, "IEND", nullptr, 0, path);
}

}  // namespace

void writePngAtomic(const Image& image, const std::string& path) {
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 3;
  writeFileAtomic(path, ".png.tmp", [&](int fd) {
    writePngStream(fd, image.width, image.height, image.text,
                   [&](int y, std::uint8_t* out) { std::memcpy(out, image.pixel(0, y), rowBytes); }, path);
  });
}

void writePngAtomic(const RadianceImage& image, double gamma, const std::string& path) {
  writeFileAtomic(path, ".png.tmp", [&](int fd) {
    writePngStream(fd, image.width, image.height, image.text,
                   [&](int y, std::uint8_t* out) {
                     const float* in = image.pixel(0, y);
                     for (std::size_t i = 0, n = static_cast<std::size_t>(image.width) * 3; i < n; ++i)
                       out[i] = encodeChannel(in[i], gamma);
                   },
                   path);
  });
}

Image readImage(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) throw IoError("cannot read image '" + path + "': " + stbi_failure_reason());
  Image img(w, h);
  std::memcpy(img.rgb.data(), data, img.rgb.size());
  stbi_image_free(data);
  return img;
}

}  // namespace vkrt
