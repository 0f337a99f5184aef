// Helpers shared by the tests: where the course data is, skipping (or failing in CI), rendering
// a scene from text, and image comparison that saves evidence on failure.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image.h"
#include "image/radiance_image.h"
#include "gpu/context.h"
#include "gpu/vulkan_renderer.h"
#include "render/render.h"
#include "scene/scene_desc.h"

namespace vkrt::test {

// True when the environment says CI=true: missing data or devices are failures there.
bool inCi();

// The course data folder (../shared/cse167 beside the source tree, or $VKRT_CSE167_DIR), if present.
std::optional<std::string> cse167Dir();
// Why a test that needs the course's data skips without it (the same words for every such test,
// so that ctest's summary gives each reason once).
inline constexpr const char* kNoCse167Data =
    "needs the CSE167 scenes and reference images: none at ../shared/cse167 (set VKRT_CSE167_DIR to where they are)";
inline constexpr const char* kNoCse168Data =
    "needs the CSE168 scenes: none at ../shared/cse168 (set VKRT_CSE168_DIR to where they are)";
// The path-tracing course data folder (../shared/cse168 beside the source tree, or
// $VKRT_CSE168_DIR), if present.
std::optional<std::string> cse168Dir();

// The project's scenes (scenes/*.test), by stem, sorted.
std::vector<std::string> projectSceneNames();

// A test-name-safe version of a scene name ('-' becomes '_').
std::string testName(std::string name);

// The source tree and the vkrt binary: where the build left them, or $VKRT_TEST_SOURCE_DIR
// and $VKRT_TEST_BINARY when the built tests run in another place (bench/device-check
// --prebuilt, on a machine that did not build them).
const std::string& sourceDir();
const std::string& vkrtBinary();

// Path of a file in the project's source tree.
std::string sourcePath(const std::string& relative);

// A fresh, empty directory for one test's files, under the build's test-output folder.
std::string freshDir(const std::string& name);
// The absolute path of `name` under the test-output folder (nothing created or removed).
std::string outputPath(const std::string& name);

// Reads a whole file.
std::string readFile(const std::string& path);
void writeFile(const std::string& path, const std::string& text);
bool fileExists(const std::string& path);
// How many entries a directory holds (to see that nothing was left or written beside a file).
std::size_t fileCount(const std::string& dir);

// Parses scene text and renders it with the CPU reference. Both renderScene and renderGpu
// fail the test when a pixel's colour was NaN or infinite.
Image renderText(const std::string& sceneText, const std::string& name = "test.test");
Image renderScene(const SceneDesc& scene);

// A w x h image of distinct, deterministic pixel values (for image I/O tests).
Image gradient(int w, int h);

// The scene of `body` after a 64x48 `size` and a camera at (0, 0, 5) looking at the origin,
// as file "t.test"; the strict one makes every warning an error (--strict), for scenes that
// must give none.
SceneDesc parseBody(const std::string& body);
SceneDesc parseBodyStrict(const std::string& body);

// Each component of a within eps of b's.
void expectNear(const dvec3& a, const dvec3& b, double eps = 1e-12);

// Whether two float arrays, or two linear images of the same size, hold the same bits.
bool sameBits(const std::vector<float>& a, const std::vector<float>& b);
bool sameBits(const RadianceImage& a, const RadianceImage& b);

// Whether two path-traced images of one scene by the general and the specialised shader
// variant agree. Both compute the same arithmetic, but a GPU's compiler may fuse multiplies
// and adds differently in the two (an H200's did, in path-traced scenes: up to 4e-6
// relative; its Whitted images were the same bits). Bit for bit on a CPU device (lavapipe
// fuses the same way in both), within 1e-5 of each value (relative; absolute below 1)
// elsewhere.
::testing::AssertionResult pathVariantsAgree(const Context& context, const RadianceImage& a, const RadianceImage& b);

// Compares two images: passes when at most `maxPixelsOver` pixels differ by more than
// `stepTolerance` 8-bit steps in some channel. On failure writes actual.png, expected.png and
// an amplified diff.png in outputPath("failures/" + name) and names them in the message.
::testing::AssertionResult imagesClose(const std::string& name, const Image& actual, const Image& expected,
                                       int stepTolerance, long long maxPixelsOver);

// A Vulkan context with the validation layer on, shared by the tests of this process; null
// (after skipping the test, or failing it in CI) when no Vulkan device can be had.
Context* gpuContextOrSkip();
// Destroys the shared context. Called at the end of main(): left to static destruction, it
// would run after the validation layer's own globals are gone (the layer is loaded later
// than the static is registered), and the layer's allocations would leak.
void releaseGpuContext();

// The scene file at `scenePath` rendered in memory as the command line would (no progress
// bar, the validation layer on), with the request as `adjust` leaves it.
RadianceImage renderFileQuietly(const std::string& scenePath, const std::function<void(RenderRequest&)>& adjust);

// Renders with the Vulkan backend; `stepBudget` 0 is the default.
Image renderGpu(const SceneDesc& scene, std::uint32_t stepBudget = 0, VulkanTimings* timings = nullptr,
                SceneReads reads = SceneReads::Auto);

// Two parallel mirrors ten units apart and a 1x1 camera between them looking straight at one:
// the ray meets the mirrors maxDepth + 1 times (maxdepth reflections), and nothing else.
// Both mirrors have emission e and specular s, so a channel's radiance is the geometric series
//   e (1 + s + s^2 + ... + s^D) = e (1 - s^(D+1)) / (1 - s)   (e (D + 1) when s = 1).
// Red has s = 1 and e = 2^-21: every partial sum k 2^-21 (k < 2^24) is exact in float32 too,
// and the total counts the segments. Green has s = 0.5, e = 0.25: the series converges to
// 0.5. Blue has s = 1 - 2^-20, e = 2^-21: over a million bounces the throughput s^k decays
// to about 0.385, and the float32 loop accumulates an error of about 1e-4 (0.02 of a step).
struct MirrorChannel {
  double emission, specular;
};
inline constexpr MirrorChannel kParallelMirrorChannels[3] = {
    {0x1p-21, 1.0}, {0.25, 0.5}, {0x1p-21, 1.0 - 0x1p-20}};
std::string parallelMirrorsScene(int maxDepth);
// The closed form of the series above for one channel.
double parallelMirrorsRadiance(const MirrorChannel& channel, int maxDepth);

// The mean of an image's values (every channel of every pixel).
double imageMean(const RadianceImage& image);

// Two ways of rendering one image (way 0 and way 1), `seeds` renders each, seeds 1 to
// `seeds`: each way's mean squared error against `reference` and its mean value, averaged over
// the seeds, and the standard error of way 0's mean.
struct EstimatorComparison {
  double mse[2] = {0, 0};
  double mean[2] = {0, 0};
  double standardError = 0;   // of mean[0]
};
EstimatorComparison compareEstimators(const RadianceImage& reference, int seeds,
                                      const std::function<RadianceImage(int way, std::uint32_t seed)>& render);

// Prints the comparison (`way0`, `way1`: the two ways' names) and expects way 1's mean squared
// error below `ratio` of way 0's, and both ways' means within 4 standard errors (and 0.1%) of
// the reference's: less noise, no bias.
void expectLessNoiseSameMean(const EstimatorComparison& c, const RadianceImage& reference, double ratio,
                             const char* way0, const char* way1);

// Result of running the vkrt binary.
struct RunResult {
  int exitCode = -1;
  std::string output;   // stdout and stderr together
};
// `env` is prepended to the command line (VAR=value ...).
RunResult runVkrt(const std::string& args, const std::string& env = "");
// Runs a shell command line (sh -c), stdout and stderr together.
RunResult runCommand(const std::string& commandLine);

// vkrt started in the background (stdout and stderr to `logPath`), for tests that signal it
// or measure its peak memory.
struct Spawned {
  int pid = -1;
  std::string logPath;
};
Spawned spawnVkrt(const std::vector<std::string>& args, const std::string& logPath,
                  const std::vector<std::string>& env = {});
struct Finished {
  int exitCode = -1;   // 128 + signal when killed by one
  std::string output;
};
struct MeasuredRun : Finished {
  long long peakRssKb = -1;   // vkrt's peak resident set (KiB)
};
Finished waitVkrt(const Spawned& process);
// Runs vkrt to its end and measures its peak resident memory. The kernel counts into a
// program's peak the resident size of the process that forked it (fork copies the parent's
// page tables, exec keeps their high-water mark), and this test binary may hold a GPU
// driver's 150 MB. So vkrt is started by a fresh, small copy of the test binary
// (measurePeakMemoryMain), whose wait4 reads vkrt's own peak.
MeasuredRun runVkrtMeasuringMemory(const std::vector<std::string>& args, const std::string& logPath,
                                   const std::vector<std::string>& env = {});
// The test binary's entry for that copy (`--measure-peak-memory FILE PROGRAM ARGS...`):
// runs PROGRAM, writes its peak resident KiB to FILE and returns its exit status; -1 when
// argv is not that.
int measurePeakMemoryMain(int argc, char** argv);
// waitVkrt, but a process still running after `seconds` is killed (SIGKILL: exit 137), so
// that a vkrt that does not stop fails the test instead of hanging it.
Finished waitVkrtWithin(const Spawned& process, double seconds);

}  // namespace vkrt::test

// Gets the shared Vulkan context into `ctx`, or returns from the test (skipped, or failed in CI).
#define VKRT_REQUIRE_GPU(ctx)                        \
  ::vkrt::Context* ctx = ::vkrt::test::gpuContextOrSkip(); \
  if (!ctx) return

// Skips the current test (saying why), except in CI, where the same condition fails it.
#define VKRT_SKIP_UNLESS_CI(why)                                   \
  do {                                                             \
    if (::vkrt::test::inCi()) FAIL() << "required in CI: " << why; \
    GTEST_SKIP() << why;                                           \
  } while (0)
