// vkrt command line: parse arguments, call renderSceneFile(), turn exceptions into exit codes.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli/options.h"
#include "gpu/context.h"
#include "gpu/device_error.h"
#include "image/png.h"
#include "interrupt.h"
#include "render/render.h"
#include "scene/diagnostic.h"

namespace {

constexpr int kExitOk = 0, kExitUsage = 1, kExitScene = 2, kExitDevice = 3, kExitIo = 4;

void printStats(const vkrt::RenderRequest& req, const vkrt::RenderReport& r) {
  const double ms = 1e3;
  std::fprintf(stderr, "vkrt: %s %dx%d maxdepth %d: %zu triangles, %zu spheres, %zu lights; backend %s",
               req.scenePath.c_str(), r.width, r.height, r.maxDepth, r.triangles, r.spheres, r.lights,
               r.backend.c_str());
  if (req.backend == vkrt::Backend::Cpu) std::fprintf(stderr, ", %d threads", r.threads);
  std::fprintf(stderr, "\n  parse   %9.1f ms\n", r.parseSeconds * ms);
  std::fprintf(stderr, "  build   %9.1f ms  (BVH, %zu nodes)\n", r.buildSeconds * ms, r.bvhNodes);
  std::fprintf(stderr, "  render  %9.1f ms\n", r.renderSeconds * ms);
  if (req.backend == vkrt::Backend::Vulkan) {
    const vkrt::VulkanTimings& v = r.vulkan;
    std::fprintf(stderr, "    instance  %9.1f ms\n", r.instanceSeconds * ms);
    std::fprintf(stderr, "    device    %9.1f ms\n", r.deviceSeconds * ms);
    std::fprintf(stderr, "    upload    %9.1f ms\n", v.uploadSeconds * ms);
    std::fprintf(stderr, "    pipeline  %9.1f ms  (%s reads)\n", v.pipelineSeconds * ms,
                 v.texelReads ? "texel-buffer" : "storage-buffer");
    std::fprintf(stderr, "    first dispatch (with JIT) %9.1f ms\n", v.firstDispatchSeconds * ms);
    std::fprintf(stderr, "    left out: %s\n", v.leftOut.empty() ? "nothing" : v.leftOut.c_str());
    std::fprintf(stderr, "    dispatch  %9.1f ms  (%u bands, %u dispatches, %llu pixel suspensions)\n",
                 v.dispatchSeconds * ms, v.bands, v.dispatches, static_cast<unsigned long long>(v.suspensions));
    std::fprintf(stderr, "    readback  %9.1f ms\n", v.readbackSeconds * ms);
  }
  std::fprintf(stderr, "  write   %9.1f ms\n", r.writeSeconds * ms);
  double mrays = r.renderSeconds > 0 ? static_cast<double>(r.rays.total()) / r.renderSeconds / 1e6 : 0.0;
  std::fprintf(stderr, "  rays    %llu = primary %llu + shadow %llu + reflection %llu; %.1f Mrays/s\n",
               static_cast<unsigned long long>(r.rays.total()), static_cast<unsigned long long>(r.rays.primary),
               static_cast<unsigned long long>(r.rays.shadow), static_cast<unsigned long long>(r.rays.reflection),
               mrays);
}

}  // namespace

int main(int argc, char** argv) {
  vkrt::Options options;
  try {
    options = vkrt::parseOptions(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const vkrt::UsageError& e) {
    std::fprintf(stderr, "vkrt: error: %s\n\n%s", e.what(), vkrt::usageText());
    return kExitUsage;
  }
  if (options.help) {
    std::fputs(vkrt::usageText(), stdout);
    return kExitOk;
  }
  if (options.version) {
    std::printf("vkrt %s\n", VKRT_VERSION);
    return kExitOk;
  }
  try {
    if (options.listDevices) {
      auto devices = vkrt::listDevices();
      for (std::size_t i = 0; i < devices.size(); ++i)
        std::printf("%zu: %s (%s)\n", i, devices[i].name.c_str(), devices[i].typeName());
      return kExitOk;
    }
    vkrt::installInterruptHandlers();
    vkrt::ProgressBar progress(!options.quiet);
    vkrt::RenderReport report = vkrt::renderSceneFile(options.request, progress);
    if (options.stats) printStats(options.request, report);
    if (report.rays.nonFinite > 0)
      std::fprintf(stderr,
                   "vkrt: warning: %llu pixels had a NaN or infinite colour (written as 0, or 1 for +infinity); "
                   "the scene has extreme values\n",
                   static_cast<unsigned long long>(report.rays.nonFinite));
    if (!options.quiet) {
      double total = report.parseSeconds + report.buildSeconds + report.renderSeconds + report.writeSeconds;
      std::fprintf(stderr, "vkrt: wrote %s (%dx%d) in %.2f s\n", report.outputPath.c_str(), report.width,
                   report.height, total);
    }
    return kExitOk;
  } catch (const vkrt::Interrupted& e) {
    std::fprintf(stderr, "\nvkrt: interrupted; nothing written\n");
    return 128 + e.signal();
  } catch (const vkrt::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitScene;
  } catch (const vkrt::DeviceError& e) {
    std::fprintf(stderr, "vkrt: error: %s\n", e.what());
    return kExitDevice;
  } catch (const vkrt::IoError& e) {
    std::fprintf(stderr, "vkrt: error: %s\n", e.what());
    return kExitIo;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "vkrt: error: out of memory: %s needs more than the %llu MB this machine has available\n",
                 options.request.scenePath.c_str(), vkrt::availableMemoryBytes() >> 20);
    return kExitIo;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vkrt: internal error: %s\n", e.what());
    return 70;
  }
}
