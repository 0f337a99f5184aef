// A render under limits (render/render_limits.h): the size, samples and depth refused before
// anything is built, each naming its limit; a render past its time stopped within moments of
// it on both backends, with nothing returned; and a render within its limits the same image
// as one without any.
#include <chrono>

#include <gtest/gtest.h>

#include "render/render.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const char* kBox =
    "camera 0 -3 1 0 0 0.5 0 0 1 45\nquadLight -0.5 -0.5 2 1 0 0 0 1 0 4 4 4\ndiffuse 0.7 0.5 0.3\n"
    "vertex -3 -3 0\nvertex 3 -3 0\nvertex 3 3 0\nvertex -3 3 0\ntri 0 1 2\ntri 0 2 3\n";

// What LimitExceeded says of the scene `body` (written to a file) under `limits`, and which
// limit; "" when it renders.
struct Refusal {
  std::string message;
  LimitExceeded::Which which = LimitExceeded::Which::Seconds;
  double seconds = 0;   // from the call to the exception
};

Refusal renderUnder(const std::string& name, const std::string& body, const RenderLimits& limits,
                    Backend backend = Backend::Cpu) {
  const std::string path = freshDir("render-limits/" + name) + "/s.test";
  writeFile(path, body);
  RenderRequest request;
  request.scenePath = path;
  request.backend = backend;
  request.validation = true;
  request.limits = limits;
  ProgressBar progress(false);
  RenderReport report;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    renderSceneInMemory(request, progress, report, false);
  } catch (const LimitExceeded& e) {
    return {e.what(), e.which(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
  }
  return {};
}

}  // namespace

TEST(RenderLimits, SizeSamplesAndDepthAreRefusedBeforeTheRender) {
  RenderLimits pixels;
  pixels.pixels = 1200;
  Refusal r = renderUnder("pixels", "size 400 300\n" + std::string(kBox), pixels);
  EXPECT_EQ(r.which, LimitExceeded::Which::Pixels);
  EXPECT_NE(r.message.find("s.test: a 400x300 image (120000 pixels) is past the limit of 1200 pixels"), std::string::npos)
      << r.message;
  EXPECT_EQ(renderUnder("pixels-within", "size 40 30\n" + std::string(kBox), pixels).message, "");

  RenderLimits spp;
  spp.spp = 4096;
  r = renderUnder("spp", "size 8 6\nintegrator pathtracer\nspp 100000000\n" + std::string(kBox), spp);
  EXPECT_EQ(r.which, LimitExceeded::Which::Spp);
  EXPECT_NE(r.message.find("s.test: 100000000 samples per pixel, past the limit of 4096"), std::string::npos) << r.message;
  EXPECT_EQ(renderUnder("spp-within", "size 8 6\nintegrator pathtracer\nspp 4096\n" + std::string(kBox), spp).message, "");
  // The Whitted model's one sample is within any limit of samples.
  EXPECT_EQ(renderUnder("spp-whitted", "size 8 6\n" + std::string(kBox), spp).message, "");

  RenderLimits depth;
  depth.depth = 100;
  r = renderUnder("depth", "size 8 6\nmaxdepth 1000\n" + std::string(kBox), depth);
  EXPECT_EQ(r.which, LimitExceeded::Which::Depth);
  EXPECT_NE(r.message.find("s.test: maxdepth 1000 is past the limit of 100"), std::string::npos) << r.message;
  r = renderUnder("depth-unlimited", "size 8 6\nintegrator pathtracer\nmaxdepth -1\n" + std::string(kBox), depth);
  EXPECT_EQ(r.which, LimitExceeded::Which::Depth);
  EXPECT_NE(r.message.find("'maxdepth -1' with 'russianroulette off' has no depth limit"), std::string::npos) << r.message;
  EXPECT_EQ(renderUnder("depth-roulette",
                        "size 8 6\nintegrator pathtracer\nspp 4\nmaxdepth -1\nrussianroulette on\n" + std::string(kBox),
                        depth).message, "");
}

// A path-traced scene of a billion samples a pixel stops at a time limit of half a second, on
// the CPU reference and on Vulkan: well within five seconds of starting (a dispatch, a tile
// and the shader's compile are each far shorter; without the limit it would run for hours).
TEST(RenderLimits, ARenderPastItsTimeStopsSoonAfter) {
  const std::string runaway = "size 40 30\nintegrator pathtracer\nspp 1000000000\nnexteventestimation on\n" + std::string(kBox);
  RenderLimits limits;
  limits.seconds = 0.5;
  for (Backend backend : {Backend::Cpu, Backend::Vulkan}) {
    if (backend == Backend::Vulkan && !gpuContextOrSkip()) return;
    const bool cpu = backend == Backend::Cpu;
    Refusal r = renderUnder(cpu ? "time-cpu" : "time-vulkan", runaway, limits, backend);
    EXPECT_EQ(r.which, LimitExceeded::Which::Seconds) << r.message;
    EXPECT_NE(r.message.find("s.test: not rendered within the time limit of 0.5 s"), std::string::npos) << r.message;
    EXPECT_GE(r.seconds, 0.5);
    EXPECT_LT(r.seconds, 5.0) << (cpu ? "cpu" : "vulkan");
  }
  // A Whitted scene is stopped too, between its tiles: two facing mirrors seen down a narrow
  // view, each pixel's ray bouncing some ten thousand times before it drifts off their edge.
  std::string mirrors = parallelMirrorsScene(1000000);
  mirrors.replace(mirrors.find("size 1 1"), 8, "size 400 300");
  mirrors.replace(mirrors.find("0 1 0 30"), 8, "0 1 0 0.01");
  Refusal r = renderUnder("time-whitted", mirrors, limits);
  EXPECT_EQ(r.which, LimitExceeded::Which::Seconds) << r.message;
  EXPECT_LT(r.seconds, 5.0);
}

// Limits that a render stays within change nothing: the same bits as without them.
TEST(RenderLimits, ARenderWithinItsLimitsIsTheSameImage) {
  const std::string path = freshDir("render-limits/same") + "/s.test";
  writeFile(path, "size 16 12\nintegrator pathtracer\nspp 8\nnexteventestimation on\n" + std::string(kBox));
  RadianceImage free = renderFileQuietly(path, [](RenderRequest& r) { r.backend = Backend::Cpu; });
  RadianceImage bounded = renderFileQuietly(path, [](RenderRequest& r) {
    r.backend = Backend::Cpu;
    r.limits = RenderLimits{600, 8, 192, 5};
  });
  EXPECT_TRUE(sameBits(free, bounded));
}
