// --crop and `vkrt merge`: a crop's pixels are the same region of a full render, bit for bit,
// on both backends (also with pixels suspended and resumed, and across band and workgroup
// boundaries); crops carry their record, and merging a grid of them gives the full render.
#include <gtest/gtest.h>

#include "cpu/reference.h"
#include "image/encode.h"
#include "image/crop.h"
#include "image/render_identity.h"
#include "image/png.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// The pixels `r` of `full`, as an image of r's size.
Image region(const Image& full, const PixelRect& r) {
  Image out(r.width(), r.height());
  for (int y = r.y0; y < r.y1; ++y)
    std::copy(full.pixel(r.x0, y), full.pixel(r.x0, y) + 3 * r.width(), out.pixel(0, y - r.y0));
  return out;
}

std::string rectName(const PixelRect& r) {
  return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," + std::to_string(r.y1);
}

// The showcase scene (spheres, triangles, mirrors, shadows) at an odd size, W x H = 61 x 43:
// neither side a multiple of the 8x8 workgroup.
SceneDesc cropScene() {
  SceneDesc scene = parseSceneFile(sourcePath("scenes/showcase.test"));
  scene.width = 61;
  scene.height = 43;
  return scene;
}

// 1x1 at the top left and at the bottom right, the right and bottom edges at odd sizes, odd
// sizes straddling the 8-pixel workgroup and band boundaries (bands of 8 rows below), a
// single row and column, and the whole image.
std::vector<PixelRect> cropsOf(int w, int h) {
  return {{0, 0, 1, 1},         {w - 1, h - 1, w, h}, {w - 13, h - 9, w, h}, {5, 3, 22, 20},
          {7, 7, 9, 9},         {3, 5, w - 2, 13},    {0, 17, w, 18},        {30, 0, 31, h},
          {0, 0, w, h}};
}

}  // namespace

TEST(Crop, CpuCropsAreTheFullRendersPixels) {
  SceneDesc scene = cropScene();
  Bvh bvh = buildBvh(scene);
  Image full = encodeImage(renderReference(scene, bvh, CpuOptions{}, nullptr), 1.0);
  for (const PixelRect& r : cropsOf(scene.width, scene.height)) {
    CpuOptions options;
    options.crop = r;
    Image crop = encodeImage(renderReference(scene, bvh, options, nullptr), 1.0);
    ASSERT_EQ(crop.width, r.width()) << rectName(r);
    ASSERT_EQ(crop.height, r.height()) << rectName(r);
    EXPECT_TRUE(crop.rgb == region(full, r).rgb)
        << rectName(r) << ": " << imagesClose("crop-cpu-" + rectName(r), crop, region(full, r), 0, 0).message();
  }
}

// Bands of 8 rows (the smallest: maxStateBytes 1) in both renders, so that crops straddle
// band boundaries of the full render and start bands of their own at other rows; and a step
// budget of 3, so that pixels are suspended and resumed.
TEST(Crop, VulkanCropsAreTheFullRendersPixels) {
  VKRT_REQUIRE_GPU(ctx);
  SceneDesc scene = cropScene();
  GpuScene flat = flatten(scene);
  for (std::uint32_t budget : {0u, 3u}) {
    VulkanOptions options;
    options.maxStateBytes = 1;
    options.stepBudget = budget;
    VulkanTimings timings;
    Image full = encodeImage(renderVulkan(*ctx, flat, options, nullptr, &timings), 1.0);
    EXPECT_GT(timings.bands, 1u);
    if (budget) {
      EXPECT_GT(timings.suspensions, 0u);
    }
    for (const PixelRect& r : cropsOf(scene.width, scene.height)) {
      options.crop = r;
      Image crop = encodeImage(renderVulkan(*ctx, flat, options, nullptr, nullptr), 1.0);
      ASSERT_EQ(crop.width, r.width()) << rectName(r);
      ASSERT_EQ(crop.height, r.height()) << rectName(r);
      EXPECT_TRUE(crop.rgb == region(full, r).rgb)
          << rectName(r) << " budget " << budget << ": "
          << imagesClose("crop-vulkan-" + rectName(r), crop, region(full, r), 0, 0).message();
    }
    options.crop.reset();
  }
  EXPECT_EQ(ctx->validationMessages(), 0);
}

TEST(Crop, RecordRoundTripsThroughPngAndPpm) {
  CropRecord record{{3, 4, 10, 9}, 64, 48};
  EXPECT_EQ(formatCropRecord(record), "3,4,10,9 of 64 48");
  std::optional<CropRecord> back = parseCropRecord("3,4,10,9 of 64 48");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->rect.x0, 3);
  EXPECT_EQ(back->rect.y1, 9);
  EXPECT_EQ(back->fullWidth, 64);
  EXPECT_EQ(back->fullHeight, 48);
  for (const char* bad : {"", "3,4,10,9", "3,4,10,9 of 64", "3,4,10,9 of 64 48 1", "3,4,10,9 in 64 48",
                          "3,4,3,9 of 64 48", "3,4,65,9 of 64 48", "-1,4,10,9 of 64 48", "3,4,10 of 64 48"})
    EXPECT_FALSE(parseCropRecord(bad)) << bad;

  std::string dir = freshDir("crop/record");
  for (const char* ext : {".png", ".ppm"}) {
    RunResult r = runVkrt("--backend cpu --crop 3,4,10,9 -o " + dir + "/tile" + ext + " " +
                          sourcePath("scenes/spheres.test"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto text = readImageText(dir + "/tile" + ext);
    ASSERT_EQ(text.size(), 2u) << ext;
    EXPECT_EQ(text[0].first, "vkrt-crop");
    EXPECT_EQ(text[0].second, "3,4,10,9 of 64 48");
    EXPECT_EQ(text[1].first, "vkrt-render");   // the render's identity (merge_identity_test.cpp)
    EXPECT_TRUE(parseRenderIdentity(text[1].second)) << text[1].second;
    Image tile = readImage(dir + "/tile" + ext);
    EXPECT_EQ(tile.width, 7);
    EXPECT_EQ(tile.height, 5);
  }
  // A full render carries no record.
  RunResult r = runVkrt("--backend cpu -o " + dir + "/full.png " + sourcePath("scenes/spheres.test"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(readImageText(dir + "/full.png").empty());
}

TEST(Crop, BadCropsAreUsageErrors) {
  std::string dir = freshDir("crop/bad");
  std::string scene = sourcePath("scenes/spheres.test");   // 64x48
  for (const char* bad : {"0,0,0,5", "0,0,5,0", "5,5,3,8", "0,0,65,48", "0,0,64,49", "64,0,65,1", "0,0,3",
                          "0,0,3,3,4", "a,b,c,d", "-1,0,3,3", "0,0,3,", "0, 0,3,3", "", "0x0,3,3,3",
                          "99999999999,0,1,1"}) {
    for (const char* backend : {"cpu", "vulkan"}) {
      RunResult r = runVkrt(std::string("--backend ") + backend + " --crop '" + bad + "' -o " + dir + "/never.png " +
                            scene);
      EXPECT_EQ(r.exitCode, 1) << bad << "\n" << r.output;
      EXPECT_EQ(r.output.rfind("vkrt: error: --crop ", 0), 0u) << r.output;
      EXPECT_FALSE(fileExists(dir + "/never.png")) << bad;
    }
  }
  RunResult outside = runVkrt("--backend cpu --crop 0,0,65,48 -o " + dir + "/never.png " + scene);
  EXPECT_NE(outside.output.find("not inside the 64x48 image"), std::string::npos) << outside.output;
  RunResult empty = runVkrt("--backend cpu --crop 5,5,3,8 -o " + dir + "/never.png " + scene);
  EXPECT_NE(empty.output.find("the rectangle is empty"), std::string::npos) << empty.output;
  // Against the size after --scale: 32x24.
  RunResult scaled = runVkrt("--backend cpu --scale 0.5 --crop 0,0,33,24 -o " + dir + "/never.png " + scene);
  EXPECT_EQ(scaled.exitCode, 1) << scaled.output;
  EXPECT_NE(scaled.output.find("not inside the 32x24 image"), std::string::npos) << scaled.output;
}

// Crops of a scene in an uneven 3x2 grid, rendered by separate runs, merged: the full render,
// bit for bit. At a size given by --size, so the crops are of the size after it.
TEST(Merge, GridOfCropsIsTheFullRender) {
  for (const char* backend : {"cpu", "vulkan"}) {
    if (std::string(backend) == "vulkan") {
      VKRT_REQUIRE_GPU(ctx);
    }
    std::string dir = freshDir(std::string("merge/grid-") + backend);
    std::string common = std::string("--backend ") + backend + " --size 61x37 " + sourcePath("scenes/showcase.test");
    RunResult full = runVkrt(common + " -o " + dir + "/full.png");
    ASSERT_EQ(full.exitCode, 0) << full.output;
    const int xs[] = {0, 20, 41, 61}, ys[] = {0, 13, 37};
    std::string tiles;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        PixelRect r{xs[i], ys[j], xs[i + 1], ys[j + 1]};
        std::string tile = dir + "/tile" + std::to_string(j * 3 + i) + ".png";
        RunResult t = runVkrt(common + " --crop " + rectName(r) + " -o " + tile);
        ASSERT_EQ(t.exitCode, 0) << t.output;
        tiles = " " + tile + tiles;   // in reverse: the records place them, not the order
      }
    RunResult merged = runVkrt("merge -o " + dir + "/merged.png" + tiles);
    ASSERT_EQ(merged.exitCode, 0) << merged.output;
    EXPECT_NE(merged.output.find("merged 6 tiles into " + dir + "/merged.png (61x37)"), std::string::npos)
        << merged.output;
    Image a = readImage(dir + "/merged.png"), b = readImage(dir + "/full.png");
    EXPECT_TRUE(a.rgb == b.rgb) << backend << ": " << imagesClose(std::string("merge-") + backend, a, b, 0, 0).message();
    EXPECT_EQ(a.width, 61);
    EXPECT_EQ(a.height, 37);
    EXPECT_TRUE(readImageText(dir + "/merged.png").empty());   // the merged image is whole
  }
}

TEST(Merge, ErrorsForTilesThatDoNotMakeOneImage) {
  std::string dir = freshDir("merge/errors");
  std::string scene = sourcePath("scenes/spheres.test");   // 64x48
  auto render = [&](const std::string& args, const std::string& name) {
    RunResult r = runVkrt("--backend cpu " + args + " -o " + dir + "/" + name + " " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.output;
  };
  render("--crop 0,0,64,24", "top.png");
  render("--crop 0,24,64,48", "bottom.png");
  render("--crop 0,20,64,30", "middle.png");
  render("--size 64x50 --crop 0,24,64,50", "other.png");
  render("", "full.png");
  struct Case {
    std::string tiles, message;
    int status;
  };
  const Case cases[] = {
      {"top.png other.png", "tiles of different images: '" + dir + "/top.png' is a crop of a 64x48 image, '" + dir +
                                "/other.png' of a 64x50 one", 1},
      {"top.png bottom.png middle.png", "tiles overlap: '" + dir + "/top.png' (0,0,64,24) and '" + dir +
                                            "/middle.png' (0,20,64,30)", 1},
      {"top.png top.png bottom.png", "tiles overlap", 1},
      {"top.png", "1536 pixels of the 64x48 image are in no tile (a tile missing?); --allow-gaps leaves them black", 1},
      {"top.png full.png", "tile '" + dir + "/full.png' has no vkrt-crop record: it is not an image written with --crop",
       1},
      {"top.png missing.png", "cannot read image '" + dir + "/missing.png'", 4},
  };
  for (const Case& c : cases) {
    std::string tiles;
    for (std::size_t at = 0, end; at < c.tiles.size(); at = end + 1) {
      end = c.tiles.find(' ', at);
      if (end == std::string::npos) end = c.tiles.size();
      tiles += " " + dir + "/" + c.tiles.substr(at, end - at);
    }
    RunResult r = runVkrt("merge -o " + dir + "/never.png" + tiles);
    EXPECT_EQ(r.exitCode, c.status) << c.tiles << "\n" << r.output;
    EXPECT_NE(r.output.find("vkrt: error: " + c.message), std::string::npos) << c.tiles << "\n" << r.output;
    EXPECT_FALSE(fileExists(dir + "/never.png")) << c.tiles;
  }
  // Usage: no output, no tile, an unknown option.
  for (const char* bad : {"merge top.png", "merge -o x.png", "merge --nope -o x.png top.png"}) {
    RunResult r = runVkrt(bad);
    EXPECT_EQ(r.exitCode, 1) << bad << "\n" << r.output;
  }

  // --allow-gaps: the pixels no tile covers are black, the rest the tile's.
  RunResult gaps = runVkrt("merge --allow-gaps -o " + dir + "/gaps.png " + dir + "/top.png");
  ASSERT_EQ(gaps.exitCode, 0) << gaps.output;
  EXPECT_NE(gaps.output.find("1536 pixels left black"), std::string::npos) << gaps.output;
  Image merged = readImage(dir + "/gaps.png"), full = readImage(dir + "/full.png");
  EXPECT_TRUE(region(merged, {0, 0, 64, 24}).rgb == region(full, {0, 0, 64, 24}).rgb);
  Image black(64, 24);
  EXPECT_TRUE(region(merged, {0, 24, 64, 48}).rgb == black.rgb);
}
