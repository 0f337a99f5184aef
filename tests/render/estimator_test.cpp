// --estimator best (render/render.h, RenderRequest::estimator): on a `pathtracer` scene it
// renders with BRDF sampling and MIS whatever the scene's `importancesampling` and
// `nexteventestimation` say: the same image in the limit (doc/path-tracing.md, "Estimators"),
// with less noise at equal samples; other integrators ignore it with a warning.
#include <cmath>

#include <gtest/gtest.h>

#include "util/errors.h"
#include "render/render.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// The project's Cornell box (scenes/gi/box.test: a glossy GGX sphere, a Phong block, one
// small light) with the estimator the course's first path-tracing scenes prescribe: light
// samples only, directions uniform over the hemisphere.
std::string boxWithHemisphereSampling(const std::string& dir) {
  std::string text = readFile(sourcePath("scenes/gi/box.test"));
  auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("nexteventestimation mis", "nexteventestimation on");
  replace("importancesampling brdf", "importancesampling hemisphere");
  replace("\noutput box.png", "");
  writeFile(dir + "/box.test", text);
  return dir + "/box.test";
}

RadianceImage renderBox(const std::string& scene, std::uint64_t spp, std::uint32_t seed, Estimator estimator,
                        RenderReport* reportOut = nullptr) {
  RenderRequest request;
  request.scenePath = scene;
  request.backend = Backend::Cpu;
  request.width = request.height = 64;
  request.crop = PixelRect{20, 20, 44, 44};
  request.spp = spp;
  request.seed = seed;
  request.estimator = estimator;
  ProgressBar quiet(false);
  RenderReport report;
  RadianceImage image = renderSceneInMemory(request, quiet, report, false);
  if (reportOut) *reportOut = report;
  return image;
}


}  // namespace

// The report names the estimator rendered: the scene's, or the one --estimator best puts in
// its place.
TEST(EstimatorBest, ReportsWhatItRenders) {
  const std::string scene = boxWithHemisphereSampling(freshDir("estimator/report"));
  RenderReport report;
  renderBox(scene, 1, 1, Estimator::Scene, &report);
  EXPECT_EQ(report.estimator,
            "nexteventestimation on, importancesampling hemisphere, russianroulette on, independent samples");
  renderBox(scene, 1, 1, Estimator::Best, &report);
  EXPECT_EQ(report.estimator,
            "nexteventestimation mis, importancesampling brdf, russianroulette on, independent samples "
            "(--estimator best)");
}

// The box at 64x64, its 24x24 centre, 16 samples, 6 seeds each way, against 1024 samples
// of the scene's own estimator (another seed): --estimator best's mean squared error is below
// 0.6 of the scene's estimator's (measured: 0.43), and both means agree with the reference's
// within 4 standard errors of the scene's estimator's renders (no bias).
TEST(EstimatorBest, SameImageLessNoise) {
  const std::string scene = boxWithHemisphereSampling(freshDir("estimator/noise"));
  const RadianceImage reference = renderBox(scene, 1024, 1000, Estimator::Scene);
  const EstimatorComparison c = compareEstimators(reference, 6, [&](int best, std::uint32_t seed) {
    return renderBox(scene, 16, seed, best ? Estimator::Best : Estimator::Scene);
  });
  expectLessNoiseSameMean(c, reference, 0.6, "scene's estimator (16 spp)", "best");
}

// Lobes with nothing to sample: a GGX floor of roughness 0 (only its diffuse part reflects)
// and a Phong wall of shininess 0 (its lobe flat over the hemisphere), with specular colour,
// under a quad light. BRDF sampling must not draw their "lobe" (a mirror direction that D
// gives no density, or only the half of the hemisphere around r): --estimator best renders the
// same mean radiance as the scene's cosine sampling, within 4 standard errors of the
// difference, 4 seeds each at 48x48 and 32 samples (before the rule: +18% and -0.7%, 15
// standard errors), on each backend.
static void expectFlatAndSpikeLobesKeepTheImage(Backend backend) {
  const std::string dir = freshDir(backend == Backend::Cpu ? "estimator/lobes-cpu" : "estimator/lobes-vulkan");
  for (const char* material : {"brdf ggx\nroughness 0\ndiffuse 0.3 0.3 0.3\nspecular 0.5 0.5 0.5\n",
                               "brdf phong\nshininess 0\ndiffuse 0.3 0.3 0.3\nspecular 0.5 0.5 0.5\n"}) {
    writeFile(dir + "/lobe.test",
              std::string("size 48 48\ncamera 0 -3 2 0 0 0 0 0 1 50\nintegrator pathtracer\nspp 32\n"
                          "nexteventestimation on\nimportancesampling cosine\nmaxdepth 3\n"
                          "quadLight -0.5 -0.5 2.5 1 0 0 0 1 0 6 6 6\n") +
                  material +
                  "vertex -3 -3 0\nvertex 3 -3 0\nvertex 3 3 0\nvertex -3 3 0\ntri 0 1 2\ntri 0 2 3\n"
                  "vertex -3 2 0\nvertex 3 2 0\nvertex 3 2 3\nvertex -3 2 3\ntri 4 5 6\ntri 4 6 7\n");
    double mean[2] = {0, 0}, spread[2] = {0, 0};
    const int seeds = 4;
    for (int best = 0; best < 2; ++best) {
      std::vector<double> means;
      for (std::uint32_t seed = 1; seed <= seeds; ++seed) {
        RenderRequest request;
        request.scenePath = dir + "/lobe.test";
        request.backend = backend;
        request.seed = seed + 10 * best;
        request.estimator = best ? Estimator::Best : Estimator::Scene;
        ProgressBar quiet(false);
        RenderReport report;
        means.push_back(imageMean(renderSceneInMemory(request, quiet, report, false)));
      }
      for (double m : means) mean[best] += m / seeds;
      for (double m : means) spread[best] += (m - mean[best]) * (m - mean[best]) / (seeds - 1) / seeds;
    }
    const double error = std::sqrt(spread[0] + spread[1]);
    std::printf("[ stats    ] mean radiance: scene's estimator %.5g, best %.5g (standard error of the difference %.2g)\n",
                mean[0], mean[1], error);
    EXPECT_NEAR(mean[1], mean[0], 4 * error + 1e-3 * mean[0]) << material;
  }
}

TEST(EstimatorBest, FlatAndSpikeLobesKeepTheImageCpu) { expectFlatAndSpikeLobesKeepTheImage(Backend::Cpu); }

TEST(EstimatorBest, FlatAndSpikeLobesKeepTheImageVulkan) {
  VKRT_REQUIRE_GPU(ctx);
  expectFlatAndSpikeLobesKeepTheImage(Backend::Vulkan);
}

// The Whitted model and the direct integrators have no estimator to choose: a warning, and
// under --strict a refusal.
TEST(EstimatorBest, OtherIntegratorsWarn) {
  const std::string dir = freshDir("estimator/other");
  writeFile(dir + "/direct.test",
            "size 8 8\ncamera 0 -3 1 0 0 0 0 0 1 45\nintegrator direct\nquadLight -0.5 -0.5 2 1 0 0 0 1 0 4 4 4\n"
            "diffuse 0.5 0.5 0.5\nvertex -3 -3 0\nvertex 3 -3 0\nvertex 3 3 0\ntri 0 1 2\n");
  RenderRequest request;
  request.scenePath = dir + "/direct.test";
  request.backend = Backend::Cpu;
  request.estimator = Estimator::Best;
  std::vector<std::string> warnings;
  request.onOptionWarning = [&](const std::string& w) { warnings.push_back(w); };
  ProgressBar quiet(false);
  RenderReport report;
  renderSceneInMemory(request, quiet, report, false);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("--estimator best does not apply to " + request.scenePath + ": its integrator is direct"),
            std::string::npos)
      << warnings[0];
  EXPECT_EQ(report.estimator, "");
  request.strict = true;
  EXPECT_THROW(renderSceneInMemory(request, quiet, report, false), UsageError);
}
