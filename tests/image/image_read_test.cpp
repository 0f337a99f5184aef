// Reading images (image/image_file.h readImage, the float readers, and the commands that read
// through them): binary PPM of any maxval as the Netpbm spec says (scaled to 8 bits, 16-bit
// samples most significant byte first), a maxval out of range refused; an image of no pixels
// refused by every reader before anything is written; a file that cannot be read said in
// plain words (the system's reason, "the file ends early"), not stb_image's terse ones.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "util/errors.h"
#include "image/image_file.h"
#include "image/pfm.h"
#include "image/image_read.h"
#include "image/png.h"
#include "test_support.h"

#define STB_IMAGE_WRITE_STATIC   // (the test's own JPEG writer: vkrt reads JPEG, never writes it)
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

using namespace vkrt;
using namespace vkrt::test;

namespace {

// A P6 (or P5) file of `samples`, each one byte when maxval <= 255, else two, most
// significant first.
std::string netpbm(const std::string& magic, int w, int h, int maxval, const std::vector<int>& samples) {
  std::string file = magic + "\n" + std::to_string(w) + " " + std::to_string(h) + "\n" + std::to_string(maxval) + "\n";
  for (int v : samples) {
    if (maxval > 255) file += static_cast<char>(v >> 8);
    file += static_cast<char>(v & 0xff);
  }
  return file;
}

// The message readImage throws for `path`, or "" when it reads the file.
std::string readFailure(const std::string& path) {
  try {
    readImage(path);
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// maxval 100: a sample v is v/100 of full scale, round(v * 255 / 100) as a byte.
TEST(PpmRead, MaxvalBelow255IsScaled) {
  const std::string dir = freshDir("image-read/maxval-100");
  writeFile(dir + "/a.ppm", netpbm("P6", 2, 1, 100, {0, 50, 100, 25, 75, 1}));
  const Image img = readImage(dir + "/a.ppm");
  ASSERT_EQ(img.width, 2);
  ASSERT_EQ(img.height, 1);
  EXPECT_EQ(img.rgb, (std::vector<std::uint8_t>{0, 128, 255, 64, 191, 3}));
}

// maxval above 255: two bytes a sample, the first the most significant. 0xFF00 of 65535 is
// 254, not its low byte (0); 0x00FF is 1, not 255; 500 of 1000 is half scale.
TEST(PpmRead, SixteenBitSamplesAreBigEndianAndScaled) {
  const std::string dir = freshDir("image-read/maxval-16-bit");
  writeFile(dir + "/a.ppm", netpbm("P6", 1, 2, 65535, {0xFF00, 0x00FF, 65535, 0, 0x8000, 257}));
  EXPECT_EQ(readImage(dir + "/a.ppm").rgb, (std::vector<std::uint8_t>{254, 1, 255, 0, 128, 1}));
  writeFile(dir + "/b.ppm", netpbm("P6", 1, 1, 1000, {500, 1000, 2}));
  EXPECT_EQ(readImage(dir + "/b.ppm").rgb, (std::vector<std::uint8_t>{128, 255, 1}));
  int w = 0, h = 0;
  readImageSize(dir + "/a.ppm", w, h);
  EXPECT_EQ(w, 1);
  EXPECT_EQ(h, 2);
}

// A grey P5 image is read the same way, each sample copied to the three channels.
TEST(PpmRead, GreyP5OfAnyMaxval) {
  const std::string dir = freshDir("image-read/p5");
  writeFile(dir + "/a.pgm", netpbm("P5", 2, 1, 4095, {4095, 2048}));
  EXPECT_EQ(readImage(dir + "/a.pgm").rgb, (std::vector<std::uint8_t>{255, 255, 255, 128, 128, 128}));
  writeFile(dir + "/b.pgm", netpbm("P5", 1, 1, 3, {1}));
  EXPECT_EQ(readImage(dir + "/b.pgm").rgb, (std::vector<std::uint8_t>{85, 85, 85}));
}

// maxval 255 is read as it is: every byte value comes back.
TEST(PpmRead, Maxval255IsReadAsItIs) {
  const std::string dir = freshDir("image-read/maxval-255");
  std::vector<int> samples;
  for (int v = 0; v < 256; ++v) samples.push_back(v);
  samples.push_back(0), samples.push_back(1);   // 86 whole pixels
  writeFile(dir + "/a.ppm", netpbm("P6", 86, 1, 255, samples));
  const Image img = readImage(dir + "/a.ppm");
  for (int v = 0; v < 256; ++v) EXPECT_EQ(img.rgb[static_cast<std::size_t>(v)], v);
}

// A maxval of 0 or above 65535 is no PPM: refused, naming the file and the maxval.
TEST(PpmRead, MaxvalOutOfRangeIsRefused) {
  const std::string dir = freshDir("image-read/maxval-range");
  writeFile(dir + "/zero.ppm", "P6\n1 1\n0\n" + std::string(3, '\0'));
  EXPECT_EQ(readFailure(dir + "/zero.ppm"),
            "cannot read image '" + dir + "/zero.ppm': its maxval is 0, and a PPM's maxval is 1 to 65535");
  writeFile(dir + "/big.ppm", "P6\n1 1\n65536\n" + std::string(6, '\x01'));
  EXPECT_EQ(readFailure(dir + "/big.ppm"),
            "cannot read image '" + dir + "/big.ppm': its maxval is 65536, and a PPM's maxval is 1 to 65535");
  int w = 0, h = 0;
  EXPECT_THROW(readImageSize(dir + "/big.ppm", w, h), IoError);
  EXPECT_THROW(readImageFileText(dir + "/big.ppm"), IoError);
}

// The commands read through the same reader: `vkrt convert` of a 16-bit PPM writes the
// scaled bytes, and `vkrt diff` finds it equal to the same image at maxval 255.
TEST(PpmRead, ConvertAndDiffReadSixteenBit) {
  const std::string dir = freshDir("image-read/cli-16-bit");
  writeFile(dir + "/deep.ppm", netpbm("P6", 2, 1, 65535, {0xFF00, 0x00FF, 0x8000, 65535, 0, 0x1234}));
  writeFile(dir + "/flat.ppm", netpbm("P6", 2, 1, 255, {254, 1, 128, 255, 0, 18}));
  RunResult run = runVkrt("convert " + dir + "/deep.ppm " + dir + "/deep.png");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(readImage(dir + "/deep.png").rgb, (std::vector<std::uint8_t>{254, 1, 128, 255, 0, 18}));
  run = runVkrt("diff " + dir + "/deep.ppm " + dir + "/flat.ppm");
  EXPECT_EQ(run.exitCode, 0) << run.output;
}

// A width or a height of 0, in every format read: refused with the same words, naming the
// file and its size, by the whole read, the size alone and the records.
TEST(EmptyImage, EveryReaderRefusesIt) {
  const std::string dir = freshDir("image-read/empty");
  writeFile(dir + "/zero.ppm", "P6\n0 3\n255\n");
  writeFile(dir + "/zero.pgm", "P5\n3 0\n65535\n");
  writeFile(dir + "/zero.pfm", "PF\n0 3\n-1.0\n");
  // A PNG signature and an IHDR of width 0 (no valid PNG: written byte by byte, as no encoder
  // would; the CRC is left 0, since the size is refused before anything checks it).
  writeFile(dir + "/zero.png", std::string("\x89PNG\r\n\x1a\n", 8) + std::string("\0\0\0\x0d", 4) + "IHDR" +
                                   std::string("\0\0\0\0\0\0\0\x03\x08\x02\0\0\0", 13) + std::string(4, '\0') +
                                   std::string("\0\0\0\0", 4) + "IEND" + std::string(4, '\0'));
  auto expected = [&](const std::string& name, const std::string& size) {
    return "cannot read image '" + dir + "/" + name + "': it is " + size + " pixels, and an image has at least one pixel";
  };
  EXPECT_EQ(readFailure(dir + "/zero.ppm"), expected("zero.ppm", "0x3"));
  EXPECT_EQ(readFailure(dir + "/zero.pgm"), expected("zero.pgm", "3x0"));
  EXPECT_EQ(readFailure(dir + "/zero.png"), expected("zero.png", "0x3"));
  for (const char* name : {"zero.ppm", "zero.png"}) {
    int w = -1, h = -1;
    try {
      readImageSize(dir + "/" + name, w, h);
      ADD_FAILURE() << name << " read as " << w << "x" << h;
    } catch (const IoError& e) {
      EXPECT_EQ(std::string(e.what()), expected(name, "0x3"));
    }
  }
  try {
    readImageFileText(dir + "/zero.ppm");
    ADD_FAILURE() << "zero.ppm's records read";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), expected("zero.ppm", "0x3"));
  }
  try {
    readPfm(dir + "/zero.pfm");
    ADD_FAILURE() << "zero.pfm read";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), expected("zero.pfm", "0x3"));
  }
}

// A JPEG whose frame header says 0 pixels wide: stb_image's "0 width", in words.
TEST(EmptyImage, JpegOfNoWidth) {
  const std::string dir = freshDir("image-read/empty-jpeg");
  // SOI, then a baseline SOF0 of height 3 and width 0.
  writeFile(dir + "/zero.jpg", std::string("\xFF\xD8\xFF\xC0\x00\x11\x08\x00\x03\x00\x00\x03", 12) +
                                   std::string(15, '\x11'));
  EXPECT_EQ(readFailure(dir + "/zero.jpg"), "cannot read image '" + dir +
                                                "/zero.jpg': the JPEG is 0 pixels wide, and an image has at least one pixel");
}

// The commands: convert writes nothing (no 0-pixel PNG, no OpenEXR error of its own), diff
// does not pass two empty images; each is an I/O error (exit 4) naming the file.
TEST(EmptyImage, ConvertAndDiffRefuseIt) {
  const std::string dir = freshDir("image-read/empty-cli");
  writeFile(dir + "/zero.ppm", "P6\n0 3\n255\n");
  writeFile(dir + "/none.ppm", "P6\n0 0\n255\n");
  const std::string zeroMessage = "cannot read image '" + dir + "/zero.ppm': it is 0x3 pixels";
  RunResult run = runVkrt("convert " + dir + "/zero.ppm " + dir + "/z.png");
  EXPECT_EQ(run.exitCode, 4) << run.output;
  EXPECT_NE(run.output.find(zeroMessage), std::string::npos) << run.output;
  EXPECT_FALSE(fileExists(dir + "/z.png"));
  run = runVkrt("convert " + dir + "/none.ppm " + dir + "/z.exr");
  EXPECT_EQ(run.exitCode, 4) << run.output;
  EXPECT_NE(run.output.find("none.ppm': it is 0x0 pixels"), std::string::npos) << run.output;
  EXPECT_FALSE(fileExists(dir + "/z.exr"));
  run = runVkrt("diff " + dir + "/zero.ppm " + dir + "/zero.ppm");
  EXPECT_EQ(run.exitCode, 4) << run.output;
  EXPECT_EQ(run.output.find("PASS"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(zeroMessage), std::string::npos) << run.output;
}

// A file that is not there, or not a file: the system's reason, as for every other file
// vkrt reads.
TEST(ReadErrors, MissingFileSaysTheSystemsReason) {
  const std::string dir = freshDir("image-read/missing");
  EXPECT_EQ(readFailure(dir + "/nonexist.png"), "cannot read image '" + dir + "/nonexist.png': No such file or directory");
  EXPECT_EQ(readFailure(dir), "cannot read image '" + dir + "': Is a directory");
  int w = 0, h = 0;
  try {
    readImageSize(dir + "/nonexist.ppm", w, h);
    ADD_FAILURE() << "a missing file's size read";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read image '" + dir + "/nonexist.ppm': No such file or directory");
  }
  RunResult run = runVkrt("convert " + dir + "/nonexist.png " + dir + "/a.png");
  EXPECT_EQ(run.exitCode, 4) << run.output;
  EXPECT_NE(run.output.find("cannot read image '" + dir + "/nonexist.png': No such file or directory"),
            std::string::npos)
      << run.output;
}

// A PNG cut short in its image data, and a file of no image format: plain words.
TEST(ReadErrors, TruncatedAndUnknownFilesInPlainWords) {
  const std::string dir = freshDir("image-read/plain-words");
  writePngAtomic(gradient(64, 64), dir + "/whole.png");
  const std::string whole = readFile(dir + "/whole.png");
  writeFile(dir + "/cut.png", whole.substr(0, whole.size() / 2));
  EXPECT_EQ(readFailure(dir + "/cut.png"), "cannot read image '" + dir + "/cut.png': the file ends early (it is truncated)");
  writeFile(dir + "/notes.png", "not an image at all\n");
  EXPECT_EQ(readFailure(dir + "/notes.png"),
            "cannot read image '" + dir + "/notes.png': not an image vkrt reads (PNG, PPM, PFM, EXR or JPEG)");
  writeFile(dir + "/cut.ppm", "P6\n4 4\n255\n" + std::string(10, '\x7f'));
  EXPECT_EQ(readFailure(dir + "/cut.ppm"),
            "cannot read image '" + dir + "/cut.ppm': the PPM raster is truncated (4x4 pixels need 48 bytes)");
}

// A file that cannot be opened for reading says so with the system's reason: here a path
// through a regular file, which fails for every user (root reads a file of mode 000).
TEST(ReadErrors, UnopenableFileSaysTheSystemsReason) {
  const std::string dir = freshDir("image-read/unopenable");
  writePngAtomic(gradient(2, 2), dir + "/plain.png");
  EXPECT_EQ(readFailure(dir + "/plain.png/inside.png"),
            "cannot read image '" + dir + "/plain.png/inside.png': Not a directory");
}

// Every reader gives a reason for every failure: a PNG, PPM, PFM, EXR and JPEG cut at every
// length (and a PNG with a damaged byte in its image data) are refused with a message that
// names the file and says why, never "cannot read image 'X': " with nothing after it; a cut
// PNG is "truncated" from its eighth byte on (its signature whole), whatever stb_image then
// made of the zeros it read instead (it said "first not IHDR", "1/2/4/8/16-bit only", "" ...).
TEST(ReadErrors, EveryCutOfEveryFormatSaysWhy) {
  const std::string dir = freshDir("image-read/cuts");
  RadianceImage small(6, 5);
  for (std::size_t i = 0; i < small.rgb.size(); ++i) small.rgb[i] = static_cast<float>(i % 7) / 7.0f;
  std::vector<std::string> files;
  for (const char* ext : {"png", "ppm", "pfm", "exr"}) {
    files.push_back(dir + "/whole." + ext);
    writeImageAtomic(small, files.back(), 1.0);
  }
  const Image bytes = gradient(6, 5);
  files.push_back(dir + "/whole.jpg");
  ASSERT_NE(stbi_write_jpg(files.back().c_str(), bytes.width, bytes.height, 3, bytes.rgb.data(), 90), 0);
  for (const std::string& whole : files) {
    const std::string data = readFile(whole);
    ASSERT_NO_THROW(readAnyImage(whole)) << whole;
    const std::string ext = whole.substr(whole.rfind('.'));
    for (std::size_t n = 1; n < data.size(); ++n) {
      const std::string cut = dir + "/cut-" + std::to_string(n) + ext;
      writeFile(cut, data.substr(0, n));
      std::string message;
      try {
        readAnyImage(cut);
      } catch (const IoError& e) {
        message = e.what();
      }
      // (A JPEG cut within its entropy-coded data may still decode: stb_image fills the rest.)
      if (message.empty() && ext == ".jpg") continue;
      const std::string prefix = "cannot read image '" + cut + "': ";
      ASSERT_EQ(message.rfind(prefix, 0), 0u) << n << " bytes of " << whole << ": '" << message << "'";
      EXPECT_GT(message.size(), prefix.size() + 5) << n << " bytes of " << whole << ": no reason in '" << message << "'";
      if (ext == ".png" && n >= 8) {
        EXPECT_NE(message.find("truncated"), std::string::npos) << n << " bytes: " << message;
      }
      std::filesystem::remove(cut);
    }
  }
  // A PNG whole but for the first byte of its image data (the zlib stream's method): damaged,
  // with stb_image's reason.
  std::string damaged = readFile(dir + "/whole.png");
  const std::size_t idat = damaged.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  damaged[idat + 4] = '\x7F';
  writeFile(dir + "/damaged.png", damaged);
  const std::string message = readFailure(dir + "/damaged.png");
  EXPECT_NE(message.find("damaged or unsupported"), std::string::npos) << message;
}
