// Linear float images: the encoding at output (quantization and gamma), PFM files written and
// read back, the sample record, the weighted mean of sample batches, the progressive driver
// (with the Whitted model and with a fake integrator), and `vkrt merge` of sample batches.
#include <cmath>
#include <cstring>
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
#include "image/samples.h"
#include "render/progressive.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A w x h image whose every channel differs (and covers awkward values).
RadianceImage ramp(int w, int h) {
  RadianceImage img(w, h);
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = 0.1f * static_cast<float>(i) - 0.3f;
  return img;
}

RadianceImage filled(int w, int h, float v, std::uint64_t samples) {
  RadianceImage img(w, h);
  std::fill(img.rgb.begin(), img.rgb.end(), v);
  img.samples = samples;
  return img;
}

// A batch file as `vkrt --seed SEED --spp COUNT -o NAME.pfm` writes it (a path render).
std::string writeBatch(const std::string& path, RadianceImage img, SampleRecord record) {
  img.text.emplace_back(kSamplesKeyword, formatSampleRecord(record));
  writePfmAtomic(img, path);
  return path;
}

const char* kWhittedScene =
    "size 24 16\ncamera 0 0 4 0 0 0 0 1 0 45\npoint 2 2 2 1 1 1\nambient 0.05 0.05 0.05\n"
    "diffuse 0.6 0.3 0.2\nspecular 0.3 0.3 0.3\nshininess 20\nsphere 0 0 0 1\n"
    "diffuse 0.2 0.5 0.2\nvertex -3 -1 -3\nvertex 3 -1 -3\nvertex 3 -1 3\nvertex -3 -1 3\ntri 0 2 1\ntri 0 3 2\n";

}  // namespace

// ---- encoding -----------------------------------------------------------------------------------

// doc/scene-format.md, "Conventions" and doc/path-tracing.md's gamma, against bytes computed by hand.
TEST(Encode, GammaOneIsFloorOf255TimesTheClampedValue) {
  EXPECT_EQ(encodeChannel(0.0f, 1.0), 0);
  EXPECT_EQ(encodeChannel(0.5f, 1.0), 127);    // 127.5
  EXPECT_EQ(encodeChannel(0.2f, 1.0), 51);     // 51.000001 in float
  EXPECT_EQ(encodeChannel(1.0f, 1.0), 255);
  EXPECT_EQ(encodeChannel(7.0f, 1.0), 255);
  EXPECT_EQ(encodeChannel(-0.5f, 1.0), 0);
  EXPECT_EQ(encodeChannel(kNaN, 1.0), 0);
  EXPECT_EQ(encodeChannel(kInf, 1.0), 255);
  EXPECT_EQ(encodeChannel(-kInf, 1.0), 0);
  EXPECT_EQ(encodeChannel(1.0f / 255.0f, 1.0), 1);
  EXPECT_EQ(encodeChannel(std::nextafter(1.0f / 255.0f, 0.0f), 1.0), 0);
}

TEST(Encode, GammaRaisesToOneOverGammaBeforeQuantizing) {
  EXPECT_EQ(encodeChannel(0.25f, 2.0), 127);   // 0.5 -> 127.5
  EXPECT_EQ(encodeChannel(0.01f, 2.0), 25);    // 0.1 -> 25.5
  EXPECT_EQ(encodeChannel(0.5f, 2.2), 186);    // 0.5^(1/2.2) = 0.72974 -> 186.08
  EXPECT_EQ(encodeChannel(0.18f, 2.2), 116);   // 0.18^(1/2.2) = 0.45866 -> 116.96
}

TEST(Encode, ImageKeepsItsRecordsAndEncodesEveryChannel) {
  RadianceImage img(2, 1);
  img.rgb = {0.0f, 0.25f, 0.5f, 1.0f, kNaN, 2.0f};
  img.text.emplace_back("vkrt-crop", "0,0,2,1 of 4 4");
  Image bytes = encodeImage(img, 2.0);
  EXPECT_EQ(bytes.rgb, (std::vector<std::uint8_t>{0, 127, 180, 255, 0, 255}));   // sqrt(0.5) = 0.7071 -> 180.3
  ASSERT_EQ(bytes.text.size(), 1u);
  EXPECT_EQ(bytes.text[0].first, "vkrt-crop");
}

// ---- PFM ----------------------------------------------------------------------------------------

TEST(Pfm, WrittenAndReadBackBitExactWithRecords) {
  std::string dir = freshDir("float/pfm-roundtrip");
  RadianceImage img = ramp(5, 3);
  img.rgb[0] = kNaN;
  img.rgb[1] = kInf;
  img.rgb[2] = -kInf;
  img.rgb[3] = std::numeric_limits<float>::denorm_min();
  img.rgb[4] = -0.0f;
  img.rgb[5] = std::numeric_limits<float>::max();
  img.text.emplace_back("vkrt-crop", "1,2,6,5 of 10 10");
  img.text.emplace_back(kSamplesKeyword, "4 gamma 2.2000000000000002 seeds 3:0+4");
  writePfmAtomic(img, dir + "/a.pfm");
  RadianceImage back = readPfm(dir + "/a.pfm");
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_TRUE(sameBits(back.rgb, img.rgb));
  EXPECT_EQ(back.text, img.text);
  EXPECT_EQ(readImageText(dir + "/a.pfm"), img.text);
  EXPECT_EQ(fileCount(dir), 1u);   // no temporary file left
}

// The format as other readers know it: the header, then little-endian floats, bottom row
// first; a file without records ends with the raster.
TEST(Pfm, LayoutIsTheFormatsBottomRowFirst) {
  std::string dir = freshDir("float/pfm-layout");
  RadianceImage img = ramp(3, 2);
  writeImageAtomic(img, dir + "/a.PFM", 2.2);   // by extension, any case; no gamma applied
  std::string bytes = readFile(dir + "/a.PFM");
  const std::string header = "PF\n3 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 3 * 2 * 3 * 4);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  float first[3];
  std::memcpy(first, bytes.data() + header.size(), sizeof first);   // x86 and ARM are little-endian
  EXPECT_EQ(first[0], img.pixel(0, 1)[0]);   // the bottom row comes first
  EXPECT_EQ(first[2], img.pixel(0, 1)[2]);
  EXPECT_TRUE(isPfmFile(dir + "/a.PFM"));
  EXPECT_TRUE(imageFormatFor("x.pfm").linearFloat);
  EXPECT_TRUE(hasImageExtension("x.Pfm"));
}

TEST(Pfm, ReadsBigEndianAndGreyFiles) {
  std::string dir = freshDir("float/pfm-read");
  // Big-endian (positive scale) colour, 1x1: 1.5, -2, 0.25.
  std::string be = "PF\n1 1\n1.0\n";
  for (std::uint32_t bits : {0x3FC00000u, 0xC0000000u, 0x3E800000u})
    for (int shift = 24; shift >= 0; shift -= 8) be += static_cast<char>((bits >> shift) & 0xFF);
  writeFile(dir + "/be.pfm", be);
  RadianceImage a = readPfm(dir + "/be.pfm");
  EXPECT_EQ(a.rgb, (std::vector<float>{1.5f, -2.0f, 0.25f}));
  // Grey, 2x1, little-endian.
  std::string grey = "Pf\n2 1\n-1\n";
  float v[2] = {0.5f, 3.0f};
  grey.append(reinterpret_cast<const char*>(v), sizeof v);
  writeFile(dir + "/grey.pfm", grey);
  RadianceImage b = readPfm(dir + "/grey.pfm");
  EXPECT_EQ(b.rgb, (std::vector<float>{0.5f, 0.5f, 0.5f, 3.0f, 3.0f, 3.0f}));
  writeFile(dir + "/short.pfm", "PF\n2 2\n-1.0\nabc");
  EXPECT_THROW(readPfm(dir + "/short.pfm"), IoError);
  writeFile(dir + "/bad.pfm", "PF\n2 x\n-1.0\n");
  EXPECT_THROW(readPfm(dir + "/bad.pfm"), IoError);
}

TEST(Pfm, BytesAreNotWrittenAsPfm) {
  std::string dir = freshDir("float/pfm-bytes");
  EXPECT_THROW(writeImageAtomic(gradient(2, 2), dir + "/a.pfm"), UsageError);
  EXPECT_EQ(fileCount(dir), 0u);
}

// PNG and PPM from a RadianceImage: the encoding, once, with the gamma given.
TEST(ImageFile, RadianceIsEncodedWithTheGammaForPngAndPpm) {
  std::string dir = freshDir("float/encode-files");
  RadianceImage img = ramp(4, 3);
  writeImageAtomic(img, dir + "/a.png", 2.0);
  writeImageAtomic(img, dir + "/a.ppm", 2.0);
  EXPECT_EQ(readImage(dir + "/a.png").rgb, encodeImage(img, 2.0).rgb);
  EXPECT_EQ(readImage(dir + "/a.ppm").rgb, encodeImage(img, 2.0).rgb);
  EXPECT_NE(encodeImage(img, 2.0).rgb, encodeImage(img, 1.0).rgb);
}

// ---- sample records and the weighted mean -------------------------------------------------------

TEST(Samples, RecordRoundTripsAndRejectsMalformedOnes) {
  SampleRecord r{{{7, 0, 16}, {9, 16, 8}}, 2.2};
  std::string text = formatSampleRecord(r);
  EXPECT_EQ(text, "24 gamma 2.2000000000000002 seeds 7:0+16 9:16+8");
  std::optional<SampleRecord> back = parseSampleRecord(text);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->gamma, 2.2);
  ASSERT_EQ(back->ranges.size(), 2u);
  EXPECT_EQ(back->ranges[1].seed, 9u);
  EXPECT_EQ(back->ranges[1].first, 16u);
  EXPECT_EQ(back->total(), 24u);
  EXPECT_FALSE(back->stratified);
  // --sampler stratified is named; independent samples keep the record as it always was.
  SampleRecord strata{{{7, 0, 16}}, 1.0, true};
  EXPECT_EQ(formatSampleRecord(strata), "16 gamma 1 sampler stratified seeds 7:0+16");
  std::optional<SampleRecord> strataBack = parseSampleRecord(formatSampleRecord(strata));
  ASSERT_TRUE(strataBack);
  EXPECT_TRUE(strataBack->stratified);
  EXPECT_EQ(strataBack->total(), 16u);
  for (const char* bad : {"", "4", "5 gamma 1 seeds 1:0+4", "4 gamma 1 sampler seeds 1:0+4",
                          "4 gamma 1 sampler independent seeds 1:0+4", "4 gamma 1 sampler stratified 1:0+4", "4 gamma 0 seeds 1:0+4", "4 gamma 1 seeds",
                          "4 gamma 1 seeds 1:0+0", "4 gamma 1 seeds x:0+4", "8 gamma 1 seeds 1:0+4 1:2+4",
                          "4 gamma 1 seeds 4294967296:0+4", "4 gamma nan seeds 1:0+4"})
    EXPECT_FALSE(parseSampleRecord(bad)) << bad;
  EXPECT_EQ(sharedSample(SampleRecord{{{1, 0, 4}}, 1}, SampleRecord{{{1, 3, 4}}, 1}), "seed 1, sample 3");
  EXPECT_EQ(sharedSample(SampleRecord{{{1, 0, 4}}, 1}, SampleRecord{{{1, 4, 4}}, 1}), "");
  EXPECT_EQ(sharedSample(SampleRecord{{{1, 0, 4}}, 1}, SampleRecord{{{2, 0, 4}}, 1}), "");
}

// A 1-sample batch and a 3-sample batch: (1 x 1 + 3 x 2) / 4, not the plain mean 1.5.
TEST(Samples, MeanIsWeightedBySampleCount) {
  RadianceImage mean;
  mean.samples = 0;
  accumulateMean(mean, filled(3, 2, 1.0f, 1));
  accumulateMean(mean, filled(3, 2, 2.0f, 3));
  EXPECT_EQ(mean.samples, 4u);
  for (float v : mean.rgb) EXPECT_EQ(v, 1.75f);
  EXPECT_THROW(accumulateMean(mean, filled(2, 2, 1.0f, 1)), InternalError);
}

// ---- the progressive driver ---------------------------------------------------------------------

// A fake integrator: sample s of every pixel is s, so the mean of [0, n) is (n - 1) / 2 whatever
// the batches; each sample costs `secondsPerSample` on a fake clock.
struct FakeIntegrator {
  double clock = 0, secondsPerSample = 0;
  std::vector<SampleBatch> batches;
  RadianceImage operator()(const SampleBatch& b) {
    batches.push_back(b);
    clock += secondsPerSample * b.count;
    double sum = 0;
    for (std::uint64_t s = b.firstSample; s < b.firstSample + b.count; ++s) sum += static_cast<double>(s);
    return filled(4, 3, static_cast<float>(sum / b.count), b.count);
  }
  // renderProgressive with these batches, on this clock.
  RadianceImage render(ProgressiveOptions o, ProgressiveReport* report = nullptr) {
    o.now = [this] { return clock; };
    return renderProgressive([this](const SampleBatch& b, const auto&) { return (*this)(b); }, o, report);
  }
};

TEST(Progressive, BatchesCoverEverySampleOnceAndAverageByCount) {
  FakeIntegrator fake;
  fake.secondsPerSample = 0.001;
  ProgressiveOptions o;
  o.spp = 100;
  o.targetBatchSeconds = 0.016;
  ProgressiveReport report;
  RadianceImage img = fake.render(o, &report);
  EXPECT_EQ(report.samples, 100u);
  EXPECT_EQ(img.samples, 100u);
  EXPECT_GT(report.batches, 3u);   // 1, 2, 4, 8, 16, 16, ...
  std::uint64_t next = 0;
  for (const SampleBatch& b : fake.batches) {
    EXPECT_EQ(b.firstSample, next);
    next += b.count;
  }
  EXPECT_EQ(next, 100u);
  EXPECT_EQ(fake.batches[0].count, 1u);
  EXPECT_EQ(fake.batches[1].count, 2u);   // at most doubling
  for (float v : img.rgb) EXPECT_NEAR(v, 49.5f, 1e-4f);
  EXPECT_FALSE(report.timeUp);
}

// firstBatch is the batch renderProgressive starts with (the Vulkan backend makes that
// batch's pipeline ahead, while the BVH builds), within spp and maxBatchSamples.
TEST(Progressive, FirstBatchIsTheOneRenderedFirst) {
  struct Case {
    std::uint64_t spp, firstSample;
    std::uint32_t firstBatchSamples, maxBatchSamples;
    double timeLimit;
  };
  for (const Case& c : {Case{100, 0, 1, 1u << 16, 0.0}, Case{5, 7, 8, 1u << 16, 0.0}, Case{64, 0, 64, 16, 0.0},
                        Case{0, 3, 1, 1u << 16, 0.5}, Case{9, 0, 0, 1u << 16, 0.0}}) {
    FakeIntegrator fake;
    fake.secondsPerSample = 0.01;
    ProgressiveOptions o;
    o.spp = c.spp;
    o.firstSample = c.firstSample;
    o.firstBatchSamples = c.firstBatchSamples;
    o.maxBatchSamples = c.maxBatchSamples;
    o.timeLimitSeconds = c.timeLimit;
    fake.render(o);
    ASSERT_FALSE(fake.batches.empty());
    const SampleBatch first = firstBatch(o);
    EXPECT_EQ(first.firstSample, fake.batches[0].firstSample) << c.spp;
    EXPECT_EQ(first.count, fake.batches[0].count) << c.spp;
  }
  ProgressiveOptions o;
  o.spp = 5;
  o.firstBatchSamples = 8;
  EXPECT_EQ(firstBatch(o).count, 5u);   // within spp
  o.spp = 64;
  o.firstBatchSamples = 64;
  o.maxBatchSamples = 16;
  EXPECT_EQ(firstBatch(o).count, 16u);   // within the most a batch takes
}

// 1/8 s per sample and 1 s: batches of 1, then 6 (nine tenths of the 7 that fit), then 1
// (what is left), then no room.
TEST(Progressive, TimeLimitStopsWhenNoSampleFitsAnyMore) {
  FakeIntegrator fake;
  fake.secondsPerSample = 0.125;
  ProgressiveOptions o;
  o.spp = 0;   // the time alone decides
  o.timeLimitSeconds = 1.0;
  ProgressiveReport report;
  RadianceImage img = fake.render(o, &report);
  EXPECT_TRUE(report.timeUp);
  EXPECT_EQ(report.samples, 8u);
  EXPECT_LE(fake.clock, 1.0);
  ASSERT_EQ(fake.batches.size(), 3u);
  EXPECT_EQ(fake.batches[1].count, 6u);
  EXPECT_EQ(fake.batches[2].count, 1u);
  for (float v : img.rgb) EXPECT_FLOAT_EQ(v, 3.5f);
  // With spp as well: whichever comes first.
  FakeIntegrator fast;
  o.spp = 5;
  fast.render(o, &report);
  EXPECT_EQ(report.samples, 5u);
  EXPECT_FALSE(report.timeUp);
}

// The time left is filled in as few batches as fit, each costing a backend its set-up (a
// Vulkan render's buffers, and the pace of its dispatches learnt again): 1/8 s a sample and
// 3/8 s leave room for 2 samples after the first, and the next batch takes both (twice the
// first, where that fits), not nine tenths of them (1) and then a third batch for the last.
TEST(Progressive, TheTimeLeftIsFilledInFewBatches) {
  FakeIntegrator fake;
  fake.secondsPerSample = 0.125;
  ProgressiveOptions o;
  o.spp = 0;
  o.timeLimitSeconds = 0.375;
  ProgressiveReport report;
  fake.render(o, &report);
  EXPECT_EQ(report.samples, 3u);
  ASSERT_EQ(fake.batches.size(), 2u);
  EXPECT_EQ(fake.batches[1].count, 2u);
}

// A time limit shorter than one sample per pixel, the least a render takes: that sample is
// rendered, and the report says how far past the limit it ran (vkrt's output line prints it).
TEST(Progressive, AFirstBatchLongerThanTheLimitIsReported) {
  FakeIntegrator fake;
  fake.secondsPerSample = 5.0;
  ProgressiveOptions o;
  o.spp = 0;
  o.timeLimitSeconds = 1.0;
  ProgressiveReport report;
  fake.render(o, &report);
  EXPECT_EQ(report.samples, 1u);
  EXPECT_TRUE(report.timeUp);
  EXPECT_DOUBLE_EQ(report.firstBatchPastLimit, 4.0);
  // Within the limit: 0, however the later batches end.
  fake = FakeIntegrator{};
  fake.secondsPerSample = 0.125;
  fake.render(o, &report);
  EXPECT_EQ(report.samples, 8u);
  EXPECT_EQ(report.firstBatchPastLimit, 0.0);
}

// A timed render loses at most 5% of the throughput of the same samples in one batch, on a
// fake clock whose batches cost about what lavapipe's do (scenes/gi/box.test): a setup, a
// warm-up in the first, and per sample 0.1 s, more in small batches (lanes with few samples
// each wait for their vector's longest path). Its batches end within 5% of the limit. (From
// 10 s on: the first batch, a sample and the warm-up, is 6% of 5 s by itself.)
TEST(Progressive, ATimedRenderKeepsNineteenTwentiethsOfTheThroughput) {
  auto batchCost = [](std::uint32_t n, bool first) { return (first ? 0.15 : 0.05) + n * 0.1 * (1.0 + 0.5 / n); };
  for (double limit : {10.0, 60.0, 600.0}) {
    FakeIntegrator fake;
    ProgressiveOptions o;
    o.spp = 0;
    o.timeLimitSeconds = limit;
    o.now = [&fake] { return fake.clock; };
    ProgressiveReport report;
    renderProgressive(
        [&](const SampleBatch& b, const auto&) {
          fake.clock += batchCost(b.count, fake.batches.empty());
          return fake(b);
        },
        o, &report);
    const double timed = static_cast<double>(report.samples) / fake.clock;
    const double oneBatch = static_cast<double>(report.samples) /
                            batchCost(static_cast<std::uint32_t>(report.samples), true);
    EXPECT_GE(timed / oneBatch, 0.95) << limit << " s: " << report.samples << " samples in " << report.batches
                                      << " batches";
    EXPECT_LE(fake.clock, 1.05 * limit);
    EXPECT_GE(fake.clock, 0.9 * limit) << "the time was not used";
  }
}

TEST(Progressive, StopEndsAfterTheCurrentBatchWithoutAddingIt) {
  FakeIntegrator fake;
  ProgressiveOptions o;
  o.spp = 50;
  int calls = 0;
  o.stop = [&calls] { return ++calls >= 2; };
  ProgressiveReport report;
  renderProgressive([&fake](const SampleBatch& b, const auto&) { return fake(b); }, o, &report);
  EXPECT_TRUE(report.stopped);
  EXPECT_EQ(report.samples, 1u);
}

// The Whitted model is deterministic: any batching of its samples gives its one image, bit
// for bit, on both backends.
TEST(Progressive, BatchesOfADeterministicRenderGiveItsImageOnTheCpu) {
  SceneDesc scene = parseScene(kWhittedScene, "whitted.test");
  Bvh bvh = buildBvh(scene);
  RadianceImage once = renderReference(scene, bvh, CpuOptions{}, nullptr);
  ProgressiveOptions o;
  o.spp = 7;
  o.targetBatchSeconds = 0;   // batches of 1
  ProgressiveReport report;
  RadianceImage batched = renderProgressive(
      [&](const SampleBatch& b, const auto&) {
        CpuOptions c;
        c.firstSample = b.firstSample;
        c.sampleCount = b.count;
        return renderReference(scene, bvh, c, nullptr);
      },
      o, &report);
  EXPECT_EQ(report.batches, 7u);
  EXPECT_EQ(batched.samples, 7u);
  EXPECT_TRUE(sameBits(batched.rgb, once.rgb));
}

TEST(Progressive, BatchesOfADeterministicRenderGiveItsImageOnVulkan) {
  VKRT_REQUIRE_GPU(ctx);
  SceneDesc scene = parseScene(kWhittedScene, "whitted.test");
  GpuScene flat = flatten(scene);
  int before = ctx->validationMessages();
  RadianceImage once = renderVulkan(*ctx, flat, VulkanOptions{}, nullptr, nullptr);
  ProgressiveOptions o;
  o.spp = 3;
  RadianceImage batched = renderProgressive(
      [&](const SampleBatch& b, const auto&) {
        VulkanOptions v;
        v.firstSample = b.firstSample;
        v.sampleCount = b.count;
        return renderVulkan(*ctx, flat, v, nullptr, nullptr);
      },
      o);
  EXPECT_EQ(batched.samples, 3u);
  EXPECT_TRUE(sameBits(batched.rgb, once.rgb));
  EXPECT_EQ(ctx->validationMessages(), before);
  // The float image, encoded, is the bytes the CPU reference gives (doc/scene-format.md's tolerance: the
  // backends round differently at a few edge pixels).
  Bvh bvh = buildBvh(scene);
  EXPECT_TRUE(imagesClose("whitted-float", encodeImage(once, 1.0),
                          encodeImage(renderReference(scene, bvh, CpuOptions{}, nullptr), 1.0), 1, 2));
}

// ---- merging sample batches ---------------------------------------------------------------------

TEST(MergeBatches, BatchesOfADeterministicRenderAverageToItsImage) {
  std::string dir = freshDir("float/merge-same");
  RadianceImage img = ramp(6, 4);
  std::vector<std::string> paths = {writeBatch(dir + "/a.pfm", img, {{{1, 0, 2}}, 1.0}),
                                    writeBatch(dir + "/b.pfm", img, {{{2, 0, 5}}, 1.0}),
                                    writeBatch(dir + "/c.pfm", img, {{{3, 0, 1}}, 1.0})};
  EXPECT_TRUE(areSampleBatches(paths));
  MergeReport report;
  RadianceImage mean = mergeSampleBatches(paths, &report);
  EXPECT_TRUE(sameBits(mean.rgb, img.rgb));
  EXPECT_EQ(report.samples.total(), 8u);
  EXPECT_EQ(report.tiles, 3);
  ASSERT_EQ(mean.text.size(), 1u);
  EXPECT_EQ(mean.text[0].second, "8 gamma 1 seeds 1:0+2 2:0+5 3:0+1");
}

// The merge is the same bits, and the same record, whatever the order the files are given in
// (a shell's glob puts batch-10 before batch-2): the batches are taken by their first samples.
TEST(MergeBatches, TheOrderOfTheFilesChangesNoBit) {
  std::string dir = freshDir("float/merge-order");
  std::vector<std::string> paths;
  for (std::uint32_t seed : {1u, 2u, 3u, 10u}) {
    RadianceImage img(16, 16);
    for (std::size_t i = 0; i < img.rgb.size(); ++i)   // values whose running mean rounds by order
      img.rgb[i] = 0.1f * static_cast<float>(seed) + 1e-3f * static_cast<float>((i * 7919u + seed * 104729u) % 1000u);
    paths.push_back(writeBatch(dir + "/batch-" + std::to_string(seed) + ".pfm", img, {{{seed, 0, 1 + seed % 3}}, 1.0}));
  }
  const RadianceImage inOrder = mergeSampleBatches(paths);
  int orders = 0;
  std::vector<std::string> shuffled = paths;
  std::sort(shuffled.begin(), shuffled.end());   // batch-1, batch-10, batch-2, batch-3: the glob's order
  do {
    RadianceImage mean = mergeSampleBatches(shuffled);
    EXPECT_TRUE(sameBits(mean.rgb, inOrder.rgb)) << shuffled[0] << " " << shuffled[1] << " " << shuffled[2];
    EXPECT_EQ(mean.text, inOrder.text);
    ++orders;
  } while (std::next_permutation(shuffled.begin(), shuffled.end()));
  EXPECT_EQ(orders, 24);
  ASSERT_EQ(inOrder.text.size(), 1u);
  EXPECT_EQ(inOrder.text[0].second, "8 gamma 1 seeds 1:0+2 2:0+3 3:0+1 10:0+2");
}

TEST(MergeBatches, WeightsAreTheSampleCounts) {
  std::string dir = freshDir("float/merge-weights");
  RadianceImage crop1 = filled(3, 2, 1.0f, 1), crop3 = filled(3, 2, 2.0f, 1);
  crop1.text.emplace_back("vkrt-crop", "1,1,4,3 of 8 8");
  crop3.text.emplace_back("vkrt-crop", "1,1,4,3 of 8 8");
  std::vector<std::string> paths = {writeBatch(dir + "/one.pfm", crop1, {{{1, 0, 1}}, 2.0}),
                                    writeBatch(dir + "/three.pfm", crop3, {{{2, 0, 3}}, 2.0})};
  ASSERT_TRUE(areSampleBatches(paths));
  MergeReport report;
  RadianceImage mean = mergeSampleBatches(paths, &report);
  for (float v : mean.rgb) EXPECT_EQ(v, 1.75f);
  EXPECT_EQ(mean.samples, 4u);
  EXPECT_EQ(report.samples.gamma, 2.0);
  ASSERT_EQ(mean.text.size(), 2u);
  EXPECT_EQ(mean.text[0], (std::pair<std::string, std::string>("vkrt-crop", "1,1,4,3 of 8 8")));
}

// Batches of different places, given together, are read as tiles; the refusal says what they
// are and what to do: a whole image among crops, and batches of two crops at once.
TEST(MergeBatches, BatchesOfDifferentPlacesSayWhatToDo) {
  std::string dir = freshDir("float/merge-places");
  auto crop = [&](const std::string& name, const char* rect, std::uint32_t seed) {
    RadianceImage img = filled(4, 4, 0.5f, 1);
    img.text.emplace_back("vkrt-crop", std::string(rect) + " of 8 4");
    return writeBatch(dir + "/" + name, img, {{{seed, 0, 1}}, 1.0});
  };
  const std::string whole = writeBatch(dir + "/whole.pfm", filled(8, 4, 0.5f, 1), {{{9, 0, 1}}, 1.0});
  const std::string a1 = crop("a1.pfm", "0,0,4,4", 1), a2 = crop("a2.pfm", "0,0,4,4", 2);
  const std::string b1 = crop("b1.pfm", "4,0,8,4", 1), b2 = crop("b2.pfm", "4,0,8,4", 2);
  auto refusal = [&](const std::vector<std::string>& paths) {
    EXPECT_FALSE(areSampleBatches(paths));
    try {
      writeMergedCrops(paths, false, dir + "/out.pfm");
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(refusal({whole, a2}).find("it is a whole image of a path-traced render: sample batches merge with batches "
                                      "of the same place"), std::string::npos);
  EXPECT_NE(refusal({a1, a2, b1, b2}).find("they are sample batches of one crop: merge each crop's batches first"),
            std::string::npos);
  EXPECT_FALSE(fileExists(dir + "/out.pfm"));
  EXPECT_EQ(refusal({a1, b1}), "no error");   // the two crops of one render's samples: tiles
  EXPECT_TRUE(fileExists(dir + "/out.pfm"));
}

// Each refusal names the files and the reason.
TEST(MergeBatches, MismatchedBatchesAreRefusedWithClearMessages) {
  std::string dir = freshDir("float/merge-refused");
  RadianceImage img = ramp(4, 4);
  std::string a = writeBatch(dir + "/a.pfm", img, {{{1, 0, 4}}, 1.0});
  auto refused = [](const std::vector<std::string>& paths, const std::string& message) {
    try {
      mergeSampleBatches(paths);
      ADD_FAILURE() << "not refused: " << message;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  refused({a, writeBatch(dir + "/same.pfm", img, {{{1, 2, 4}}, 1.0})},
          "batches '" + a + "' and '" + dir + "/same.pfm' hold the same samples (seed 1, sample 2): render each "
          "batch with its own --seed");
  refused({a, writeBatch(dir + "/small.pfm", ramp(4, 3), {{{2, 0, 4}}, 1.0})},
          "batches of different sizes: '" + a + "' is 4x4, '" + dir + "/small.pfm' 4x3");
  refused({a, writeBatch(dir + "/gamma.pfm", img, {{{2, 0, 4}}, 2.2})},
          "batches of different gammas: '" + a + "' has gamma 1, '" + dir + "/gamma.pfm' gamma 2.2");
  refused({a, writeBatch(dir + "/strata.pfm", img, {{{2, 0, 4}}, 1.0, true})},
          "batches of different samplers: '" + a + "' holds independent samples, '" + dir +
              "/strata.pfm' stratified ones (--sampler)");
  RadianceImage cropped = img;
  cropped.text.emplace_back("vkrt-crop", "0,0,4,4 of 8 8");
  refused({a, writeBatch(dir + "/crop.pfm", cropped, {{{2, 0, 4}}, 1.0})},
          "batches of different places: '" + a + "' is the whole image, '" + dir + "/crop.pfm' the crop 0,0,4,4 of 8 8");
  Image png = encodeImage(img, 1.0);
  png.text.emplace_back(kSamplesKeyword, "4 gamma 1 seeds 2:0+4");
  writeImageAtomic(png, dir + "/b.png");
  refused({a, dir + "/b.png"}, "batch '" + dir + "/b.png' is not a PFM or EXR file: sample batches are averaged from linear float images");
  writePfmAtomic(img, dir + "/plain.pfm");
  refused({a, dir + "/plain.pfm"}, "batch '" + dir + "/plain.pfm' has no vkrt-samples record");
  RadianceImage bad = img;
  bad.text.emplace_back(kSamplesKeyword, "5 gamma 1 seeds 2:0+4");
  writePfmAtomic(bad, dir + "/bad.pfm");
  refused({a, dir + "/bad.pfm"}, "malformed vkrt-samples record '5 gamma 1 seeds 2:0+4'");
  // Crops (different places, or no samples record) are not batches: merge assembles them.
  EXPECT_FALSE(areSampleBatches({a, dir + "/crop.pfm"}));
  EXPECT_FALSE(areSampleBatches({a, dir + "/plain.pfm"}));
}
