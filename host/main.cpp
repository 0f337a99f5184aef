// vkrt command line: parse arguments, call renderSceneFile() (once per scene; several scenes
// share one RenderSession), turn exceptions into exit statuses (through reportError:
// host/cli/exit_status.h). Every command first names the files it reads and writes to one
// RunFiles (host/cli/run_files.h), which refuses an output that is one of the run's own
// files before anything is read, rendered or written.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli/exit_status.h"
#include "cli/grade.h"
#include "counted.h"
#include "cli/options.h"
#include "cli/run_files.h"
#include "cli/watch.h"
#include "errors.h"
#include "image/atomic_file.h"
#include "gpu/context.h"
#include "image/encode.h"
#include "image/image_file.h"
#include "image/image_read.h"
#include "image/merge.h"
#include "cli/warning_printers.h"
#include "gpu/loader_drivers.h"
#include "interrupt.h"
#include "render/render.h"
#include "scene/diagnostic.h"

namespace {

using vkrt::kExitDiffers;
using vkrt::kExitOk;

// The exception being handled, or Interrupted when a signal has been received: a signal
// that cuts a wait short (an image read from a FIFO: "Interrupted system call") is what
// stopped the command, and its status is the signal's.
std::exception_ptr failure() {
  if (int signal = vkrt::pendingInterrupt()) return std::make_exception_ptr(vkrt::Interrupted(signal));
  return std::current_exception();
}

// " (N samples)" after a path integrator's output, with "time up" when --time ended it, and
// how far past it the first batch ran when that alone took longer.
std::string samplesNote(const vkrt::RenderReport& r) {
  if (!r.pathIntegrator) return "";
  std::string past;
  if (r.firstBatchPastLimit > 0) {   // (under --time the first batch is one sample)
    char s[32];
    std::snprintf(s, sizeof s, r.firstBatchPastLimit >= 1 ? "%.1f" : "%.2g", r.firstBatchPastLimit);
    past = std::string("; the first sample per pixel, which every render takes, ended ") + s + " s past --time";
  }
  return ", " + vkrt::counted(r.samples, "sample", "samples") + " per pixel" +
         (r.timeUp ? " when the time was up" : "") + past;
}

// The heatmap of --diff, when asked for, in the 8-bit format of its name.
void writeHeatmap(const vkrt::Options& o, const vkrt::ImageDiff& diff) {
  if (o.heatmapPath) vkrt::writeImageAtomic(vkrt::differenceHeatmap(diff, o.heatmapScale), *o.heatmapPath);
}

// --diff FILE: an output of the run, checked (and its folder's writability) before any
// image is read or rendered.
void claimHeatmap(const vkrt::Options& o, vkrt::RunFiles& files) {
  if (!o.heatmapPath) return;
  files.addOutput(*o.heatmapPath, "the heatmap (--diff)");
  vkrt::checkOutputWritable(*o.heatmapPath);
}

// The metrics, the heatmap (written, and named with its scale) and the failures, as text.
void printComparisonText(const vkrt::Options& o, const vkrt::ImageDiff& diff, const std::vector<std::string>& failures) {
  writeHeatmap(o, diff);
  std::printf("%s", vkrt::diffReportText(diff).c_str());
  if (o.heatmapPath)
    std::printf("  heatmap     %s (black: equal; blue 1/255 ... red %d/255 or more)\n", o.heatmapPath->c_str(),
                o.heatmapScale);
  for (const std::string& f : failures) std::printf("FAIL: %s\n", f.c_str());
}

// Compares `actual` with `expected` (diff and --check): the report on stdout (text or JSON),
// the heatmap if asked for; kExitDiffers when a threshold is exceeded. Throws IoError.
// `linear`: for two linear-float images, their difference in radiance units, reported beside
// the 8-bit figures (which the thresholds judge).
int reportComparison(const vkrt::Options& o, const vkrt::Image& actual, const vkrt::Image& expected,
                     const std::string& what, const std::optional<vkrt::LinearDifference>& linear = std::nullopt) {
  if (actual.width != expected.width || actual.height != expected.height) {
    std::string msg = "sizes differ: " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                      " vs " + std::to_string(expected.width) + "x" + std::to_string(expected.height);
    if (o.json)
      std::printf("{\"pass\":false,\"failures\":[%s]}\n", vkrt::jsonQuoted(msg).c_str());
    else
      std::printf("%s: FAIL: %s\n", what.c_str(), msg.c_str());
    return kExitDiffers;
  }
  vkrt::ImageDiff diff = vkrt::compare(actual, expected);
  std::vector<std::string> failures = vkrt::failedThresholds(diff, o.thresholds);
  if (o.json) {
    writeHeatmap(o, diff);
    std::string json = vkrt::diffReportJson(diff, failures);
    if (linear) {
      // JSON has no infinity: a difference without bound (a NaN or infinite channel) is null.
      auto number = [](double v) {
        char s[32];
        std::snprintf(s, sizeof s, "%.9g", v);
        return std::isfinite(v) ? std::string(s) : std::string("null");
      };
      json = json.substr(0, json.size() - 1) + ",\"linear_max_diff\":" + number(linear->maxDiff) +
             ",\"linear_rmse\":" + number(linear->rmse) + "}";
    }
    std::printf("%s\n", json.c_str());
  } else {
    std::printf("%s\n", what.c_str());
    if (linear)
      std::printf("  linear      max diff %.6g, RMSE %.6g (radiance, before encoding)\n", linear->maxDiff, linear->rmse);
    printComparisonText(o, diff, failures);
    if (failures.empty()) std::printf("PASS\n");
  }
  return failures.empty() ? kExitOk : kExitDiffers;
}

// "3 lights (1 point, 2 quad)": the total, then each kind there is.
std::string lightsText(const vkrt::RenderReport::Lights& l) {
  std::string kinds;
  auto add = [&](std::size_t n, const std::string& kind) {
    if (n > 0) kinds += (kinds.empty() ? "" : ", ") + kind;
  };
  for (std::size_t type = 0; type < vkrt::kLightTypeCount; ++type)
    add(l.byType[type], std::to_string(l.byType[type]) + " " + std::string(vkrt::kLightTypeNames[type]));
  add(l.quad, std::to_string(l.quad) + " quad");
  for (std::uint32_t kind = 0; kind < vkrt::shapes::kKinds; ++kind)
    add(l.emissive[kind], vkrt::counted(l.emissive[kind], "emissive " + std::string(vkrt::shapes::kNames[kind]),
                                        "emissive " + std::string(vkrt::shapes::kPluralNames[kind])));
  return vkrt::counted(l.total(), "light", "lights") + (kinds.empty() ? "" : " (" + kinds + ")");
}

void printStats(const vkrt::RenderRequest& req, const vkrt::RenderReport& r) {
  const double ms = 1e3;
  std::string primitives;   // "2 triangles, 1 sphere, ": every kind of shape
  for (std::uint32_t kind = 0; kind < vkrt::shapes::kKinds; ++kind) {
    using vkrt::shapes::kNames, vkrt::shapes::kPluralNames;
    primitives += vkrt::counted(r.primitives[kind], kNames[kind], kPluralNames[kind]) + ", ";
  }
  std::fprintf(stderr, "vkrt: %s %dx%d maxdepth %d: %s%s; backend %s", req.scenePath.c_str(), r.width, r.height,
               r.maxDepth, primitives.c_str(), lightsText(r.lights).c_str(), r.backend.c_str());
  if (req.backend == vkrt::Backend::Cpu)
    std::fprintf(stderr, ", %s", vkrt::counted(r.threads, "thread", "threads").c_str());
  if (!r.estimator.empty()) std::fprintf(stderr, "\n  estimator: %s", r.estimator.c_str());
  std::fprintf(stderr, "\n  parse   %9.1f ms\n", r.parseSeconds * ms);
  std::fprintf(stderr, "  build   %9.1f ms  (BVH, %s", r.buildSeconds * ms,
               vkrt::counted(r.bvhNodes, "node", "nodes").c_str());
  if (req.backend == vkrt::Backend::Vulkan)
    std::fprintf(stderr, "; beside it the first batch's pipeline, %.1f ms", r.pipelineAheadSeconds * ms);
  std::fprintf(stderr, ")\n");
  std::fprintf(stderr, "  render  %9.1f ms\n", r.renderSeconds * ms);
  if (req.backend == vkrt::Backend::Vulkan) {
    const vkrt::VulkanTimings& v = r.vulkan;
    std::fprintf(stderr, "    instance  %9.1f ms\n", r.instanceSeconds * ms);
    std::fprintf(stderr, "    device    %9.1f ms\n", r.deviceSeconds * ms);
    std::fprintf(stderr, "    upload    %9.1f ms\n", v.uploadSeconds * ms);
    std::fprintf(stderr, "    pipeline  %9.1f ms  (%s reads)\n", v.pipelineSeconds * ms,
                 v.texelReads ? "texel-buffer" : "storage-buffer");
    std::fprintf(stderr, "    first dispatch (with JIT) %9.1f ms\n", v.firstDispatchSeconds * ms);
    std::fprintf(stderr, "    shader: the %s variant (about %.3g M rays; %s)\n",
                 v.general ? "general" : "specialised", v.estimatedRays / 1e6,
                 v.testedAll ? "each ray tests every primitive" : "rays walk the BVH");
    std::fprintf(stderr, "    left out: %s\n", v.leftOut.empty() ? "nothing" : v.leftOut.c_str());
    std::fprintf(stderr, "    dispatch  %9.1f ms  (%s, %s, %s)\n", v.dispatchSeconds * ms,
                 vkrt::counted(v.bands, "band", "bands").c_str(),
                 vkrt::counted(v.dispatches, "dispatch", "dispatches").c_str(),
                 vkrt::counted(v.suspensions, "suspension", "suspensions").c_str());
    std::fprintf(stderr, "    readback  %9.1f ms\n", v.readbackSeconds * ms);
  }
  std::fprintf(stderr, "  write   %9.1f ms\n", r.writeSeconds * ms);
  double mrays = r.renderSeconds > 0 ? static_cast<double>(r.rays.total()) / r.renderSeconds / 1e6 : 0.0;
  std::fprintf(stderr, "  rays    %llu = primary %llu + shadow %llu + secondary %llu; %.1f Mrays/s\n",
               static_cast<unsigned long long>(r.rays.total()), static_cast<unsigned long long>(r.rays.primary),
               static_cast<unsigned long long>(r.rays.shadow), static_cast<unsigned long long>(r.rays.secondary),
               mrays);
}

std::string reportJson(const vkrt::RenderReport& r) {
  char buf[1024];
  const vkrt::VulkanTimings& v = r.vulkan;
  std::snprintf(buf, sizeof buf,
                "{\"backend\":%s,\"seconds\":%.6f,\"parse_s\":%.6f,\"build_s\":%.6f,\"render_s\":%.6f,"
                "\"instance_s\":%.6f,\"device_s\":%.6f,\"upload_s\":%.6f,\"pipeline_ahead_s\":%.6f,\"pipeline_s\":%.6f,"
                "\"first_dispatch_s\":%.6f,\"dispatch_s\":%.6f,\"readback_s\":%.6f,\"rays\":%llu,"
                "\"shadow_rays\":%llu,\"secondary_rays\":%llu}",
                vkrt::jsonQuoted(r.backend).c_str(), r.parseSeconds + r.buildSeconds + r.renderSeconds, r.parseSeconds, r.buildSeconds,
                r.renderSeconds, r.instanceSeconds, r.deviceSeconds, v.uploadSeconds, r.pipelineAheadSeconds, v.pipelineSeconds,
                v.firstDispatchSeconds, v.dispatchSeconds, v.readbackSeconds,
                static_cast<unsigned long long>(r.rays.total()), static_cast<unsigned long long>(r.rays.shadow),
                static_cast<unsigned long long>(r.rays.secondary));
  return buf;
}

// The warning for pixels whose colour was NaN or infinite (with --strict: an error already);
// under --compare, which writes nothing, named by the backend that rendered them.
void warnNonFinite(const vkrt::Options& o, const vkrt::RenderReport& report, const std::string& backend = "") {
  if (report.rays.nonFinite > 0 && !o.quiet)
    std::fprintf(stderr, "vkrt: warning: %s%s a NaN or infinite colour (%s); the scene has extreme values\n",
                 backend.empty() ? "" : (backend + ": ").c_str(),
                 vkrt::counted(report.rays.nonFinite, "pixel had", "pixels had").c_str(),
                 backend.empty() ? "NaN written as 0, +infinity as 255 in PNG and PPM, as the largest float in PFM and EXR"
                                 : "compared as 8-bit: NaN as 0, +infinity as 255");
}

// --compare: both backends in turn, nothing written; the total time of each and their
// difference (stdout), each one's breakdown (stderr) only with --stats. Exit 5 when a
// threshold is exceeded.
int compareBackends(const vkrt::Options& o) {
  vkrt::RunFiles files;
  files.addInput(o.request.scenePath, "the scene file");
  claimHeatmap(o, files);
  vkrt::RenderReport reports[2];
  vkrt::Image images[2];
  const vkrt::Backend backends[2] = {vkrt::Backend::Vulkan, vkrt::Backend::Cpu};
  for (int i = 0; i < 2; ++i) {
    vkrt::RenderRequest request = o.request;
    request.backend = backends[i];
    request.onWarnings = vkrt::warningPrinter(o.quiet || i > 0);   // the same scene twice: once
    request.onOptionWarning = vkrt::optionWarningPrinter(o.quiet || i > 0);
    vkrt::ProgressBar progress(!o.quiet && !o.json);
    images[i] = vkrt::encodeImage(vkrt::renderSceneInMemory(request, progress, reports[i], false), reports[i].gamma);
    if (o.stats && !o.json && !o.quiet) printStats(request, reports[i]);
    warnNonFinite(o, reports[i], i == 0 ? "vulkan" : "cpu");
  }
  vkrt::ImageDiff diff = vkrt::compare(images[0], images[1]);
  std::vector<std::string> failures = vkrt::failedThresholds(diff, o.thresholds);
  if (!o.thresholds.any()) failures.clear();   // --compare reports; it gates only when asked to
  auto total = [](const vkrt::RenderReport& r) { return r.parseSeconds + r.buildSeconds + r.renderSeconds; };
  if (o.json) {
    writeHeatmap(o, diff);
    std::printf("{\"scene\":%s,\"vulkan\":%s,\"cpu\":%s,\"difference\":%s}\n",
                vkrt::jsonQuoted(o.request.scenePath).c_str(),
                reportJson(reports[0]).c_str(), reportJson(reports[1]).c_str(),
                vkrt::diffReportJson(diff, failures).c_str());
  } else {
    std::printf("%s: vulkan %.3f s, cpu %.3f s (without writing); vulkan vs cpu:\n", o.request.scenePath.c_str(),
                total(reports[0]), total(reports[1]));
    printComparisonText(o, diff, failures);
  }
  return failures.empty() ? kExitOk : kExitDiffers;
}

double totalSeconds(const vkrt::RenderReport& r) {
  return r.parseSeconds + r.buildSeconds + r.renderSeconds + r.writeSeconds;
}

// Several scenes in one process, sharing the Vulkan context: one line per scene (on stderr,
// as every log), then a summary; a failed scene does not stop the others, a signal does. The
// exit status is the highest of the scenes' (worseExitStatus). A scene whose output is one
// of the batch's scene files, or a file an earlier scene wrote, is refused (usage error,
// nothing rendered for it): the files stay as they were.
int renderBatch(const vkrt::Options& o) {
  auto start = std::chrono::steady_clock::now();
  vkrt::RenderSession session;
  vkrt::RunFiles files;
  for (const std::string& scenePath : o.scenes) files.addInput(scenePath, "the scene file");
  const std::size_t n = o.scenes.size();
  std::size_t rendered = 0, failed = 0, done = 0;
  int worst = kExitOk;
  for (const std::string& scenePath : o.scenes) {
    ++done;
    auto t0 = std::chrono::steady_clock::now();
    vkrt::RenderRequest request = o.request;
    request.scenePath = scenePath;
    request.onWarnings = vkrt::warningPrinter(o.quiet);
    request.onOptionWarning = vkrt::optionWarningPrinter(o.quiet);
    const std::string role = "the output of " + scenePath;
    request.onOutput = [&files, &role](const std::string& path) { files.checkOutput(path, role); };
    int status = kExitOk;
    vkrt::RenderReport report;
    try {
      vkrt::ProgressBar progress(!o.quiet);
      report = vkrt::renderSceneFile(request, progress, nullptr, &session);
      files.addOutput(report.outputPath, role);
      if (o.stats && !o.request.dryRun) printStats(request, report);
      warnNonFinite(o, report);
    } catch (...) {
      status = vkrt::reportError(failure(), {scenePath, o.quiet}, stderr);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    worst = vkrt::worseExitStatus(worst, status);
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
                   scenePath.c_str(), vkrt::exitStatusName(status).c_str(), seconds);
    }
    if (status >= vkrt::kExitSignalBase) break;   // Ctrl-C stops the batch, not just this scene
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet || worst != kExitOk) {
    std::fprintf(stderr, "vkrt: %s in %.2f s: %zu %s, %zu failed", vkrt::counted(n, "scene", "scenes").c_str(),
                 seconds, rendered, o.request.dryRun ? "checked (--dry-run: nothing rendered)" : "rendered", failed);
    if (done < n) std::fprintf(stderr, ", %zu not rendered (stopped)", n - done);
    std::fprintf(stderr, "; exit status %d\n", worst);
  }
  return worst;
}

// vkrt merge: the tiles are inputs, the merged image the output.
int merge(const vkrt::Options& options) {
  vkrt::RunFiles files;
  for (const std::string& tile : options.mergeTiles) files.addInput(tile, "the tile");
  files.addOutput(options.mergeOutput, "the merged image");
  vkrt::checkOutputWritable(options.mergeOutput);
  vkrt::checkMergeInputsAreFiles(options.mergeTiles);
  vkrt::MergeReport merged;
  auto printWarnings = [&] {   // -q leaves warnings out, as a scene's
    if (!options.quiet)
      for (const std::string& w : merged.warnings) std::fprintf(stderr, "vkrt: warning: %s\n", w.c_str());
  };
  if (vkrt::areSampleBatches(options.mergeTiles)) {
    vkrt::RadianceImage mean = vkrt::mergeSampleBatches(options.mergeTiles, &merged);
    printWarnings();
    vkrt::writeImageAtomic(mean, options.mergeOutput, merged.samples.gamma);
    if (!options.quiet)
      std::fprintf(stderr, "vkrt: averaged %s (%s per pixel) into %s (%dx%d)\n",
                   vkrt::counted(merged.tiles, "batch", "batches").c_str(),
                   vkrt::counted(merged.samples.total(), "sample", "samples").c_str(), options.mergeOutput.c_str(),
                   mean.width, mean.height);
    return kExitOk;
  }
  vkrt::writeMergedCrops(options.mergeTiles, options.allowGaps, options.mergeOutput, &merged);
  printWarnings();
  if (!options.quiet)
    std::fprintf(stderr, "vkrt: merged %s into %s (%dx%d)%s\n", vkrt::counted(merged.tiles, "tile", "tiles").c_str(),
                 options.mergeOutput.c_str(), merged.width, merged.height,
                 merged.gapPixels ? (", " + vkrt::counted(merged.gapPixels, "pixel", "pixels") + " left black").c_str()
                                  : "");
  return kExitOk;
}

// vkrt diff A B: both images are inputs, the heatmap (--diff) the output.
int diff(const vkrt::Options& options) {
  vkrt::RunFiles files;
  files.addInput(options.diffA, "image A");
  files.addInput(options.diffB, "image B");
  claimHeatmap(options, files);
  vkrt::AnyImage a = vkrt::readAnyImage(options.diffA);   // A first: its error, if both have one
  vkrt::AnyImage b = vkrt::readAnyImage(options.diffB);
  std::optional<vkrt::LinearDifference> linear;
  if (a.radiance && b.radiance) linear = vkrt::linearDifference(*a.radiance, *b.radiance);
  auto bytes = [](const vkrt::AnyImage& image) { return image.radiance ? vkrt::asBytes(*image.radiance) : image.bytes; };
  return reportComparison(options, bytes(a), bytes(b), options.diffA + " vs " + options.diffB, linear);
}

// vkrt convert IN OUT: IN is an input, never written; OUT is written whole or not at all.
int convert(const vkrt::Options& options) {
  vkrt::RunFiles files;
  files.addInput(options.convertInput, "the image to convert");
  files.addOutput(options.convertOutput, "the converted image");
  vkrt::checkOutputWritable(options.convertOutput);
  vkrt::convertImage(options.convertInput, options.convertOutput);
  if (!options.quiet)
    std::fprintf(stderr, "vkrt: wrote %s (%s) from %s\n", options.convertOutput.c_str(),
                 std::string(vkrt::imageFormatFor(options.convertOutput).name).c_str(), options.convertInput.c_str());
  return kExitOk;
}

// One scene: the scene file and the --check reference are inputs; the heatmap and the image
// (its path known once the scene is parsed, checked before the render starts) outputs. The
// reference is read before anything is rendered.
int renderOne(vkrt::Options& options) {
  vkrt::RunFiles files;
  files.addInput(options.request.scenePath, "the scene file");
  if (options.checkAgainst) files.addInput(*options.checkAgainst, "the reference image (--check)");
  claimHeatmap(options, files);
  std::optional<vkrt::Image> reference;
  if (options.checkAgainst) reference = vkrt::readImageAsBytes(*options.checkAgainst);
  options.request.onOutput = [&files](const std::string& path) { files.checkOutput(path, "the image"); };
  vkrt::ProgressBar progress(!options.quiet);
  vkrt::Image image;
  options.request.onWarnings = vkrt::warningPrinter(options.quiet);
  options.request.onOptionWarning = vkrt::optionWarningPrinter(options.quiet);
  vkrt::RenderReport report = vkrt::renderSceneFile(options.request, progress, reference ? &image : nullptr);
  if (options.request.dryRun) {
    if (!options.quiet)
      std::fprintf(stderr, "vkrt: %s -> %s (%dx%d), not rendered (--dry-run)\n", options.request.scenePath.c_str(),
                   report.outputPath.c_str(), report.width, report.height);
    return kExitOk;
  }
  if (options.stats) printStats(options.request, report);
  warnNonFinite(options, report);
  if (!options.quiet)
    std::fprintf(stderr, "vkrt: wrote %s (%dx%d%s) in %.2f s\n", report.outputPath.c_str(), report.width,
                 report.height, samplesNote(report).c_str(), totalSeconds(report));
  if (reference)
    return reportComparison(options, image, *reference, report.outputPath + " vs " + *options.checkAgainst);
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  vkrt::Options options;
  try {
    options = vkrt::parseOptions(std::vector<std::string>(argv + 1, argv + argc));
  } catch (...) {
    return vkrt::reportError(std::current_exception(), {}, stderr);
  }
  if (options.help) {
    std::fputs(vkrt::usageText(), stdout);
    return kExitOk;
  }
  if (options.version) {
    std::printf("vkrt %s\n", VKRT_VERSION);
    return kExitOk;
  }
  // Before any thread starts and before the Vulkan loader is opened.
  vkrt::skipDriversWithoutDevices();
  // Before any file is opened: a signal stops every command cleanly, its temporary file removed.
  vkrt::installInterruptHandlers();
  if (!options.quiet)
    for (const std::string& w : options.warnings) std::fprintf(stderr, "vkrt: warning: %s\n", w.c_str());
  try {
    if (options.mergeCommand) return merge(options);
    if (options.diffCommand) return diff(options);
    if (options.convertCommand) return convert(options);
    if (options.gradeCommand) return vkrt::gradeCommand(options);
    if (options.listDevices) {
      auto devices = vkrt::listDevices();
      for (std::size_t i = 0; i < devices.size(); ++i)
        std::printf("%zu: %s (%s)\n", i, devices[i].name.c_str(), devices[i].typeName());
      return kExitOk;
    }
    if (options.compare) return compareBackends(options);
    if (options.watch) return vkrt::watchScene(options);
    if (options.scenes.size() > 1) return renderBatch(options);
    return renderOne(options);
  } catch (...) {
    return vkrt::reportError(failure(), {options.request.scenePath, options.quiet}, stderr);
  }
}
