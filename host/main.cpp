// vkrt command line: parse the arguments into one command's options (cli/options.h), call
// the command (each lives in host/cli/), turn exceptions into exit statuses (through
// reportError: host/cli/exit_status.h).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cli/compare_backends.h"
#include "cli/convert_image.h"
#include "cli/diff_images.h"
#include "cli/exit_status.h"
#include "cli/grade.h"
#include "cli/merge_images.h"
#include "cli/options.h"
#include "cli/render_scenes.h"
#include "net/tev_display.h"
#include "cli/view_scene.h"
#include "cli/watch.h"
#include "gpu/loader_drivers.h"
#include "util/interrupt.h"
#include "platform/arguments.h"
#include "platform/terminal.h"
#include "platform/path_text.h"

namespace {

int run(vkrt::RenderOptions& o) {
  if (o.listDevices) return vkrt::printDevices();
  // The viewer (--display-server): an image per render, named for its output file, updated as
  // it refines; sent on a thread of its own, finished (at most 2 s) when the run ends.
  std::optional<vkrt::TevDisplay> display;
  if (o.display) {
    display.emplace(*o.display, o.quiet);
    o.request.onImageStart = [&display](const vkrt::RenderReport& report) {
      using vkrt::platform::pathFromUtf8, vkrt::platform::utf8FromPath;
      display->begin(utf8FromPath(pathFromUtf8(report.outputPath).filename()), report.width, report.height);
    };
    o.request.onImageRows = [&display](int y0, const vkrt::RadianceImage& rows) { display->update(y0, rows); };
  }
  if (o.compare) return vkrt::compareBackends(o);
  if (o.view) return vkrt::viewScene(o);
  if (o.watch) return vkrt::watchScene(o);
  if (o.scenes.size() > 1) return vkrt::renderBatch(o);
  return vkrt::renderOne(o);
}
int run(vkrt::DiffOptions& o) { return vkrt::diffImages(o); }
int run(vkrt::MergeOptions& o) { return vkrt::mergeImages(o); }
int run(vkrt::ConvertOptions& o) { return vkrt::convertImage(o); }
int run(vkrt::GradeOptions& o) { return vkrt::gradeCommand(o); }

// The scene an allocation failure names: the render command's (first) scene.
std::string sceneOf(const vkrt::CommandOptions& command) {
  const auto* render = std::get_if<vkrt::RenderOptions>(&command);
  return render ? render->request.scenePath : "";
}

}  // namespace

int main(int argc, char** argv) {
  vkrt::platform::prepareStandardStreams();
  vkrt::CommandOptions command;
  try {
    // (UTF-8 whatever the system's code page: on Windows, from the wide command line.)
    command = vkrt::parseOptions(vkrt::platform::commandLineArguments(argc, argv));
  } catch (...) {
    return vkrt::reportError(std::current_exception(), {}, stderr);
  }
  const vkrt::CommonOptions& common = std::visit([](const auto& o) -> const vkrt::CommonOptions& { return o; }, command);
  if (common.help) {
    std::fputs(vkrt::usageText(), stdout);
    return vkrt::kExitOk;
  }
  if (common.version) {
    std::printf("vkrt %s\n", VKRT_VERSION);
    return vkrt::kExitOk;
  }
  // Before any thread starts and before the Vulkan loader is opened.
  vkrt::skipDriversWithoutDevices();
  // Before any file is opened: a signal stops every command cleanly, its temporary file removed.
  vkrt::installInterruptHandlers();
  if (!common.quiet)
    for (const std::string& w : common.warnings) std::fprintf(stderr, "vkrt: warning: %s\n", w.c_str());
  try {
    return std::visit([](auto& o) { return run(o); }, command);
  } catch (...) {
    return vkrt::reportError(vkrt::currentFailure(), {sceneOf(command), common.quiet}, stderr);
  }
}
