// Streaming a Whitted render to its file: the renderers hand bands of rows to a RowSink and
// the writers encode each as it comes (PNG and PPM in order, PFM at its place in the file),
// so that peak memory does not grow with the image. The bytes are those of the whole-image
// writers, and the rows those of a render held whole.
#include <cstring>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

#include "cpu/reference.h"
#include "util/errors.h"
#include "gpu/vulkan_renderer.h"
#include "image/encode.h"
#include "image/image_file.h"
#include "image/merge.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/row_sink.h"
#include "util/ray_counts.h"
#include "render/render.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

namespace {

using Records = std::vector<std::pair<std::string, std::string>>;

// Every channel different, with values past 1, negative, NaN and infinite.
RadianceImage ramp(int w, int h) {
  RadianceImage img(w, h);
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = 0.013f * static_cast<float>(i % 97) - 0.2f;
  img.rgb[5] = std::numeric_limits<float>::quiet_NaN();
  img.rgb[7] = std::numeric_limits<float>::infinity();
  return img;
}

// Rows [y0, y1) of `image`.
RadianceImage rowsOf(const RadianceImage& image, int y0, int y1) {
  RadianceImage band(image.width, y1 - y0);
  std::memcpy(band.rgb.data(), image.pixel(0, y0), band.rgb.size() * sizeof(float));
  return band;
}

// Hands `image` to the sink in bands of the given heights, repeated.
void feed(const RadianceImage& image, const std::vector<int>& heights, const RowSink& sink) {
  std::size_t k = 0;
  for (int y = 0; y < image.height; ++k) {
    int y1 = std::min(image.height, y + heights[k % heights.size()]);
    sink(y, rowsOf(image, y, y1));
    y = y1;
  }
}

std::size_t filesIn(const std::string& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

// The showcase scene (spheres, triangles, mirrors, shadows) at 61 x 43.
SceneDesc showcase() {
  SceneDesc scene = parseSceneFile(sourcePath("scenes/showcase.test"));
  scene.width = 61;
  scene.height = 43;
  return scene;
}

}  // namespace

// Bands of uneven heights (1, 5 and 17 rows) give the bytes the whole-image writers give, in
// every format, with the records.
TEST(Streaming, WritersGiveTheBytesOfTheWholeImageWriters) {
  std::string dir = freshDir("streaming/writers");
  RadianceImage image = ramp(37, 23);
  image.text = {{"vkrt-crop", "1,2,38,25 of 40 30"}, {"vkrt-render", "0123456789abcdef"}};
  for (const char* ext : {".png", ".ppm", ".pfm"}) {
    for (double gamma : {1.0, 2.2}) {
      std::string whole = dir + "/whole" + ext, streamed = dir + "/streamed" + ext;
      writeImageAtomic(image, whole, gamma);
      writeImageStreamed(streamed, gamma, image.width, image.height, image.text,
                         [&](const RowSink& sink) { feed(image, {1, 5, 17}, sink); });
      EXPECT_EQ(readFile(streamed), readFile(whole)) << ext << " gamma " << gamma;
    }
  }
  RadianceImage back = readPfm(dir + "/streamed.pfm");
  EXPECT_TRUE(sameBits(back.rgb, image.rgb));
  EXPECT_EQ(back.text, image.text);
}

// Rows out of order, too many or too few, or a render that throws: the error goes on, and
// neither the file nor a temporary one is left.
TEST(Streaming, RowsOutOfOrderOrMissingOrAFailedRenderWriteNothing) {
  std::string dir = freshDir("streaming/refused");
  RadianceImage image = ramp(9, 8);
  const std::size_t before = filesIn(dir);
  for (const char* ext : {".png", ".ppm", ".pfm"}) {
    const std::string path = dir + "/o" + ext;
    EXPECT_THROW(writeImageStreamed(path, 1.0, 9, 8, {},
                                    [&](const RowSink& sink) {
                                      sink(0, rowsOf(image, 0, 2));
                                      sink(3, rowsOf(image, 3, 8));   // rows 2 and 3 skipped
                                    }),
                 InternalError)
        << ext;
    EXPECT_THROW(writeImageStreamed(path, 1.0, 9, 8, {}, [&](const RowSink& sink) { sink(0, rowsOf(image, 0, 7)); }),
                 InternalError)
        << ext;
    EXPECT_THROW(writeImageStreamed(path, 1.0, 9, 7, {}, [&](const RowSink& sink) { sink(0, rowsOf(image, 0, 8)); }),
                 InternalError)
        << ext;
    EXPECT_THROW(writeImageStreamed(path, 1.0, 9, 8, {},
                                    [&](const RowSink& sink) {
                                      sink(0, rowsOf(image, 0, 4));
                                      throw IoError("the render failed");
                                    }),
                 IoError)
        << ext;
    EXPECT_FALSE(fileExists(path)) << ext;
  }
  EXPECT_EQ(filesIn(dir), before) << "a temporary file was left";
}

// The CPU reference in bands of 16 rows (and a crop's bands, whose rows start at the crop's
// top) hands on exactly the pixels of the render held whole, each row once, in order.
TEST(Streaming, CpuBandsAreTheWholeRendersPixels) {
  SceneDesc scene = showcase();
  Bvh bvh = buildBvh(scene);
  for (std::optional<PixelRect> crop : {std::optional<PixelRect>(), std::optional<PixelRect>(PixelRect{3, 5, 58, 40})}) {
    CpuOptions whole;
    whole.crop = crop;
    RayCounts wholeRays, bandRays;
    RadianceImage expected = renderReference(scene, bvh, whole, &wholeRays);
    CpuOptions banded = whole;
    banded.bandPixels = 1;   // the smallest band: 16 rows
    RadianceImage got(expected.width, expected.height);
    int next = 0, bands = 0;
    std::uint64_t lastDone = 0, lastTotal = 0;
    banded.progress = [&](std::uint64_t done, std::uint64_t total) {
      EXPECT_GE(done, lastDone);
      lastDone = done;
      lastTotal = total;
    };
    banded.rows = [&](int y0, const RadianceImage& band) {
      ASSERT_EQ(y0, next);
      ASSERT_EQ(band.width, expected.width);
      ASSERT_LE(band.height, 16);
      std::memcpy(got.pixel(0, y0), band.rgb.data(), band.rgb.size() * sizeof(float));
      next += band.height;
      ++bands;
    };
    RadianceImage returned = renderReference(scene, bvh, banded, &bandRays);
    EXPECT_TRUE(returned.rgb.empty()) << "the streamed image was kept";
    EXPECT_EQ(next, expected.height);
    EXPECT_GT(bands, 2);
    EXPECT_TRUE(sameBits(got.rgb, expected.rgb));
    EXPECT_EQ(bandRays.total(), wholeRays.total());
    EXPECT_EQ(lastDone, lastTotal);
    EXPECT_EQ(lastTotal, static_cast<std::uint64_t>(expected.width) * static_cast<std::uint64_t>(expected.height));
  }
}

// The Vulkan backend's bands (8 rows: maxStateBytes 1), read back and handed on, are the
// render held whole, for the image and a crop.
TEST(Streaming, VulkanBandsAreTheWholeRendersPixels) {
  VKRT_REQUIRE_GPU(ctx);
  SceneDesc scene = showcase();
  GpuScene flat = flatten(scene);
  for (std::optional<PixelRect> crop : {std::optional<PixelRect>(), std::optional<PixelRect>(PixelRect{3, 5, 58, 40})}) {
    VulkanOptions whole;
    whole.maxStateBytes = 1;
    whole.crop = crop;
    RadianceImage expected = renderVulkan(*ctx, flat, whole, nullptr, nullptr);
    VulkanOptions banded = whole;
    RadianceImage got(expected.width, expected.height);
    int next = 0, bands = 0;
    banded.rows = [&](int y0, const RadianceImage& band) {
      ASSERT_EQ(y0, next);
      ASSERT_EQ(band.width, expected.width);
      std::memcpy(got.pixel(0, y0), band.rgb.data(), band.rgb.size() * sizeof(float));
      next += band.height;
      ++bands;
    };
    RadianceImage returned = renderVulkan(*ctx, flat, banded, nullptr, nullptr);
    EXPECT_TRUE(returned.rgb.empty()) << "the streamed image was kept";
    EXPECT_EQ(next, expected.height);
    EXPECT_GT(bands, 2);
    EXPECT_TRUE(sameBits(got.rgb, expected.rgb));
  }
  EXPECT_EQ(ctx->validationMessages(), 0);
}

// `vkrt -o` streams a Whitted render into PNG, PPM and PFM: the files hold the render
// renderSceneInMemory gives (with a crop's records), bit for bit.
TEST(Streaming, CliOutputIsTheRenderHeldWhole) {
  std::string dir = freshDir("streaming/cli");
  const std::string scene = sourcePath("scenes/showcase.test");
  RenderRequest request;
  request.scenePath = scene;
  request.backend = Backend::Cpu;
  request.width = 61;
  request.height = 43;
  request.crop = PixelRect{3, 5, 58, 40};
  ProgressBar quiet(false);
  RenderReport report;
  RadianceImage expected = renderSceneInMemory(request, quiet, report, false);
  for (const char* ext : {".png", ".ppm", ".pfm"}) {
    const std::string out = dir + "/o" + ext;
    RunResult r = runVkrt("--backend cpu -q --size 61x43 --crop 3,5,58,40 -o " + out + " " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readImageText(out), expected.text) << ext;
    if (std::string(ext) == ".pfm") {
      EXPECT_TRUE(sameBits(readPfm(out).rgb, expected.rgb));
    } else {
      EXPECT_TRUE(readImage(out).rgb == encodeImage(expected, 1.0).rgb) << ext;
    }
  }
}

// A tall PFM streams: its rows go to their places in the file as the bands come, so that the
// peak memory is far below the float image (16384 x 2048: 384 MB).
TEST(LargeImage, PfmRowsGoToTheirPlaceWithoutTheWholeImage) {
  std::string dir = freshDir("streaming/large-pfm");
  writeFile(dir + "/wide.test",
            "size 16384 2048\ncamera 0 0 4 0 0 0 0 1 0 45\nambient 0.3 0.2 0.1\nsphere 0 0 0 1\n");
  MeasuredRun r = runVkrtMeasuringMemory({"--backend", "cpu", "-q", "-o", dir + "/o.pfm", dir + "/wide.test"}, dir + "/log");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::printf("[ stats    ] 16384x2048 PFM, cpu: peak RSS %lld MB (float image 384 MB)\n", r.peakRssKb / 1024);
  EXPECT_LT(r.peakRssKb / 1024, 40);
  RadianceImage img = readPfm(dir + "/o.pfm");
  ASSERT_EQ(img.width, 16384);
  ASSERT_EQ(img.height, 2048);
  EXPECT_EQ(img.pixel(8192, 1024)[0], 0.3f);   // the ambient sphere in the middle
  EXPECT_EQ(img.pixel(8192, 1024)[2], 0.1f);
  EXPECT_EQ(img.pixel(0, 0)[0], 0.0f);         // black corners
  EXPECT_EQ(img.pixel(16383, 2047)[1], 0.0f);
  fs::remove(dir + "/o.pfm");
}

// `vkrt merge` of crops streams too: writeMergedCrops gives the bytes of the merge held whole
// (8-bit tiles to PNG and PPM, PFM tiles to PFM and PNG), also with gaps and with tiles of
// uneven heights that start and end at other rows; a .pfm of 8-bit tiles is refused.
TEST(Streaming, MergeWritesTheBytesOfTheMergeHeldWhole) {
  std::string dir = freshDir("streaming/merge");
  const std::string scene = sourcePath("scenes/showcase.test");
  // Uneven tiles: a tall one on the left, three of other heights on the right; one hole.
  const PixelRect rects[] = {{0, 0, 20, 43}, {20, 0, 61, 7}, {20, 7, 40, 30}, {40, 7, 61, 43}, {20, 30, 40, 40}};
  std::vector<std::string> png, pfm;
  for (std::size_t i = 0; i < std::size(rects); ++i) {
    const PixelRect& r = rects[i];
    const std::string crop = std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," +
                             std::to_string(r.y1);
    for (const char* ext : {".png", ".pfm"}) {
      const std::string out = dir + "/tile" + std::to_string(i) + ext;
      RunResult t = runVkrt("--backend cpu -q --size 61x43 --crop " + crop + " -o " + out + " " + scene);
      ASSERT_EQ(t.exitCode, 0) << t.output;
      (std::string(ext) == ".png" ? png : pfm).push_back(out);
    }
  }
  for (bool gaps : {false, true}) {
    std::vector<std::string> tiles8 = png, tilesF = pfm;
    if (gaps) {   // a hole at 20,7,40,30: the tile below it starts while no tile ends there
      tiles8.erase(tiles8.begin() + 2);
      tilesF.erase(tilesF.begin() + 2);
    }
    Image whole8 = mergeCrops(tiles8, true);
    RadianceImage wholeF = mergeFloatCrops(tilesF, true);
    writeImageAtomic(whole8, dir + "/whole.png");
    writeImageAtomic(whole8, dir + "/whole.ppm");
    writeImageAtomic(wholeF, dir + "/whole.pfm", 1.0);
    writeImageAtomic(wholeF, dir + "/whole-f.png", 1.0);
    MergeReport report;
    writeMergedCrops(tiles8, true, dir + "/streamed.png", &report);
    EXPECT_EQ(report.width, 61);
    EXPECT_EQ(report.height, 43);
    EXPECT_EQ(report.gapPixels, gaps ? 20u * 3u + 20u * 23u : 20u * 3u);
    writeMergedCrops(tiles8, true, dir + "/streamed.ppm");
    writeMergedCrops(tilesF, true, dir + "/streamed.pfm");
    writeMergedCrops(tilesF, true, dir + "/streamed-f.png");
    EXPECT_EQ(readFile(dir + "/streamed.png"), readFile(dir + "/whole.png")) << gaps;
    EXPECT_EQ(readFile(dir + "/streamed.ppm"), readFile(dir + "/whole.ppm")) << gaps;
    EXPECT_EQ(readFile(dir + "/streamed.pfm"), readFile(dir + "/whole.pfm")) << gaps;
    EXPECT_EQ(readFile(dir + "/streamed-f.png"), readFile(dir + "/whole-f.png")) << gaps;
  }
  EXPECT_THROW(writeMergedCrops(png, true, dir + "/never.pfm"), UsageError);
  EXPECT_FALSE(fileExists(dir + "/never.pfm"));
}

// A merge of 16 PFM tiles of 16384x128 streams: each tile is read when the rows reach it and
// dropped after, so the peak is a tile or two, not the 384 MB merged image.
TEST(LargeImage, MergeOfTallPfmTilesStreamsWithoutTheWholeImage) {
  std::string dir = freshDir("streaming/large-merge");
  writeFile(dir + "/wide.test",
            "size 16384 2048\ncamera 0 0 4 0 0 0 0 1 0 45\nambient 0.3 0.2 0.1\nsphere 0 0 0 1\n");
  std::vector<std::string> args = {"merge", "-q", "-o", dir + "/merged.pfm"};
  for (int i = 0; i < 16; ++i) {
    const std::string tile = dir + "/tile" + std::to_string(i) + ".pfm";
    RunResult t = runVkrt("--backend cpu -q --crop 0," + std::to_string(i * 128) + ",16384," +
                          std::to_string(i * 128 + 128) + " -o " + tile + " " + dir + "/wide.test");
    ASSERT_EQ(t.exitCode, 0) << t.output;
    args.push_back(tile);
  }
  MeasuredRun r = runVkrtMeasuringMemory(args, dir + "/log");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::printf("[ stats    ] merge of 16 tiles into 16384x2048 PFM: peak RSS %lld MB (float image 384 MB)\n",
              r.peakRssKb / 1024);
  EXPECT_LT(r.peakRssKb / 1024, 96);
  RadianceImage img = readPfm(dir + "/merged.pfm");
  ASSERT_EQ(img.height, 2048);
  EXPECT_EQ(img.pixel(8192, 1024)[0], 0.3f);
  EXPECT_EQ(img.pixel(0, 0)[0], 0.0f);
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".pfm") fs::remove(e.path());
}
