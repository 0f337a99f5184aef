// The watch loop: render, refine, wait for a change, render again.
#include "cli/watch.h"

#include <chrono>
#include <cstdio>
#include <exception>

#include "cli/exit_status.h"
#include "watch/file_watch.h"
#include "cli/warning_printers.h"
#include "cli/run_files.h"
#include "util/counted.h"
#include "image/atomic_file.h"
#include "image/image_file.h"
#include "image/samples.h"
#include "util/interrupt.h"
#include "render/render.h"
#include "util/timing.h"

namespace vkrt {
namespace {

// The vkrt-samples record of `image` (every path integrator's image has one).
SampleRecord samplesOf(const RadianceImage& image) {
  if (std::optional<SampleRecord> r = sampleRecordOf(image.text)) return *r;
  throw InternalError("a path-traced image without its samples record");
}

class Watcher {
 public:
  Watcher(RenderOptions& options, WatchListener* listener)
      : o_(options), listener_(listener), watch_(options.request.scenePath) {}

  int run() {
    checkWatchOutputs(o_);
    for (int round = 1;; ++round) {
      bool changed = false;
      if (listener_) listener_->roundStarted(round);
      try {
        changed = renderAndRefine(round);
      } catch (const Interrupted&) {
        throw;
      } catch (...) {
        std::string message;
        const int status = reportErrorKeepingText(std::current_exception(), {o_.request.scenePath, o_.quiet}, message);
        if (message.empty()) message = "(the error is on vkrt's stderr)\n";
        // Nothing rendered yet and nothing the scene can fix (no device, no memory): no use waiting.
        if (round == 1 && status != kExitScene && status != kExitIo && status != kExitUsage) return status;
        const std::string waiting = "vkrt: watch: " + exitStatusName(status) +
                                    ", nothing written; waiting for the next change of " + o_.request.scenePath + "\n";
        std::fputs(waiting.c_str(), stderr);
        if (listener_) listener_->failed(round, message + waiting);
      }
      if (!changed) watch_.waitForChange(-1);
    }
  }

 private:
  // One render, then for a path integrator further batches until the file changes (true) or
  // the batches are all in (false).
  bool renderAndRefine(int round) {
    const auto t0 = std::chrono::steady_clock::now();
    RenderRequest request = o_.request;
    std::size_t warnings = 0;
    request.onWarnings = [this, &warnings, print = warningPrinter(o_.quiet)](const std::vector<Diagnostic>& w) {
      warnings = w.size();
      if (print) print(w);
      if (listener_)
        for (const Diagnostic& d : w) listener_->warned(d.format());
    };
    request.onOptionWarning = [this, print = optionWarningPrinter(o_.quiet || round != 1)](const std::string& w) {
      if (print) print(w);
      if (listener_) listener_->warned("vkrt: warning: " + w);
    };
    // Named anew each round: an editor that saves by renaming gives the scene another inode,
    // and its old one may come back as the image's.
    RunFiles files;
    files.addInput(o_.request.scenePath, "the scene file");
    request.onOutput = [&files](const std::string& path) { files.checkOutput(path, "the image"); };
    ProgressBar progress(!o_.quiet);
    RenderReport report;
    RadianceImage mean = renderSceneInMemory(request, progress, report, true, &session_);
    writeImageAtomic(mean, report.outputPath, report.gamma);
    char line[1024];
    std::snprintf(line, sizeof line, "vkrt: watch: [%d] wrote %s (%dx%d%s) in %.3f s%s\n", round,
                  report.outputPath.c_str(), report.width, report.height,
                  report.pathIntegrator ? (", " + counted(mean.samples, "sample", "samples") + " per pixel").c_str() : "",
                  secondsSince(t0), warnings ? (", " + counted(warnings, "warning", "warnings")).c_str() : "");
    if (!o_.quiet) std::fputs(line, stderr);
    WatchStep step{round, 1, report.pathIntegrator ? kMaxWatchBatches : 1, mean.samples, secondsSince(t0),
                   report.outputPath, line};
    if (listener_) listener_->rendered(step);
    if (!report.pathIntegrator) return false;
    SampleRecord record = samplesOf(mean);
    const std::uint32_t seed = o_.request.seed.value_or(0);
    for (int batch = 1; batch < kMaxWatchBatches; ++batch) {
      if (watch_.waitForChange(0)) return true;
      const auto tb = std::chrono::steady_clock::now();
      RenderRequest more = request;
      more.seed = seed + static_cast<std::uint32_t>(batch);
      more.onWarnings = nullptr;
      more.onOptionWarning = nullptr;
      more.onImageStart = nullptr;   // the viewer's image is the round's, refined below
      more.onImageRows = nullptr;
      RenderReport batchReport;
      ProgressBar quietBar(false);
      RadianceImage next = renderSceneInMemory(more, quietBar, batchReport, true, &session_);
      const SampleRecord added = samplesOf(next);
      record.ranges.insert(record.ranges.end(), added.ranges.begin(), added.ranges.end());
      accumulateMean(mean, std::move(next));
      if (request.onImageRows) request.onImageRows(0, mean);
      setSampleRecord(mean.text, record);
      writeImageAtomic(mean, report.outputPath, report.gamma);
      std::snprintf(line, sizeof line, "vkrt: watch: [%d] refined %s to %s per pixel (%d of %d batches) in %.3f s\n",
                    round, report.outputPath.c_str(), counted(mean.samples, "sample", "samples").c_str(), batch + 1,
                    kMaxWatchBatches, secondsSince(tb));
      if (!o_.quiet) std::fputs(line, stderr);
      step.batch = batch + 1, step.samples = mean.samples, step.seconds = secondsSince(t0), step.line = line;
      if (listener_) listener_->rendered(step);
    }
    return false;
  }

  RenderOptions& o_;
  WatchListener* listener_;
  RenderSession session_;
  FileWatch watch_;
};

}  // namespace

void checkWatchOutputs(const RenderOptions& o) {
  if (o.request.output) checkOutputWritable(*o.request.output);
  if (o.request.outputDir) checkOutputWritable(defaultOutputIn(*o.request.outputDir, o.request.scenePath));
}

int watchScene(RenderOptions& options, WatchListener* listener) {
  try {
    return Watcher(options, listener).run();
  } catch (const Interrupted& stop) {
    if (!options.quiet) std::fprintf(stderr, "vkrt: watch: stopped\n");
    return kExitSignalBase + stop.signal();
  }
}

}  // namespace vkrt
