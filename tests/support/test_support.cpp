// Test helpers.
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <chrono>
#include <csignal>
#include <memory>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cpu/reference.h"
#include "gpu/device_error.h"
#include "compare/image_diff.h"
#include "image/encode.h"
#include "image/png.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"
#include "render/progress.h"
#include "scene/flatten.h"
#include "scene/parse.h"

namespace fs = std::filesystem;

namespace vkrt::test {

namespace {

std::string fromEnvironment(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}

}  // namespace

const std::string& sourceDir() {
  static const std::string dir = fromEnvironment("VKRT_TEST_SOURCE_DIR", VKRT_SOURCE_DIR);
  return dir;
}

const std::string& vkrtBinary() {
  static const std::string binary = fromEnvironment("VKRT_TEST_BINARY", VKRT_BINARY);
  return binary;
}

bool inCi() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

std::optional<std::string> cse167Dir() {
  const char* env = std::getenv("VKRT_CSE167_DIR");
  fs::path dir = env ? fs::path(env) : fs::path(sourceDir()) / ".." / "shared" / "cse167";
  if (fs::is_directory(dir / "scenes")) return fs::canonical(dir).string();
  return std::nullopt;
}

std::optional<std::string> cse168Dir() {
  const char* env = std::getenv("VKRT_CSE168_DIR");
  fs::path dir = env ? fs::path(env) : fs::path(sourceDir()) / ".." / "shared" / "cse168";
  if (fs::is_directory(dir / "scenes")) return fs::canonical(dir).string();
  return std::nullopt;
}

std::vector<std::string> projectSceneNames() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(sourceDir()) / "scenes"))
    if (e.path().extension() == ".test") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string testName(std::string name) {
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

std::string sourcePath(const std::string& relative) { return (fs::path(sourceDir()) / relative).string(); }

std::string outputPath(const std::string& name) {
  const char* env = std::getenv("VKRT_TEST_OUTPUT");
  return fs::absolute(fs::path(env ? env : "test-output") / name).string();
}

std::string freshDir(const std::string& name) {
  fs::path dir = outputPath(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

bool fileExists(const std::string& path) { return fs::exists(path); }

// Every image the tests render is scanned for colours that were NaN or infinite (the
// renderers count them: RayCounts::nonFinite); tests that want them call the renderers directly.
Image renderScene(const SceneDesc& scene) {
  Bvh bvh = buildBvh(scene);
  RayCounts rays;
  Image image = encodeImage(renderReference(scene, bvh, CpuOptions{}, &rays), 1.0);
  EXPECT_EQ(rays.nonFinite, 0u) << "the CPU reference produced NaN or infinite colours";
  return image;
}

Image renderText(const std::string& sceneText, const std::string& name) {
  return renderScene(parseScene(sceneText, name));
}

::testing::AssertionResult imagesClose(const std::string& name, const Image& actual, const Image& expected,
                                       int stepTolerance, long long maxPixelsOver) {
  if (actual.width != expected.width || actual.height != expected.height)
    return ::testing::AssertionFailure() << name << ": sizes differ: " << actual.width << "x" << actual.height
                                         << " vs " << expected.width << "x" << expected.height;
  ImageDiff d = compare(actual, expected);
  long long over = d.countOver(stepTolerance);
  if (over <= maxPixelsOver) return ::testing::AssertionSuccess();
  std::string dir = freshDir("failures/" + name);
  std::string a = dir + "/actual.png", e = dir + "/expected.png", df = dir + "/diff.png";
  writePngAtomic(actual, a);
  writePngAtomic(expected, e);
  writePngAtomic(amplifiedDifference(actual, expected, 16), df);
  return ::testing::AssertionFailure()
         << name << ": " << over << " pixels differ by more than " << stepTolerance << "/255 (allowed "
         << maxPixelsOver << "); largest difference " << d.maxChannelDiff << "/255; worst: " << d.worst(5)
         << "\n  actual:   " << a << "\n  expected: " << e << "\n  diff x16: " << df;
}

namespace {
std::unique_ptr<Context> sharedContext;
std::string sharedContextFailure;
}  // namespace

void releaseGpuContext() { sharedContext.reset(); }

Context* gpuContextOrSkip() {
  std::unique_ptr<Context>& context = sharedContext;
  std::string& failure = sharedContextFailure;
  if (!context && failure.empty()) {
    try {
      context = std::make_unique<Context>(ContextOptions{"", true});
    } catch (const DeviceError& e) {
      failure = e.what();
    }
  }
  if (context) return context.get();
  if (inCi()) {
    ADD_FAILURE() << "no Vulkan device (required in CI): " << failure;
  } else {
    // What GTEST_SKIP() records, in a function that returns a value.
    ::testing::internal::AssertHelper(::testing::TestPartResult::kSkip, __FILE__, __LINE__,
                                      ("no Vulkan device, GPU test skipped: " + failure).c_str()) =
        ::testing::Message();
  }
  return nullptr;
}

RadianceImage renderFileQuietly(const std::string& scenePath, const std::function<void(RenderRequest&)>& adjust) {
  RenderRequest request;
  request.scenePath = scenePath;
  request.validation = true;
  adjust(request);
  ProgressBar quiet(false);
  RenderReport report;
  return renderSceneInMemory(request, quiet, report, false);
}

Image renderGpu(const SceneDesc& scene, std::uint32_t stepBudget, VulkanTimings* timings, SceneReads reads) {
  Context* context = gpuContextOrSkip();
  if (!context) return Image();
  VulkanOptions options;
  options.stepBudget = stepBudget;
  options.reads = reads;
  int before = context->validationMessages();
  RayCounts rays;
  Image image = encodeImage(renderVulkan(*context, flatten(scene), options, &rays, timings), 1.0);
  EXPECT_EQ(context->validationMessages(), before) << "the Vulkan validation layer reported problems (see stderr)";
  EXPECT_EQ(rays.nonFinite, 0u) << "the shader produced NaN or infinite colours";
  return image;
}

std::string parallelMirrorsScene(int maxDepth) {
  auto exact = [](double v) {   // enough digits to read back the same double
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  std::string emission, specular;
  for (const MirrorChannel& c : kParallelMirrorChannels) {
    emission += " " + exact(c.emission);
    specular += " " + exact(c.specular);
  }
  // Mirror A in z = 0 facing +z, mirror B in z = 10 facing -z; the ray runs along the z axis,
  // through the inside of both triangles (away from their edges).
  return "size 1 1\ncamera 0 0 5 0 0 0 0 1 0 30\nmaxdepth " + std::to_string(maxDepth) +
         "\nambient 0 0 0\nemission" + emission + "\nspecular" + specular +
         "\nvertex -10 -10 0\nvertex 10 -10 0\nvertex 0 10 0\ntri 0 1 2\n"
         "vertex -10 -10 10\nvertex 10 -10 10\nvertex 0 10 10\ntri 3 5 4\n";
}

double parallelMirrorsRadiance(const MirrorChannel& c, int maxDepth) {
  const double segments = maxDepth + 1.0;
  if (c.specular == 1.0) return c.emission * segments;
  // s^(D+1) through exp and log1p, which stay accurate for s near 1.
  return c.emission * -std::expm1(segments * std::log1p(c.specular - 1.0)) / (1.0 - c.specular);
}

namespace {

// Forks and execs `all` (argv) with stdout and stderr to `logPath` and `env` (NAME=value)
// added to this process's environment. argv and the environment are made before the fork:
// the child of a process with other threads (a GPU driver's) may only make system calls.
Spawned spawnArgv(std::vector<std::string> all, const std::string& logPath, const std::vector<std::string>& env) {
  std::vector<std::string> environment;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    const bool replaced = std::any_of(env.begin(), env.end(),
                                      [&](const std::string& x) { return x.substr(0, x.find('=')) == name; });
    if (!replaced) environment.push_back(entry);
  }
  environment.insert(environment.end(), env.begin(), env.end());
  std::vector<char*> argv, envp;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : environment) envp.push_back(e.data());
  envp.push_back(nullptr);
  static const char kExecFailed[] = "spawnArgv: exec failed\n";
  Spawned s;
  s.logPath = logPath;
  pid_t pid = ::fork();
  if (pid == 0) {
    int fd = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::execve(argv[0], argv.data(), envp.data());
    if (::write(2, kExecFailed, sizeof kExecFailed - 1) < 0) {
      // (nothing more to say)
    }
    ::_exit(127);
  }
  s.pid = pid;
  return s;
}

constexpr const char* kMeasureFlag = "--measure-peak-memory";

}  // namespace

Spawned spawnVkrt(const std::vector<std::string>& args, const std::string& logPath,
                  const std::vector<std::string>& env) {
  std::vector<std::string> all = {vkrtBinary()};
  all.insert(all.end(), args.begin(), args.end());
  return spawnArgv(std::move(all), logPath, env);
}

Finished waitVkrt(const Spawned& process) {
  Finished f;
  int status = 0;
  if (::waitpid(process.pid, &status, 0) != process.pid) return f;
  f.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  f.output = readFile(process.logPath);
  return f;
}

MeasuredRun runVkrtMeasuringMemory(const std::vector<std::string>& args, const std::string& logPath,
                                   const std::vector<std::string>& env) {
  const std::string peakPath = logPath + ".peak";
  std::remove(peakPath.c_str());
  std::vector<std::string> all = {"/proc/self/exe", kMeasureFlag, peakPath, vkrtBinary()};
  all.insert(all.end(), args.begin(), args.end());
  Spawned helper = spawnArgv(std::move(all), logPath, env);
  MeasuredRun f;
  static_cast<Finished&>(f) = waitVkrt(helper);
  std::ifstream peak(peakPath);
  if (!(peak >> f.peakRssKb)) {
    ADD_FAILURE() << "vkrt's peak memory was not measured (" << peakPath << "); exit " << f.exitCode;
    f.peakRssKb = -1;
  }
  std::remove(peakPath.c_str());
  return f;
}

int measurePeakMemoryMain(int argc, char** argv) {
  if (argc < 4 || std::strcmp(argv[1], kMeasureFlag) != 0) return -1;
  pid_t pid = ::fork();
  if (pid == 0) {
    ::execv(argv[3], argv + 3);
    std::perror(argv[3]);
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  if (pid < 0 || ::wait4(pid, &status, 0, &usage) != pid) return 126;
  if (std::FILE* f = std::fopen(argv[2], "w")) {
    std::fprintf(f, "%ld\n", usage.ru_maxrss);
    std::fclose(f);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

Finished waitVkrtWithin(const Spawned& p, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  siginfo_t info{};
  while (std::chrono::steady_clock::now() < deadline) {
    info.si_pid = 0;
    if (::waitid(P_PID, static_cast<id_t>(p.pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid != 0)
      return waitVkrt(p);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(p.pid, SIGKILL);
  return waitVkrt(p);
}

RunResult runVkrt(const std::string& args, const std::string& env) {
  return runCommand((env.empty() ? "" : "env " + env + " ") + "'" + vkrtBinary() + "' " + args);
}

RunResult runCommand(const std::string& commandLine) {
  const std::string cmd = "{ " + commandLine + "; } 2>&1";
  RunResult r;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  int status = ::pclose(p);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

// A test image whose every pixel differs from its neighbours in some channel.
namespace {
const std::string kBodyHeader = "size 64 48\ncamera 0 0 5 0 0 0 0 1 0 45\n";
}  // namespace

SceneDesc parseBody(const std::string& body) { return parseScene(kBodyHeader + body, "t.test"); }

SceneDesc parseBodyStrict(const std::string& body) {
  return parseSceneWithWarnings(kBodyHeader + body, "t.test", ParseOptions{true}).scene;
}

void expectNear(const dvec3& a, const dvec3& b, double eps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

bool sameBits(const RadianceImage& a, const RadianceImage& b) {
  return a.width == b.width && a.height == b.height && sameBits(a.rgb, b.rgb);
}

::testing::AssertionResult pathVariantsAgree(const Context& context, const RadianceImage& a, const RadianceImage& b) {
  if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size())
    return ::testing::AssertionFailure() << "sizes differ";
  const bool cpuDevice = context.isCpuDevice();
  if (cpuDevice)
    return sameBits(a, b) ? ::testing::AssertionSuccess()
                          : ::testing::AssertionFailure() << "not the same bits on a CPU device";
  double worst = 0.0;
  std::size_t differing = 0, worstAt = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    if (std::memcmp(&a.rgb[i], &b.rgb[i], sizeof(float)) == 0) continue;   // (equal NaNs and infinities too)
    const double x = a.rgb[i], y = b.rgb[i];
    ++differing;
    const double d = std::abs(x - y) / std::max(1.0, std::abs(x));
    if (!(d <= worst)) worst = d, worstAt = i;
  }
  if (worst <= 1e-5) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << differing << " values differ; the worst by " << worst << " at value "
                                       << worstAt << " (" << a.rgb[worstAt] << " against " << b.rgb[worstAt] << ")";
}

Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 13);
      p[2] = static_cast<std::uint8_t>(x ^ y);
    }
  return img;
}

std::size_t fileCount(const std::string& dir) {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++n;
  return n;
}

double imageMean(const RadianceImage& image) {
  double sum = 0;
  for (float v : image.rgb) sum += v;
  return sum / static_cast<double>(image.rgb.size());
}

EstimatorComparison compareEstimators(const RadianceImage& reference, int seeds,
                                      const std::function<RadianceImage(int way, std::uint32_t seed)>& render) {
  EstimatorComparison c;
  std::vector<double> means0;
  for (std::uint32_t seed = 1; seed <= static_cast<std::uint32_t>(seeds); ++seed)
    for (int way = 0; way < 2; ++way) {
      const RadianceImage image = render(way, seed);
      double sum = 0;
      for (std::size_t i = 0; i < image.rgb.size(); ++i)
        sum += (image.rgb[i] - reference.rgb[i]) * (image.rgb[i] - reference.rgb[i]);
      c.mse[way] += sum / static_cast<double>(image.rgb.size()) / seeds;
      const double m = imageMean(image);
      c.mean[way] += m / seeds;
      if (way == 0) means0.push_back(m);
    }
  double spread = 0;
  for (double m : means0) spread += (m - c.mean[0]) * (m - c.mean[0]);
  c.standardError = std::sqrt(spread / (seeds - 1) / seeds);
  return c;
}

void expectLessNoiseSameMean(const EstimatorComparison& c, const RadianceImage& reference, double ratio,
                             const char* way0, const char* way1) {
  const double mean = imageMean(reference);
  std::printf("[ stats    ] MSE: %s %.4g, %s %.4g (ratio %.3f); mean %.4g, %.4g, reference %.4g (standard error %.2g)\n",
              way0, c.mse[0], way1, c.mse[1], c.mse[1] / c.mse[0], c.mean[0], c.mean[1], mean, c.standardError);
  EXPECT_LT(c.mse[1], ratio * c.mse[0]);
  EXPECT_NEAR(c.mean[1], mean, 4 * c.standardError + 1e-3 * mean);
  EXPECT_NEAR(c.mean[0], mean, 4 * c.standardError + 1e-3 * mean);
}

}  // namespace vkrt::test
