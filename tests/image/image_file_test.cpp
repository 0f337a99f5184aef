// Output formats by file name (the table of image/image_file.h, each row walked): .ppm writes
// binary PPM (atomically, as PNG), any other name PNG; a name vkrt does not write as named
// gets a warning.
#include <cctype>
#include <cstring>
#include <filesystem>
#include <string_view>

#include <gtest/gtest.h>

#include "image/image_file.h"
#include "image/png.h"
#include "image/ppm.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::string kScene =
    "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\ndiffuse 0.5 0.2 0.9\nsphere 0 0 0 1\n";

// A P6 file read by this test itself (not stb_image): "P6\nW H\n255\n" and the bytes.
Image readP6(const std::string& path) {
  std::string bytes = readFile(path);
  int w = 0, h = 0, maxval = 0, consumed = 0;
  if (std::sscanf(bytes.c_str(), "P6\n%d %d\n%d%n", &w, &h, &maxval, &consumed) != 3 || maxval != 255)
    return Image();
  Image img(w, h);
  std::size_t start = static_cast<std::size_t>(consumed) + 1;   // the single whitespace after maxval
  if (bytes.size() != start + img.rgb.size()) return Image();
  std::memcpy(img.rgb.data(), bytes.data() + start, img.rgb.size());
  return img;
}

}  // namespace

TEST(ImageFile, FormatByExtension) {
  EXPECT_EQ(imageFormatFor("a.ppm").name, "PPM");
  EXPECT_EQ(imageFormatFor("dir.png/A.PPM").name, "PPM");
  EXPECT_EQ(imageFormatFor("a.png").name, "PNG");
  EXPECT_EQ(imageFormatFor("a.bmp").name, "PNG");
  EXPECT_EQ(imageFormatFor("dir.ppm/a").name, "PNG");
  EXPECT_TRUE(hasImageExtension("x.PNG"));
  EXPECT_TRUE(hasImageExtension("x.ppm"));
  EXPECT_FALSE(hasImageExtension("x.bmp"));
  EXPECT_FALSE(hasImageExtension("x.ppm/y"));
}

// Every row of the format table: each extension (any case) gives its row and counts as a
// known name; the texts list it; an 8-bit image written under a linear-float name is a usage
// error with nothing created; a linear-float image comes back through the row's readers bit
// for bit, with its records, and is known by its first bytes; an 8-bit one's records come
// back too. The default (first) row is an 8-bit format.
TEST(ImageFile, EveryFormatOfTheTable) {
  std::string dir = freshDir("image-file/table");
  ASSERT_FALSE(imageFormats().empty());
  EXPECT_FALSE(imageFormats().front().linearFloat);
  const Image bytes = gradient(5, 3);
  RadianceImage radiance(5, 3);
  for (std::size_t i = 0; i < radiance.rgb.size(); ++i) radiance.rgb[i] = 0.37f * static_cast<float>(i) - 1.5f;
  // In keyword order: an EXR header holds its attributes sorted by name, and reads them back so.
  radiance.text = {{"vkrt-other", "1 2 3"}, {"vkrt-test", "a record"}};
  int n = 0;
  for (const ImageFormat& format : imageFormats()) {
    SCOPED_TRACE(std::string(format.name));
    ASSERT_FALSE(format.extensions.empty());
    ASSERT_TRUE(format.isFile && format.openRows && format.readText);
    for (std::string_view ext : format.extensions) {
      std::string upper(ext);
      for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      EXPECT_EQ(&imageFormatFor("d.x/a." + std::string(ext)), &format);
      EXPECT_EQ(&imageFormatFor("a." + upper), &format);
      EXPECT_TRUE(hasImageExtension("a." + upper));
      EXPECT_EQ(holdsLinearFloat("a." + std::string(ext)), format.linearFloat);
    }
    const std::string ext = "." + std::string(format.extensions.front());
    EXPECT_NE(imageExtensionsText().find(ext), std::string::npos);
    EXPECT_NE(imageFormatNamesText().find(format.name), std::string::npos);
    const std::string path = dir + "/f" + std::to_string(n++) + ext;
    if (format.linearFloat) {
      ASSERT_TRUE(format.read && format.readInfo);
      EXPECT_THROW(writeImageAtomic(bytes, path), UsageError);
      EXPECT_FALSE(fileExists(path));
      EXPECT_NE(imageExtensionsText(FormatsOf::LinearFloat).find(ext), std::string::npos);
      EXPECT_EQ(imageExtensionsText(FormatsOf::Bytes).find(ext), std::string::npos);
      writeImageAtomic(radiance, path, 2.2);
      EXPECT_TRUE(isFloatImageFile(path));
      EXPECT_EQ(floatImageFormatOf(path), &format);
      RadianceImage back = readFloatImage(path);
      ASSERT_EQ(back.width, 5);
      ASSERT_EQ(back.height, 3);
      EXPECT_EQ(std::memcmp(back.rgb.data(), radiance.rgb.data(), radiance.rgb.size() * sizeof(float)), 0);
      EXPECT_EQ(back.text, radiance.text);
      RadianceImage info = readFloatImageInfo(path);
      EXPECT_EQ(info.width, 5);
      EXPECT_TRUE(info.rgb.empty());
      EXPECT_EQ(readFloatImageText(path), radiance.text);
    } else {
      EXPECT_EQ(format.read, nullptr);
      EXPECT_NE(imageExtensionsText(FormatsOf::Bytes).find(ext), std::string::npos);
      Image withText = bytes;
      withText.text = radiance.text;
      writeImageAtomic(withText, path);
      EXPECT_TRUE(format.isFile(path));
      EXPECT_FALSE(isFloatImageFile(path));
      EXPECT_EQ(readImageFileText(path), radiance.text);
    }
    EXPECT_EQ(readImageFileText(path), radiance.text);
    for (const ImageFormat& other : imageFormats()) {
      if (&other == &format) continue;
      EXPECT_FALSE(other.isFile(path)) << other.name;
    }
  }
}

TEST(ImageFile, PpmHeaderBytesAndAtomicReplacement) {
  std::string dir = freshDir("image-file/ppm");
  Image img = gradient(5, 3);
  writeFile(dir + "/a.ppm", "old contents");
  writeImageAtomic(img, dir + "/a.ppm");
  std::string bytes = readFile(dir + "/a.ppm");
  ASSERT_EQ(bytes.size(), std::strlen("P6\n5 3\n255\n") + 45);
  EXPECT_EQ(bytes.substr(0, 11), "P6\n5 3\n255\n");
  EXPECT_EQ(std::memcmp(bytes.data() + 11, img.rgb.data(), 45), 0);
  EXPECT_EQ(readImage(dir + "/a.ppm").rgb, img.rgb);   // and what vkrt diff reads
  EXPECT_EQ(fileCount(dir), 1u);                         // no temporary file left
  EXPECT_THROW(writePpmAtomic(img, dir + "/missing/a.ppm"), IoError);
  EXPECT_EQ(fileCount(dir), 1u);
}

// The same render as PPM and as PNG: the same pixels.
TEST(ImageFile, CliWritesPpmWithThePngsPixels) {
  std::string dir = freshDir("image-file/cli-ppm");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/named.test", kScene + "output " + dir + "/named.PPM\n");
  RunResult png = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  ASSERT_EQ(png.exitCode, 0) << png.output;
  RunResult ppm = runVkrt("--backend cpu -o " + dir + "/o.ppm " + dir + "/s.test");
  ASSERT_EQ(ppm.exitCode, 0) << ppm.output;
  EXPECT_EQ(ppm.output.find("warning:"), std::string::npos) << ppm.output;
  RunResult named = runVkrt("--backend cpu " + dir + "/named.test");
  ASSERT_EQ(named.exitCode, 0) << named.output;
  EXPECT_EQ(named.output.find("warning:"), std::string::npos) << named.output;
  Image reference = readImage(dir + "/o.png");
  for (const char* f : {"/o.ppm", "/named.PPM"}) {
    Image back = readP6(dir + f);
    ASSERT_EQ(back.width, 40) << f;
    ASSERT_EQ(back.height, 30) << f;
    EXPECT_TRUE(back.rgb == reference.rgb) << f;
  }
  EXPECT_GT(reference.pixel(20, 15)[2], 100);
}

// Any other name: PNG bytes under that name, and a warning (from -o: the command line's;
// with --strict a usage error and nothing written).
TEST(ImageFile, OtherExtensionsWarnAndWritePng) {
  std::string dir = freshDir("image-file/bmp");
  writeFile(dir + "/s.test", kScene);
  RunResult r = runVkrt("--backend cpu -o " + dir + "/o.bmp " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: warning: output file '" + dir +
                          "/o.bmp' is not named .png, .ppm, .pfm or .exr: vkrt writes PNG, under that name"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(readFile(dir + "/o.bmp").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(readImage(dir + "/o.bmp").width, 40);
  RunResult q = runVkrt("-q --backend cpu -o " + dir + "/q.bmp " + dir + "/s.test");
  EXPECT_EQ(q.exitCode, 0);
  EXPECT_EQ(q.output, "");
  RunResult strict = runVkrt("--strict --backend cpu -o " + dir + "/strict.bmp " + dir + "/s.test");
  EXPECT_EQ(strict.exitCode, 1) << strict.output;
  EXPECT_FALSE(fileExists(dir + "/strict.bmp"));
  // In the scene: the parser's warning (parse_warnings_test.cpp), PNG bytes all the same.
  writeFile(dir + "/bmp.test", kScene + "output " + dir + "/scene.bmp\n");
  RunResult scene = runVkrt("--backend cpu " + dir + "/bmp.test");
  EXPECT_EQ(scene.exitCode, 0) << scene.output;
  EXPECT_NE(scene.output.find("is not named .png, .ppm, .pfm or .exr"), std::string::npos) << scene.output;
  EXPECT_EQ(readFile(dir + "/scene.bmp").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // -o FILE overrides that line: it names nothing written, so no warning, and --strict
  // renders; -o DIR/ writes under its name, so the warning stays.
  RunResult named = runVkrt("--strict --backend cpu -o " + dir + "/named.png " + dir + "/bmp.test");
  EXPECT_EQ(named.exitCode, 0) << named.output;
  EXPECT_EQ(named.output.find("is not named"), std::string::npos) << named.output;
  EXPECT_TRUE(fileExists(dir + "/named.png"));
  std::filesystem::create_directory(dir + "/into");
  RunResult into = runVkrt("--backend cpu -o " + dir + "/into/ " + dir + "/bmp.test");
  EXPECT_EQ(into.exitCode, 0) << into.output;
  EXPECT_NE(into.output.find("is not named .png, .ppm, .pfm or .exr"), std::string::npos) << into.output;
  EXPECT_TRUE(fileExists(dir + "/into/scene.bmp"));
}
