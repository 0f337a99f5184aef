// OpenEXR through Debian's OpenEXR library (3.1): scanline files of float R, G, B, the records
// as string attributes.
#include "image/exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cstdint>
#include <exception>
#include <fstream>
#include <string_view>

#include "util/errors.h"
#include "util/interrupt.h"

namespace vkrt {
namespace {

// Records are the string attributes named so (kCropKeyword, kSamplesKeyword, kRenderKeyword).
constexpr std::string_view kRecordPrefix = "vkrt-";
// The largest image read: as many pixels as vkrt renders at most (16384 x 16384).
constexpr std::uint64_t kMaxPixels = std::uint64_t{16384} * 16384;
constexpr const char* kChannels[3] = {"R", "G", "B"};

// The address OpenEXR adds (x, y) strides to, for pixel (x0, y0) at `first`: computed on
// integers, since the pointer it stands for may lie outside the array (OpenEXR only reads
// and writes inside it).
char* frameBase(const float* first, std::int64_t x0, std::int64_t y0, std::int64_t width) {
  const std::int64_t offset = (y0 * width + x0) * 3 * static_cast<std::int64_t>(sizeof(float));
  return reinterpret_cast<char*>(reinterpret_cast<std::uintptr_t>(first) - static_cast<std::uintptr_t>(offset));
}

// An OpenEXR output stream over a ByteSink, written at the stream's place (the library
// seeks back to fill in the line offsets). A failed write is kept and reported again by
// check(): OpenEXR also writes from its destructor, which swallows what it throws.
class SinkStream : public Imf::OStream {
 public:
  SinkStream(ByteSink& sink, const std::string& path) : Imf::OStream(path.c_str()), sink_(sink) {}
  void write(const char c[], int n) override {
    check();
    try {
      sink_.writeAt(reinterpret_cast<const std::uint8_t*>(c), static_cast<std::size_t>(n), place_);
    } catch (const IoError& e) {
      error_ = e.what();
      throw;
    }
    place_ += static_cast<std::uint64_t>(n);
  }
  std::uint64_t tellp() override { return place_; }
  void seekp(std::uint64_t place) override { place_ = place; }
  void check() const {
    if (!error_.empty()) throw IoError(error_);
  }

 private:
  ByteSink& sink_;
  std::uint64_t place_ = 0;
  std::string error_;   // the first failed write's message
};

// Runs `read` on the opened file; OpenEXR's exceptions become IoError.
template <class F>
auto withInputFile(const std::string& path, F&& read) {
  try {
    Imf::InputFile file(path.c_str());
    return read(file);
  } catch (const IoError&) {
    throw;
  } catch (const std::exception& e) {
    throw imageReadError(path, e.what());
  }
}

RadianceImage infoOf(const Imf::InputFile& file, const std::string& path) {
  const Imath::Box2i dw = file.header().dataWindow();
  const std::int64_t w = std::int64_t{dw.max.x} - dw.min.x + 1, h = std::int64_t{dw.max.y} - dw.min.y + 1;
  checkImageHasPixels(path, w, h);
  if (static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) > kMaxPixels)
    throw imageReadError(path, "the EXR's data window is " + std::to_string(w) + "x" + std::to_string(h) +
                         " (at most 16384x16384 pixels are read)");
  RadianceImage info;
  info.width = static_cast<int>(w);
  info.height = static_cast<int>(h);
  for (auto a = file.header().begin(); a != file.header().end(); ++a) {
    const std::string name = a.name();
    if (name.compare(0, kRecordPrefix.size(), kRecordPrefix) != 0) continue;
    if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a.attribute()))
      info.text.emplace_back(name, s->value());
  }
  return info;
}

}  // namespace

struct ExrRowWriter::State {
  State(ByteSink& sink, const std::string& name, const Imf::Header& header)
      : stream(sink, name), file(std::make_unique<Imf::OutputFile>(stream, header)), path(name) {}
  SinkStream stream;                      // outlives the file, which writes to it as it closes
  std::unique_ptr<Imf::OutputFile> file;
  int width = 0, height = 0, next = 0;
  std::string path;
};

ExrRowWriter::ExrRowWriter(ByteSink& sink, int width, int height, const ImageRecords& records,
                           const std::string& path) {
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* c : kChannels) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    for (const auto& [keyword, text] : records) header.insert(keyword, Imf::StringAttribute(text));
    state_ = std::make_unique<State>(sink, path, header);
  } catch (const IoError&) {
    throw;
  } catch (const std::exception& e) {
    throw IoError("cannot write '" + path + "': " + e.what());
  }
  state_->width = width;
  state_->height = height;
}

ExrRowWriter::~ExrRowWriter() = default;

void ExrRowWriter::radianceRows(int y0, const RadianceImage& band) {
  throwIfInterrupted();
  State& s = *state_;
  if (y0 != s.next || band.width != s.width || band.height > s.height - y0)
    throw InternalError("EXR rows " + std::to_string(y0) + "+" + std::to_string(band.height) + " after " +
                        std::to_string(s.next));
  try {
    Imf::FrameBuffer frame;
    char* base = frameBase(band.rgb.data(), 0, y0, s.width);
    for (int c = 0; c < 3; ++c)
      frame.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 3 * sizeof(float),
                                            3 * sizeof(float) * static_cast<std::size_t>(s.width)));
    s.file->setFrameBuffer(frame);
    s.file->writePixels(band.height);
  } catch (const IoError&) {
    throw;
  } catch (const std::exception& e) {
    throw IoError("cannot write '" + s.path + "': " + e.what());
  }
  s.next = y0 + band.height;
}

void ExrRowWriter::finish() {
  if (state_->next != state_->height)
    throw InternalError("EXR: " + std::to_string(state_->next) + " rows of " + std::to_string(state_->height));
  // The line offsets are written when the file closes (OpenEXR's destructor, which reports
  // no error: the stream keeps it).
  state_->file.reset();
  state_->stream.check();
}

std::unique_ptr<RowWriter> openExrRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string& path) {
  return std::make_unique<ExrRowWriter>(sink, width, height, records, path);
}

RadianceImage readExr(const std::string& path) {
  return withInputFile(path, [&](Imf::InputFile& file) {
    RadianceImage image = infoOf(file, path);
    const Imath::Box2i dw = file.header().dataWindow();
    image.rgb.assign(static_cast<std::size_t>(image.width) * image.height * 3, 0.0f);
    const Imf::ChannelList& channels = file.header().channels();
    const bool grey = !channels.findChannel("R") && !channels.findChannel("G") && !channels.findChannel("B") &&
                      channels.findChannel("Y");
    Imf::FrameBuffer frame;
    char* base = frameBase(image.rgb.data(), dw.min.x, dw.min.y, image.width);
    const std::size_t xStride = 3 * sizeof(float), yStride = xStride * static_cast<std::size_t>(image.width);
    if (grey)
      frame.insert("Y", Imf::Slice(Imf::FLOAT, base, xStride, yStride, 1, 1, 0.0));
    else
      for (int c = 0; c < 3; ++c)
        frame.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride, 1, 1, 0.0));
    file.setFrameBuffer(frame);
    file.readPixels(dw.min.y, dw.max.y);
    if (grey)
      for (std::size_t i = 0; i < image.rgb.size(); i += 3) image.rgb[i + 1] = image.rgb[i + 2] = image.rgb[i];
    return image;
  });
}

RadianceImage readExrInfo(const std::string& path) {
  return withInputFile(path, [&](Imf::InputFile& file) { return infoOf(file, path); });
}

ImageRecords readExrText(const std::string& path) {
  return readExrInfo(path).text;
}

bool isExrFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[4] = {};
  in.read(reinterpret_cast<char*>(head), 4);
  return in.gcount() == 4 && head[0] == 0x76 && head[1] == 0x2f && head[2] == 0x31 && head[3] == 0x01;
}

}  // namespace vkrt
