// Rendering scene files: one, with --check; several, as a batch; --list-devices
// (host/cli/render_scenes.h).
#include "cli/render_scenes.h"

#include <chrono>
#include <cstdio>
#include <optional>

#include "cli/comparison_report.h"
#include "cli/exit_status.h"
#include "cli/render_report.h"
#include "cli/run_files.h"
#include "cli/warning_printers.h"
#include "util/counted.h"
#include "gpu/context.h"
#include "image/image_read.h"

namespace vkrt {

static double totalSeconds(const RenderReport& r) {
  return r.parseSeconds + r.buildSeconds + r.renderSeconds + r.writeSeconds;
}

// Several scenes in one process, sharing the Vulkan context: one line per scene (on stderr,
// as every log), then a summary; a failed scene does not stop the others, a signal does. The
// exit status is the highest of the scenes' (worseExitStatus). A scene whose output is one
// of the batch's scene files, or a file an earlier scene wrote, is refused (usage error,
// nothing rendered for it): the files stay as they were.
int renderBatch(const RenderOptions& o) {
  auto start = std::chrono::steady_clock::now();
  RenderSession session;
  RunFiles files;
  for (const std::string& scenePath : o.scenes) files.addInput(scenePath, "the scene file");
  const std::size_t n = o.scenes.size();
  std::size_t rendered = 0, failed = 0, done = 0;
  int worst = kExitOk;
  for (const std::string& scenePath : o.scenes) {
    ++done;
    auto t0 = std::chrono::steady_clock::now();
    RenderRequest request = o.request;
    request.scenePath = scenePath;
    request.onWarnings = warningPrinter(o.quiet);
    request.onOptionWarning = optionWarningPrinter(o.quiet);
    const std::string role = "the output of " + scenePath;
    request.onOutput = [&files, &role](const std::string& path) { files.checkOutput(path, role); };
    int status = kExitOk;
    RenderReport report;
    try {
      ProgressBar progress(!o.quiet);
      report = renderSceneFile(request, progress, nullptr, &session);
      files.addOutput(report.outputPath, role);
      if (o.stats && !o.request.dryRun) printStats(request, report);
      warnNonFinite(o.quiet, report);
    } catch (...) {
      status = reportError(currentFailure(), {scenePath, o.quiet}, stderr);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    worst = worseExitStatus(worst, status);
    if (status == kExitOk) {
      ++rendered;
      if (!o.quiet && o.request.dryRun)
        std::fprintf(stderr, "vkrt: [%zu/%zu] ok      %s -> %s (%dx%d), not rendered (--dry-run)\n", done, n,
                     scenePath.c_str(), report.outputPath.c_str(), report.width, report.height);
      else if (!o.quiet)
        std::fprintf(stderr, "vkrt: [%zu/%zu] ok      %s -> %s (%dx%d%s) in %.2f s\n", done, n, scenePath.c_str(),
                     report.outputPath.c_str(), report.width, report.height, samplesNote(report).c_str(), seconds);
    } else {
      ++failed;
      std::fprintf(stderr, "vkrt: [%zu/%zu] exit %-2d %s: %s, nothing written, in %.2f s\n", done, n, status,
                   scenePath.c_str(), exitStatusName(status).c_str(), seconds);
    }
    if (status >= kExitSignalBase) break;   // Ctrl-C stops the batch, not just this scene
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet || worst != kExitOk) {
    std::fprintf(stderr, "vkrt: %s in %.2f s: %zu %s, %zu failed", counted(n, "scene", "scenes").c_str(),
                 seconds, rendered, o.request.dryRun ? "checked (--dry-run: nothing rendered)" : "rendered", failed);
    if (done < n) std::fprintf(stderr, ", %zu not rendered (stopped)", n - done);
    std::fprintf(stderr, "; exit status %d\n", worst);
  }
  return worst;
}

// One scene: the scene file and the --check reference are inputs; the heatmap and the image
// (its path known once the scene is parsed, checked before the render starts) outputs. The
// reference is read before anything is rendered.
int renderOne(RenderOptions& options) {
  RunFiles files;
  files.addInput(options.request.scenePath, "the scene file");
  if (options.checkAgainst) files.addInput(*options.checkAgainst, "the reference image (--check)");
  claimHeatmap(options.comparison, files);
  // A float reference (PFM, EXR) is kept as radiance too: the render's radiance is compared
  // with it by HDR-FLIP (the 8-bit figures compare the two encoded).
  std::optional<Image> reference;
  std::optional<RadianceImage> referenceRadiance;
  if (options.checkAgainst) {
    AnyImage any = readAnyImage(*options.checkAgainst);
    if (any.radiance) {
      reference = asBytes(*any.radiance);
      referenceRadiance = std::move(any.radiance);
    } else {
      reference = std::move(any.bytes);
    }
  }
  options.request.onOutput = [&files](const std::string& path) { files.checkOutput(path, "the image"); };
  ProgressBar progress(!options.quiet);
  Image image;
  options.request.onWarnings = warningPrinter(options.quiet);
  options.request.onOptionWarning = optionWarningPrinter(options.quiet);
  RadianceImage radiance;
  RenderReport report = renderSceneFile(options.request, progress, reference ? &image : nullptr, nullptr,
                                        referenceRadiance ? &radiance : nullptr);
  if (options.request.dryRun) {
    if (!options.quiet)
      std::fprintf(stderr, "vkrt: %s -> %s (%dx%d), not rendered (--dry-run)\n", options.request.scenePath.c_str(),
                   report.outputPath.c_str(), report.width, report.height);
    return kExitOk;
  }
  if (options.stats) printStats(options.request, report);
  warnNonFinite(options.quiet, report);
  if (!options.quiet)
    std::fprintf(stderr, "vkrt: wrote %s (%dx%d%s) in %.2f s\n", report.outputPath.c_str(), report.width,
                 report.height, samplesNote(report).c_str(), totalSeconds(report));
  if (reference) {
    const bool hdr = referenceRadiance && radiance.width == image.width && radiance.height == image.height;
    return reportComparison(options.comparison, image, *reference, report.outputPath + " vs " + *options.checkAgainst,
                            std::nullopt, hdr ? &radiance : nullptr, hdr ? &*referenceRadiance : nullptr);
  }
  return kExitOk;
}

int printDevices() {
  auto devices = listDevices();
  for (std::size_t i = 0; i < devices.size(); ++i)
    std::printf("%zu: %s (%s)\n", i, devices[i].name.c_str(), devices[i].typeName());
  return kExitOk;
}

}  // namespace vkrt
