// PNG writing, streamed row by row through zlib (memory: about a megabyte besides the rows
// handed in, so a render's bands can be encoded as they come; and a Ctrl-C is seen between
// rows), and reading its records. stb_image_write cannot stream: it builds the filtered image
// and the whole compressed stream in memory, three times the image in all.
#include "image/png.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <vector>

#include <zlib.h>

#include "image/atomic_file.h"
#include "image/encode.h"
#include "util/interrupt.h"

namespace vkrt {
namespace {

constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

std::uint32_t bigEndian(const unsigned char* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | std::uint32_t{p[3]};
}

void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// One PNG chunk: length, type, data, CRC of type and data.
void writeChunk(ByteSink& sink, const char type[4], const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> head;
  putBigEndian(head, static_cast<std::uint32_t>(size));
  head.insert(head.end(), type, type + 4);
  uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type), 4);
  if (size > 0) crc = crc32(crc, data, static_cast<uInt>(size));
  sink.write(head.data(), head.size());
  sink.write(data, size);
  std::vector<std::uint8_t> tail;
  putBigEndian(tail, static_cast<std::uint32_t>(crc));
  sink.write(tail.data(), tail.size());
}

constexpr std::size_t kBpp = 3;   // bytes per pixel: 8-bit RGB

// One PNG filter type over a row: out[i] = row[i] - predict(a, b, c), where a is the byte a
// pixel to the left, b the byte above and c the byte above-left (0 outside the image).
// Returns the sum of the outputs read as signed bytes' magnitudes, the usual heuristic's
// cost. The first pixel, which has nothing to its left, gets a loop of its own, so that the
// rest runs without a branch and the compiler vectorises it (bench/README.md, "Fixed cost of
// the Vulkan backend"). `out` must not overlap `row` or `above`.
template <class Predict>
long filterWith(const std::uint8_t* __restrict row, const std::uint8_t* __restrict above, std::size_t bytes,
                std::uint8_t* __restrict out, Predict predict) {
  long cost = 0;
  auto put = [&](std::size_t i, int a, int b, int c) {
    auto v = static_cast<std::uint8_t>(row[i] - predict(a, b, c));
    out[i] = v;
    cost += std::min(v, static_cast<std::uint8_t>(-v));
  };
  for (std::size_t i = 0; i < std::min(bytes, kBpp); ++i) put(i, 0, above[i], 0);
  for (std::size_t i = kBpp; i < bytes; ++i) put(i, row[i - kBpp], above[i], above[i - kBpp]);
  return cost;
}

// Filters one row with the type (PNG filter types 0-4) whose output costs least, the first
// such; out[0] gets the type. `above` is the row before, all zeros for the first.
void filterRow(const std::uint8_t* row, const std::uint8_t* above, std::size_t bytes, std::vector<std::uint8_t>& out,
               std::vector<std::uint8_t>& trial) {
  long best = -1;
  auto consider = [&](std::uint8_t type, auto predict) {
    trial[0] = type;
    long cost = filterWith(row, above, bytes, trial.data() + 1, predict);
    if (best < 0 || cost < best) {
      best = cost;
      out.swap(trial);
    }
  };
  consider(0, [](int, int, int) { return 0; });
  consider(1, [](int a, int, int) { return a; });
  consider(2, [](int, int b, int) { return b; });
  consider(3, [](int a, int b, int) { return (a + b) >> 1; });
  consider(4, [](int a, int b, int c) {   // Paeth: of a, b and c, the nearest to a + b - c
    int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
    return pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
  });
}

}  // namespace

struct PngRowEncoder::State {
  z_stream z{};
  bool started = false;
  std::vector<std::uint8_t> compressed, filtered, trial;
  std::vector<std::uint8_t> above;   // the row before; zeros before the first
};

PngRowEncoder::PngRowEncoder(ByteSink& sink, int width, int height,
                             const std::vector<std::pair<std::string, std::string>>& records, const std::string& path)
    : sink_(sink), height_(height), rowBytes_(static_cast<std::size_t>(width) * 3), path_(path),
      state_(std::make_unique<State>()) {
  sink.write(kSignature, sizeof kSignature);
  std::vector<std::uint8_t> header;
  putBigEndian(header, static_cast<std::uint32_t>(width));
  putBigEndian(header, static_cast<std::uint32_t>(height));
  header.insert(header.end(), {8, 2, 0, 0, 0});   // 8 bits, RGB, deflate, filters, no interlace
  writeChunk(sink, "IHDR", header.data(), header.size());
  for (const auto& [keyword, value] : records) {
    std::vector<std::uint8_t> text(keyword.begin(), keyword.end());
    text.push_back(0);
    text.insert(text.end(), value.begin(), value.end());
    writeChunk(sink, "tEXt", text.data(), text.size());
  }
  if (int rc = deflateInit(&state_->z, 1); rc != Z_OK) {
    if (rc == Z_MEM_ERROR) throw OutOfMemory("no memory for the PNG compressor writing '" + path + "'");
    throw IoError("cannot write '" + path + "': zlib failed to start");
  }
  state_->started = true;
  state_->compressed.resize(1u << 20);
  state_->filtered.resize(rowBytes_ + 1);
  state_->trial.resize(rowBytes_ + 1);
  state_->above.resize(rowBytes_);
}

PngRowEncoder::~PngRowEncoder() {
  if (state_->started) deflateEnd(&state_->z);
}

void PngRowEncoder::pump(int flush) {
  z_stream& z = state_->z;
  do {
    z.next_out = state_->compressed.data();
    z.avail_out = static_cast<uInt>(state_->compressed.size());
    int rc = deflate(&z, flush);
    if (rc == Z_STREAM_ERROR) throw IoError("cannot write '" + path_ + "': zlib failed");
    std::size_t produced = state_->compressed.size() - z.avail_out;
    if (produced > 0) writeChunk(sink_, "IDAT", state_->compressed.data(), produced);
  } while (z.avail_out == 0);
}

void PngRowEncoder::row(const std::uint8_t* rgb) {
  if (rows_ >= height_) throw InternalError("PngRowEncoder: more rows than the image's " + std::to_string(height_));
  throwIfInterrupted();
  filterRow(rgb, state_->above.data(), rowBytes_, state_->filtered, state_->trial);
  std::memcpy(state_->above.data(), rgb, rowBytes_);
  state_->z.next_in = state_->filtered.data();
  state_->z.avail_in = static_cast<uInt>(state_->filtered.size());
  pump(Z_NO_FLUSH);
  ++rows_;
}

void PngRowEncoder::finish() {
  if (rows_ != height_)
    throw InternalError("PngRowEncoder: " + std::to_string(rows_) + " rows of " + std::to_string(height_));
  pump(Z_FINISH);
  writeChunk(sink_, "IEND", nullptr, 0);
}

void writePngAtomic(const Image& image, const std::string& path) {
  writeFileAtomic(path, ".png.tmp", [&](ByteSink& file) {
    PngRowEncoder png(file, image.width, image.height, image.text, path);
    for (int y = 0; y < image.height; ++y) png.row(image.pixel(0, y));
    png.finish();
  });
}

void writePngAtomic(const RadianceImage& image, double gamma, const std::string& path) {
  writeFileAtomic(path, ".png.tmp", [&](ByteSink& file) {
    PngRowEncoder png(file, image.width, image.height, image.text, path);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(image.width) * 3);
    for (int y = 0; y < image.height; ++y) {
      encodeRow(image.pixel(0, y), bytes.size(), gamma, bytes.data());
      png.row(bytes.data());
    }
    png.finish();
  });
}

std::string pngBytes(const RadianceImage& image, double gamma) {
  MemorySink sink;
  PngRowEncoder png(sink, image.width, image.height, {}, "(a PNG in memory)");
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(image.width) * 3);
  for (int y = 0; y < image.height; ++y) {
    encodeRow(image.pixel(0, y), bytes.size(), gamma, bytes.data());
    png.row(bytes.data());
  }
  png.finish();
  return sink.take();
}

void PngRowEncoder::byteRows(int, const Image& band) {
  for (int y = 0; y < band.height; ++y) row(band.pixel(0, y));
}

std::unique_ptr<RowWriter> openPngRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string& path) {
  return std::make_unique<PngRowEncoder>(sink, width, height, records, path);
}

bool isPngFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char signature[8] = {};
  in.read(reinterpret_cast<char*>(signature), 8);
  return in.gcount() == 8 && std::memcmp(signature, kSignature, 8) == 0;
}

ImageRecords readPngText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw imageReadError(path, std::strerror(errno));
  auto cutShort = [&](const std::string& what) { return imageReadError(path, what); };
  in.seekg(0, std::ios::end);
  const auto fileSize = static_cast<std::uint64_t>(std::max<std::streamoff>(0, in.tellg()));
  in.seekg(8);
  // Chunks: length, type, data, CRC. The text comes before IDAT in our files, but a PNG may
  // put it anywhere before IEND; the image data is skipped, not read. A file that ends
  // before IEND is cut short.
  ImageRecords text;
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
  return text;
}

void checkPngInflatesToItsPixels(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[8];
  if (!in.read(reinterpret_cast<char*>(head), 8) || std::memcmp(head, kSignature, 8) != 0) return;
  std::uint64_t bound = 0, width = 0, height = 0;   // 0 until IHDR
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return;
  struct End {
    z_stream& z;
    ~End() { inflateEnd(&z); }
  } end{z};
  std::vector<unsigned char> input(1 << 16), output(1 << 16);
  std::uint64_t inflated = 0;
  bool done = false;
  for (unsigned char chunk[8]; !done && in.read(reinterpret_cast<char*>(chunk), 8);) {
    std::uint64_t length = bigEndian(chunk);
    const std::string type(reinterpret_cast<const char*>(chunk + 4), 4);
    if (type == "IHDR" && length == 13) {
      unsigned char h[13];
      if (!in.read(reinterpret_cast<char*>(h), 13)) return;
      width = bigEndian(h), height = bigEndian(h + 4);
      const std::uint64_t depth = h[8];
      const int channels[7] = {1, 0, 3, 1, 2, 0, 4};   // by colour type: grey, -, RGB, palette, grey+alpha, -, RGBA
      const std::uint64_t perPixel = h[9] < 7 ? static_cast<std::uint64_t>(channels[h[9]]) : 4;
      const std::uint64_t rowBytes = (width * perPixel * depth + 7) / 8;
      // Each row's filter byte and bytes; Adam7 adds at most a filter byte and a partial byte
      // per row of each of its 7 passes.
      bound = height * (1 + rowBytes) + 14 * (height + 8) + 1024;
      in.seekg(4, std::ios::cur);   // its CRC
      continue;
    }
    if (type == "IEND") break;
    if (type != "IDAT" || bound == 0) {
      in.seekg(static_cast<std::streamoff>(length) + 4, std::ios::cur);
      continue;
    }
    while (length > 0 && !done) {
      const std::size_t take = static_cast<std::size_t>(std::min<std::uint64_t>(length, input.size()));
      if (!in.read(reinterpret_cast<char*>(input.data()), static_cast<std::streamsize>(take))) return;
      length -= take;
      z.next_in = input.data();
      z.avail_in = static_cast<uInt>(take);
      while (z.avail_in > 0 && !done) {
        z.next_out = output.data();
        z.avail_out = static_cast<uInt>(output.size());
        const int status = inflate(&z, Z_NO_FLUSH);
        inflated += output.size() - z.avail_out;
        if (inflated > bound)
          throw imageReadError(path, "its compressed data inflates past the " + std::to_string(bound) + " bytes its " +
                                         std::to_string(width) + "x" + std::to_string(height) +
                                         " pixels take (a decompression bomb)");
        if (status == Z_STREAM_END || (status != Z_OK && status != Z_BUF_ERROR)) done = true;
        if (status == Z_BUF_ERROR && z.avail_out != 0) break;
      }
    }
    in.seekg(4, std::ios::cur);   // its CRC
  }
}

}  // namespace vkrt
