// Image bytes into memory (MemorySink) as into a file (FileSink, writeFileAtomic's): placed
// writes past the end and over what is there, each format's writer, and `vkrt view`'s PNG.
#include <cstdint>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "image/atomic_file.h"
#include "image/byte_sink.h"
#include "image/encode.h"
#include "image/image_file.h"
#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::uint8_t* bytesOf(const char* text) { return reinterpret_cast<const std::uint8_t*>(text); }

// Writes in order and at places, as PFM and OpenEXR do: past the end (a gap), over bytes
// written, and on in order after a placed write (which leaves the position alone).
void placedWrites(ByteSink& sink) {
  sink.write(bytesOf("abcd"), 4);
  sink.writeAt(bytesOf("XY"), 2, 9);     // past the end: 5 zeros between
  sink.writeAt(bytesOf("Q"), 1, 1);      // over "b"
  sink.write(bytesOf("ef"), 2);          // at 4, where write() left off
  sink.writeAt(bytesOf("LMNO"), 4, 10);  // over "Y" and on past the end
  sink.writeAt(bytesOf(""), 0, 100);     // nothing: no growth
}

// Every channel different, values past 1 and below 0 (8-bit formats clamp them).
RadianceImage ramp(int w, int h) {
  RadianceImage image(w, h);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = 0.0131f * static_cast<float>(i % 101) - 0.1f;
  return image;
}

}  // namespace

TEST(ImageByteSink, MemoryGrowsPastTheEndAndOverwritesInPlace) {
  MemorySink memory;
  placedWrites(memory);
  EXPECT_EQ(memory.bytes(), std::string("aQcdef\0\0\0XLMNO", 14));
}

// The same writes into a file give the same bytes (the memory sink is a file's model).
TEST(ImageByteSink, MemoryHoldsWhatAFileHolds) {
  const std::string path = freshDir("byte-sink/same") + "/placed.bin";
  writeFileAtomic(path, ".bin.tmp", [](ByteSink& file) { placedWrites(file); });
  MemorySink memory;
  placedWrites(memory);
  EXPECT_EQ(memory.bytes(), readFile(path));
}

// pngBytes (vkrt view's page) makes in memory the file writePngAtomic writes.
TEST(ImageByteSink, PngBytesAreThePngFile) {
  const std::string path = freshDir("byte-sink/png") + "/view.png";
  const RadianceImage image = ramp(67, 45);
  writePngAtomic(image, 2.2, path);
  const std::string bytes = pngBytes(image, 2.2);
  EXPECT_EQ(bytes.size(), readFile(path).size());
  EXPECT_TRUE(bytes == readFile(path));
}

// Each format's writer, records and all, into memory and into a file: the same bytes (PFM
// places its rows bottom first and its trailer after them; OpenEXR seeks back for its line
// offsets).
TEST(ImageByteSink, EveryFormatWritesTheSameBytesIntoMemory) {
  const std::string dir = freshDir("byte-sink/formats");
  const RadianceImage image = ramp(40, 70);
  const ImageRecords records = {{"vkrt-test", "a record"}, {"vkrt-other", "and another"}};
  const Image bytes = encodeImage(image, 1.0);
  for (const ImageFormat& format : imageFormats()) {
    SCOPED_TRACE(std::string(format.name));
    const std::string path = dir + "/out." + std::string(format.extensions.front());
    auto rows = [&](RowWriter& writer) {
      if (format.linearFloat)
        writer.radianceRows(0, image);
      else
        writer.byteRows(0, bytes);
    };
    writeRowsAtomic(path, format, image.width, image.height, records, rows);
    MemorySink memory;
    std::unique_ptr<RowWriter> writer = format.openRows(memory, image.width, image.height, records, path);
    rows(*writer);
    writer->finish();
    writer.reset();
    EXPECT_GT(memory.bytes().size(), 100u);   // an image, not a header alone
    EXPECT_TRUE(memory.bytes() == readFile(path));
  }
}
