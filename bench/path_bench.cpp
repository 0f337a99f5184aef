// vkrt_path_bench: times renderVulkanPath on one scene file (parse, flatten, render), for
// measuring the path tracer before the command line drives it. Prints wall and CPU seconds
// (the process's, lavapipe's worker threads included), the Vulkan timings, ray counts, and a
// hash of the float image's bits, so that two builds can be checked for the same image.
#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <string>

#include "gpu/context.h"
#include "gpu/vulkan_path_renderer.h"
#include "util/ray_counts.h"
#include "scene/flatten.h"
#include "scene/parse.h"

using namespace vkrt;

namespace {

const char* kUsage =
    "usage: vkrt_path_bench SCENE [--spp N] [--seed N] [--crop X0 Y0 X1 Y1] [--budget N] [--runs N]\n"
    "                       [--reads auto|storage|texel] [--test-all on|off] [--stratified] [--raw FILE]\n"
    "  --stratified  stratified samples over the --spp samples (vkrt --sampler stratified)\n"
    "  --raw FILE   write the image's floats (rgb, row-major) to FILE\n";

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::uint64_t fnv1a(const void* data, std::size_t bytes) {
  std::uint64_t h = 14695981039346656037ull;
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 1;
  }
  std::string scenePath = argv[1], rawPath;
  VulkanPathOptions options;
  int runs = 1;
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "missing value after %s\n%s", a.c_str(), kUsage);
        std::exit(1);
      }
      return argv[++i];
    };
    if (a == "--spp") {
      options.sampleCount = static_cast<std::uint32_t>(std::atoi(next()));
    } else if (a == "--seed") {
      options.seed = static_cast<std::uint32_t>(std::atoi(next()));
    } else if (a == "--budget") {
      options.stepBudget = static_cast<std::uint32_t>(std::atoi(next()));
    } else if (a == "--runs") {
      runs = std::atoi(next());
    } else if (a == "--raw") {
      rawPath = next();
    } else if (a == "--reads") {
      std::string r = next();
      options.reads = r == "storage" ? SceneReads::Storage : r == "texel" ? SceneReads::Texel : SceneReads::Auto;
    } else if (a == "--stratified") {
      options.stratified = true;
    } else if (a == "--test-all") {
      options.testAll = std::string(next()) != "off";
    } else if (a == "--crop") {
      PixelRect c{};
      c.x0 = std::atoi(next());
      c.y0 = std::atoi(next());
      c.x1 = std::atoi(next());
      c.y1 = std::atoi(next());
      options.crop = c;
    } else {
      std::fprintf(stderr, "unknown option %s\n%s", a.c_str(), kUsage);
      return 1;
    }
  }
  options.renderSpp = options.sampleCount;
  try {
    auto w0 = std::chrono::steady_clock::now();
    double c0 = cpuSeconds();
    SceneDesc desc = parseSceneFile(scenePath);
    GpuScene scene = flatten(desc);
    Context context(ContextOptions{});
    double setupWall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    double setupCpu = cpuSeconds() - c0;
    std::printf("setup (parse, flatten, context): wall %.3f s, cpu %.3f s\n", setupWall, setupCpu);
    for (int run = 0; run < runs; ++run) {
      auto r0 = std::chrono::steady_clock::now();
      double rc0 = cpuSeconds();
      RayCounts rays;
      VulkanTimings t;
      RadianceImage image = renderVulkanPath(context, scene, options, &rays, &t);
      double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - r0).count();
      double cpu = cpuSeconds() - rc0;
      auto millions = [](std::uint64_t n) { return static_cast<double>(n) * 1e-6; };
      const std::uint64_t total = rays.primary + rays.shadow + rays.secondary;
      std::printf(
          "run %d: wall %.3f s, cpu %.3f s | pipeline %.3f first dispatch %.3f dispatch %.3f readback %.3f | "
          "dispatches %u bands %u suspensions %llu | rays %.2f M (primary %.2f shadow %.2f scatter %.2f) "
          "%.2f Mrays/cpu-s | nonfinite %llu | %s variant | image %016llx\n",
          run, wall, cpu, t.pipelineSeconds, t.firstDispatchSeconds, t.dispatchSeconds, t.readbackSeconds,
          t.dispatches, t.bands, static_cast<unsigned long long>(t.suspensions), millions(total), millions(rays.primary),
          millions(rays.shadow), millions(rays.secondary), millions(total) / cpu,
          static_cast<unsigned long long>(rays.nonFinite), t.general ? "general" : "specialised",
          static_cast<unsigned long long>(fnv1a(image.rgb.data(), image.rgb.size() * sizeof(float))));
      if (!rawPath.empty() && run == 0) {
        std::ofstream out(rawPath, std::ios::binary);
        out.write(reinterpret_cast<const char*>(image.rgb.data()),
                  static_cast<std::streamsize>(image.rgb.size() * sizeof(float)));
      }
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 3;
  }
  return 0;
}
