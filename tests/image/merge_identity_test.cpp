// `vkrt merge` checks what its parts are: each tile and batch carries the identity of its
// render (a hash of the scene file and the settings that change the picture), and merge
// refuses parts of different renders; every record field is range-checked before it sizes
// anything; a part that is empty, cut short or unreadable is an I/O error naming it.
#include <gtest/gtest.h>

#include "image/crop.h"
#include "image/image_file.h"
#include "image/merge.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/render_identity.h"
#include "image/samples.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// Two scenes of one size that differ only in a colour: their tiles fit together, and must not.
const char* kSceneA = "size 32 24\ncamera 0 0 4 0 0 0 0 1 0 45\nambient 0.3 0.2 0.1\nsphere 0 0 0 1\n";
const char* kSceneB = "size 32 24\ncamera 0 0 4 0 0 0 0 1 0 45\nambient 0.1 0.2 0.3\nsphere 0 0 0 1\n";
const char* kPathA =
    "size 12 8\nintegrator pathtracer\nspp 2\ncamera 0 0 4 0 0 0 0 1 0 45\nquadLight -1 2 -1 2 0 0 0 0 2 4 4 4\n"
    "diffuse 0.5 0.4 0.3\nsphere 0 0 0 1\n";
const char* kPathB =
    "size 12 8\nintegrator pathtracer\nspp 2\ncamera 0 0 4 0 0 0 0 1 0 45\nquadLight -1 2 -1 2 0 0 0 0 2 4 4 4\n"
    "diffuse 0.3 0.4 0.5\nsphere 0 0 0 1\n";

std::string identityOf(const std::string& path) {
  for (const auto& [k, v] : readImageText(path))
    if (k == kRenderKeyword) return v;
  return "";
}

void render(const std::string& args) {
  RunResult r = runVkrt("--backend cpu -q " + args);
  ASSERT_EQ(r.exitCode, 0) << args << "\n" << r.output;
}

void expectRefused(const std::string& mergeArgs, int status, const std::string& message, const std::string& out) {
  RunResult r = runVkrt("merge -o " + out + " " + mergeArgs);
  EXPECT_EQ(r.exitCode, status) << mergeArgs << "\n" << r.output;
  EXPECT_NE(r.output.find("vkrt: error: " + message), std::string::npos) << mergeArgs << "\n" << r.output;
  EXPECT_FALSE(fileExists(out)) << mergeArgs;
}

}  // namespace

TEST(RenderIdentity, RecordRoundTripsAndFnvIsTheStandardHash) {
  // FNV-1a 64 of "a" (the published test vector), fed whole or in pieces.
  Fnv1a64 a;
  a.add("a");
  EXPECT_EQ(a.value(), 0xaf63dc4c8601ec8cULL);
  Fnv1a64 whole, pieces;
  whole.add("foobar");
  pieces.add("foo");
  pieces.add("bar");
  EXPECT_EQ(whole.value(), pieces.value());
  EXPECT_EQ(whole.value(), 0x85944171f73967e8ULL);
  EXPECT_EQ(formatRenderIdentity(0xaf63dc4c8601ec8cULL), "af63dc4c8601ec8c");
  EXPECT_EQ(parseRenderIdentity("af63dc4c8601ec8c"), 0xaf63dc4c8601ec8cULL);
  for (const char* bad :
       {"", "af63dc4c8601ec8", "af63dc4c8601ec8c0", "af63dc4c8601ec8g", " f63dc4c8601ec8c", "AF63DC4C8601EC8C"})
    EXPECT_FALSE(parseRenderIdentity(bad)) << bad;
}

// Tiles of one render carry one identity whatever the crop; another scene file of the same
// size, or another --maxdepth, gives another, and merge refuses them together.
TEST(MergeIdentity, TilesOfDifferentScenesOrSettingsOfOneSizeAreRefused) {
  std::string dir = freshDir("merge-identity/tiles");
  writeFile(dir + "/a.test", kSceneA);
  writeFile(dir + "/b.test", kSceneB);
  render("--crop 0,0,32,12 -o " + dir + "/a-top.png " + dir + "/a.test");
  render("--crop 0,12,32,24 -o " + dir + "/a-bottom.png " + dir + "/a.test");
  render("--crop 0,12,32,24 -o " + dir + "/b-bottom.png " + dir + "/b.test");
  render("--crop 0,12,32,24 --maxdepth 2 -o " + dir + "/a-depth2.png " + dir + "/a.test");
  render("--backend vulkan --crop 0,12,32,24 -o " + dir + "/a-bottom-vulkan.png " + dir + "/a.test");
  const std::string top = identityOf(dir + "/a-top.png");
  EXPECT_TRUE(parseRenderIdentity(top)) << top;
  EXPECT_EQ(identityOf(dir + "/a-bottom.png"), top);
  EXPECT_EQ(identityOf(dir + "/a-bottom-vulkan.png"), top) << "the backend changes only rounding";
  const std::string other = identityOf(dir + "/b-bottom.png");
  EXPECT_NE(other, top);
  EXPECT_NE(identityOf(dir + "/a-depth2.png"), top);

  RunResult ok = runVkrt("merge -o " + dir + "/a.png " + dir + "/a-top.png " + dir + "/a-bottom.png");
  EXPECT_EQ(ok.exitCode, 0) << ok.output;
  EXPECT_EQ(ok.output.find("warning:"), std::string::npos) << ok.output;
  expectRefused(dir + "/a-top.png " + dir + "/b-bottom.png", 1,
                "tiles of different renders: '" + dir + "/a-top.png' and '" + dir +
                    "/b-bottom.png' differ in their scene file or settings (vkrt-render " + top + " and " + other + ")",
                dir + "/never.png");
  expectRefused(dir + "/a-top.png " + dir + "/a-depth2.png", 1,
                "tiles of different renders: '" + dir + "/a-top.png' and '" + dir + "/a-depth2.png'", dir + "/never.png");
}

// Sample batches of two path-traced scenes of one size (and one gamma) are refused; batches of
// one scene with other seeds and spp merge.
TEST(MergeIdentity, BatchesOfDifferentScenesOfOneSizeAreRefused) {
  std::string dir = freshDir("merge-identity/batches");
  writeFile(dir + "/a.test", kPathA);
  writeFile(dir + "/b.test", kPathB);
  render("--seed 1 -o " + dir + "/a1.pfm " + dir + "/a.test");
  render("--seed 2 --spp 3 -o " + dir + "/a2.pfm " + dir + "/a.test");
  render("--seed 3 -o " + dir + "/b3.pfm " + dir + "/b.test");
  EXPECT_EQ(identityOf(dir + "/a1.pfm"), identityOf(dir + "/a2.pfm"));
  RunResult ok = runVkrt("merge -o " + dir + "/a.pfm " + dir + "/a1.pfm " + dir + "/a2.pfm");
  ASSERT_EQ(ok.exitCode, 0) << ok.output;
  EXPECT_EQ(identityOf(dir + "/a.pfm"), identityOf(dir + "/a1.pfm")) << "the mean is of the same render";
  expectRefused(dir + "/a1.pfm " + dir + "/a2.pfm " + dir + "/b3.pfm", 1,
                "batches of different renders: '" + dir + "/a1.pfm' and '" + dir + "/b3.pfm' differ in their scene file",
                dir + "/never.pfm");
  // The merged mean merges on with further batches of its render, not with others.
  render("--seed 4 -o " + dir + "/a4.pfm " + dir + "/a.test");
  RunResult more = runVkrt("merge -o " + dir + "/a-more.pfm " + dir + "/a.pfm " + dir + "/a4.pfm");
  EXPECT_EQ(more.exitCode, 0) << more.output;
  expectRefused(dir + "/a.pfm " + dir + "/b3.pfm", 1, "batches of different renders", dir + "/never.pfm");
}

// Parts written before the identity existed merge, with a warning naming each; a part whose
// identity is not 16 hex digits, or that carries a record twice, is refused.
TEST(MergeIdentity, PartsWithoutAnIdentityMergeWithAWarningAndMalformedOnesAreRefused) {
  std::string dir = freshDir("merge-identity/old");
  Image top = gradient(8, 4), bottom = gradient(8, 4);
  top.text = {{kCropKeyword, "0,0,8,4 of 8 8"}};
  bottom.text = {{kCropKeyword, "0,4,8,8 of 8 8"}};
  writeImageAtomic(top, dir + "/top.png");
  writeImageAtomic(bottom, dir + "/bottom.png");
  RunResult r = runVkrt("merge -o " + dir + "/m.png " + dir + "/top.png " + dir + "/bottom.png");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: warning: tile '" + dir + "/bottom.png' has no vkrt-render record (written by an "
                          "older vkrt): merged without checking"),
            std::string::npos)
      << r.output;
  RunResult quiet = runVkrt("merge -q -o " + dir + "/m.png " + dir + "/top.png " + dir + "/bottom.png");
  EXPECT_EQ(quiet.output, "");
  MergeReport report;
  mergeCrops({dir + "/top.png", dir + "/bottom.png"}, false, &report);
  EXPECT_EQ(report.warnings.size(), 2u);

  Image twice = bottom;
  twice.text.emplace_back(kCropKeyword, "0,0,8,4 of 8 8");
  writeImageAtomic(twice, dir + "/twice.png");
  expectRefused(dir + "/top.png " + dir + "/twice.png", 1,
                "tile '" + dir + "/twice.png' carries two vkrt-crop records ('0,4,8,8 of 8 8' and '0,0,8,4 of 8 8')",
                dir + "/never.png");
  bottom.text.emplace_back(kRenderKeyword, "not-hex-digits!!");
  writeImageAtomic(bottom, dir + "/bad.png");
  expectRefused(dir + "/top.png " + dir + "/bad.png", 1,
                "tile '" + dir + "/bad.png': malformed vkrt-render record 'not-hex-digits!!'", dir + "/never.png");
}

// Forged crop records: a full image beyond the size limit (2^31 - 1, or 20000 x 20000 with
// --allow-gaps) is a malformed record naming the file, refused before the merged image is
// allocated; nothing is written.
TEST(MergeIdentity, RecordFieldsOutOfRangeAreUsageErrors) {
  std::string dir = freshDir("merge-identity/forged");
  Image tile = gradient(1, 1);
  for (const std::string& value : {std::string("0,0,1,1 of 2147483647 1"), std::string("0,0,1,1 of 20000 20000"),
                                   std::string("0,0,1,1 of 1 2147483647"), std::string("0,0,1,1 of 16385 1")}) {
    tile.text = {{kCropKeyword, value}};
    writeImageAtomic(tile, dir + "/forged.png");
    MeasuredRun r = runVkrtMeasuringMemory({"merge", "--allow-gaps", "-o", dir + "/never.png", dir + "/forged.png"},
                                           dir + "/log");
    EXPECT_EQ(r.exitCode, 1) << value << "\n" << r.output;
    EXPECT_NE(r.output.find("vkrt: error: tile '" + dir + "/forged.png': malformed vkrt-crop record '" + value +
                            "' (the full image is not from 1 to 16384 pixels on a side)"),
              std::string::npos)
        << r.output;
    EXPECT_LT(r.peakRssKb / 1024, 100) << value;
    EXPECT_FALSE(fileExists(dir + "/never.png"));
  }
  std::string why;
  EXPECT_TRUE(parseCropRecord("0,0,16384,16384 of 16384 16384", &why)) << why;
  // A samples record whose counts wrap around 2^64 to its TOTAL is malformed.
  EXPECT_FALSE(parseSampleRecord("0 gamma 1 seeds 1:0+9223372036854775807 2:0+9223372036854775807 3:0+2"));
  EXPECT_FALSE(parseSampleRecord("1 gamma 1 seeds 1:0+9223372036854775807 2:0+9223372036854775807 3:0+3"));
  // Batches whose counts together pass 2^64 are refused.
  RadianceImage img(2, 2);
  std::vector<std::string> paths;
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    RadianceImage b = img;
    b.text = {{kSamplesKeyword, "9223372036854775807 gamma 1 seeds " + std::to_string(seed) + ":0+9223372036854775807"}};
    paths.push_back(dir + "/huge" + std::to_string(seed) + ".pfm");
    writePfmAtomic(b, paths.back());
  }
  expectRefused(paths[0] + " " + paths[1] + " " + paths[2], 1,
                "batch '" + paths[2] + "': the batches hold more than 2^64 samples per pixel in all", dir + "/never.pfm");
}

// An empty, truncated or unreadable tile or batch is an I/O error (status 4) naming the file,
// not "no record"; a PFM whose header claims more pixels than the file holds is refused before
// its raster is allocated.
TEST(MergeIdentity, EmptyTruncatedOrUnreadablePartsAreIoErrors) {
  std::string dir = freshDir("merge-identity/truncated");
  writeFile(dir + "/a.test", kSceneA);
  writeFile(dir + "/p.test", kPathA);
  render("--crop 0,0,32,12 -o " + dir + "/top.png " + dir + "/a.test");
  render("--crop 0,12,32,24 -o " + dir + "/bottom.png " + dir + "/a.test");
  render("--crop 0,12,32,24 -o " + dir + "/bottom.ppm " + dir + "/a.test");
  render("--crop 0,0,32,12 -o " + dir + "/top.pfm " + dir + "/a.test");
  render("--crop 0,12,32,24 -o " + dir + "/bottom.pfm " + dir + "/a.test");
  render("--seed 1 -o " + dir + "/b1.pfm " + dir + "/p.test");
  render("--seed 2 -o " + dir + "/b2.pfm " + dir + "/p.test");
  auto cut = [&](const std::string& from, const std::string& to, std::size_t keep) {
    std::string bytes = readFile(dir + "/" + from);
    ASSERT_LT(keep, bytes.size());
    writeFile(dir + "/" + to, bytes.substr(0, keep));
  };
  const std::string png = readFile(dir + "/bottom.png");
  cut("bottom.png", "cut-png-head.png", 40);                  // inside the records
  cut("bottom.png", "cut-png.png", png.size() - 20);          // inside the image data
  cut("bottom.png", "cut-png-iend.png", png.size() - 12);     // without IEND
  cut("bottom.ppm", "cut.ppm", readFile(dir + "/bottom.ppm").size() - 7);
  cut("bottom.pfm", "cut.pfm", readFile(dir + "/bottom.pfm").size() / 2);
  cut("b2.pfm", "cut-batch.pfm", readFile(dir + "/b2.pfm").size() / 2);
  writeFile(dir + "/empty.png", "");
  writeFile(dir + "/garbage.png", "this is not an image at all");
  writeFile(dir + "/huge.pfm", "PF\n1048576 1048576\n-1.0\n0123456789abcdef");
  const std::pair<std::string, std::string> cases[] = {
      {"top.png empty.png", "cannot read image '" + dir + "/empty.png': the file is empty"},
      {"top.png cut-png-head.png", "cannot read image '" + dir + "/cut-png-head.png': the PNG is truncated"},
      {"top.png cut-png.png", "cannot read image '" + dir + "/cut-png.png': the PNG is truncated"},
      {"top.png cut-png-iend.png", "cannot read image '" + dir + "/cut-png-iend.png': the PNG is truncated"},
      {"top.png garbage.png", "cannot read image '" + dir + "/garbage.png'"},
      {"top.png cut.ppm", "cannot read image '" + dir + "/cut.ppm': the PPM raster is truncated"},
      {"top.pfm cut.pfm", "cannot read image '" + dir + "/cut.pfm': the PFM raster is truncated"},
      {"top.pfm huge.pfm", "cannot read image '" + dir + "/huge.pfm': the PFM raster is truncated"},
      {"b1.pfm cut-batch.pfm", "cannot read image '" + dir + "/cut-batch.pfm': the PFM raster is truncated"},
  };
  for (const auto& [parts, message] : cases) {
    std::string paths;
    for (std::size_t at = 0, end; at < parts.size(); at = end + 1) {
      end = parts.find(' ', at);
      if (end == std::string::npos) end = parts.size();
      paths += " " + dir + "/" + parts.substr(at, end - at);
    }
    expectRefused(paths, 4, message, dir + "/never.png");
  }
  // The whole tiles merge.
  RunResult ok = runVkrt("merge -o " + dir + "/m.png " + dir + "/top.png " + dir + "/bottom.png");
  EXPECT_EQ(ok.exitCode, 0) << ok.output;
}
