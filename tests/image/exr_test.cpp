// OpenEXR (host/image/exr.h): what vkrt writes is read bit for bit by tinyexr, an EXR
// implementation apart from the OpenEXR library vkrt uses, records included; what tinyexr
// writes vkrt reads; and vkrt reads its own files back, whole, in bands, and as records.
#include <tinyexr.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "util/errors.h"
#include "image/exr.h"
#include "image/image_file.h"
#include "image/row_sink.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// Values float32 keeps and 8 bits would not: negative, above 1, tiny, huge, a denormal.
RadianceImage awkwardImage(int w, int h) {
  RadianceImage image(w, h);
  const float specials[] = {0.0f, -0.0f, -1.5f, 1e-30f, 3e38f, 1.0f / 3.0f, 65504.5f,
                            std::numeric_limits<float>::denorm_min(), 0.7f};
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = specials[i % std::size(specials)] * (1.0f + static_cast<float>(i) * 1e-3f);
  // In keyword order: an EXR header holds its attributes sorted by name, and reads them back so.
  image.text = {{"vkrt-crop", "x 3 y 1 full 40 30"}, {"vkrt-samples", "16 gamma 2.2 seeds 7:0+16"}};
  return image;
}

// tinyexr's reading of `path`: the RGBA floats (its LoadEXR) and the header's string attributes.
struct TinyRead {
  int width = 0, height = 0;
  std::vector<float> rgba;
  std::vector<std::pair<std::string, std::string>> strings;
};
TinyRead tinyRead(const std::string& path) {
  TinyRead r;
  float* rgba = nullptr;
  const char* err = nullptr;
  if (LoadEXR(&rgba, &r.width, &r.height, path.c_str(), &err) != TINYEXR_SUCCESS) {
    ADD_FAILURE() << "tinyexr cannot read " << path << ": " << (err ? err : "?");
    if (err) FreeEXRErrorMessage(err);
    return r;
  }
  r.rgba.assign(rgba, rgba + static_cast<std::size_t>(r.width) * r.height * 4);
  std::free(rgba);
  EXRVersion version;
  EXRHeader header;
  InitEXRHeader(&header);
  EXPECT_EQ(ParseEXRVersionFromFile(&version, path.c_str()), TINYEXR_SUCCESS);
  if (ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err) == TINYEXR_SUCCESS) {
    for (int i = 0; i < header.num_custom_attributes; ++i) {
      const EXRAttribute& a = header.custom_attributes[i];
      if (std::strcmp(a.type, "string") == 0)
        r.strings.emplace_back(a.name, std::string(reinterpret_cast<const char*>(a.value), static_cast<std::size_t>(a.size)));
    }
    FreeEXRHeader(&header);
  } else if (err) {
    FreeEXRErrorMessage(err);
  }
  return r;
}

std::uint32_t bitsOf(float f) {
  std::uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}

}  // namespace

TEST(Exr, AnIndependentReaderSeesEveryBitAndEveryRecord) {
  const std::string path = freshDir("exr/independent") + "/a.exr";
  const RadianceImage image = awkwardImage(13, 7);
  writeImageAtomic(image, path, 2.2);
  const TinyRead r = tinyRead(path);
  ASSERT_EQ(r.width, 13);
  ASSERT_EQ(r.height, 7);
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 13; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(bitsOf(r.rgba[(static_cast<std::size_t>(y) * 13 + x) * 4 + c]), bitsOf(image.pixel(x, y)[c]))
            << "pixel " << x << "," << y << " channel " << c;
  for (const auto& record : image.text) {
    bool found = false;
    for (const auto& [name, value] : r.strings) found = found || (name == record.first && value == record.second);
    EXPECT_TRUE(found) << record.first << " " << record.second;
  }
}

TEST(Exr, ReadsWhatAnotherWriterWrote) {
  const std::string path = freshDir("exr/foreign") + "/t.exr";
  const int w = 9, h = 5;
  std::vector<float> rgb(static_cast<std::size_t>(w) * h * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<float>(i) * 0.37f - 3.0f;
  const char* err = nullptr;
  ASSERT_EQ(SaveEXR(rgb.data(), w, h, 3, /*save_as_fp16=*/0, path.c_str(), &err), TINYEXR_SUCCESS) << (err ? err : "");
  ASSERT_TRUE(isExrFile(path));
  const RadianceImage read = readExr(path);
  ASSERT_EQ(read.width, w);
  ASSERT_EQ(read.height, h);
  EXPECT_TRUE(sameBits(read.rgb, rgb));
  EXPECT_TRUE(read.text.empty());
}

TEST(Exr, RoundTripsBitForBitWholeAndStreamed) {
  const std::string dir = freshDir("exr/roundtrip");
  const RadianceImage image = awkwardImage(40, 30);
  writeImageAtomic(image, dir + "/whole.exr", 1.0);
  // Streamed in bands of 7 rows, as a render writes it.
  writeImageStreamed(dir + "/bands.exr", 1.0, 40, 30, image.text, [&](const RowSink& sink) {
    for (int y0 = 0; y0 < 30; y0 += 7) {
      const int rows = std::min(7, 30 - y0);
      RadianceImage band(40, rows);
      std::memcpy(band.rgb.data(), image.pixel(0, y0), band.rgb.size() * sizeof(float));
      sink(y0, band);
    }
  });
  for (const char* name : {"/whole.exr", "/bands.exr"}) {
    const RadianceImage back = readFloatImage(dir + name);
    EXPECT_TRUE(sameBits(back, image)) << name;
    EXPECT_EQ(back.text, image.text) << name;
    const RadianceImage info = readFloatImageInfo(dir + name);
    EXPECT_EQ(info.width, 40);
    EXPECT_TRUE(info.rgb.empty());
    EXPECT_EQ(readFloatImageText(dir + name), image.text);
  }
  EXPECT_EQ(fileCount(dir), 2u);   // no temporary file left
}

TEST(Exr, NotAnExrIsAnIoErrorNamingTheFile) {
  const std::string dir = freshDir("exr/bad");
  writeFile(dir + "/cut.exr", std::string("v/1\x01", 4) + "garbage");
  EXPECT_FALSE(isExrFile(dir + "/missing.exr"));
  try {
    readExr(dir + "/cut.exr");
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/cut.exr"), std::string::npos) << e.what();
  }
}
