// Command-line options of `vkrt`: argv -> the options of one command (render, diff, merge,
// convert, grade), each its own struct. No rendering here. The options themselves are the
// rows of each command's table (cli/options.cpp, cli/option_table.h).
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "compare/image_check.h"
#include "grade/grade_thresholds.h"
#include "util/errors.h"   // UsageError
#include "net/tev_display.h"
#include "render/render.h"

namespace vkrt {

// What every command's options have.
struct CommonOptions {
  bool quiet = false;     // print nothing but errors (warnings left out)
  bool help = false;
  bool version = false;
  // Warnings about the command line itself (-o FILE with an extension vkrt does not write),
  // for main() to print; with --strict they are usage errors instead.
  std::vector<std::string> warnings;
};

// What diff, --check and --compare compare by, and how they report.
struct ComparisonOptions {
  CheckThresholds thresholds;
  bool json = false;                        // the comparison as one JSON object on stdout
  std::optional<std::string> heatmapPath;   // --diff FILE.png
  std::optional<std::string> flipMapPath;   // --flip-map FILE.png
  int heatmapScale = 16;                    // --diff-scale N: steps at which the heatmap turns red
};

// `vkrt [options] SCENE.test ...`: render (one scene, a batch, --compare, --watch, --check),
// or --list-devices; `vkrt view [options] SCENE.test` (the same options, and --bind, --port).
struct RenderOptions : CommonOptions {
  RenderRequest request;             // scenePath: the first scene
  std::vector<std::string> scenes;   // every scene given, in order (more than one: a batch)
  bool stats = false;
  bool listDevices = false;
  bool compare = false;   // --compare: render with both backends, report both and their difference
  bool watch = false;     // --watch: render again at each change of the scene file (cli/watch.h)
  std::optional<std::string> checkAgainst;   // --check REF.png: compare the render with REF
  ComparisonOptions comparison;
  std::optional<DisplayAddress> display;     // --display-server HOST:PORT (net/tev_display.h)
  // vkrt view: --watch shown on a page in the browser (cli/view_scene.h), served on
  // bind:port (port 0: a free one). --bind and --port go only with view.
  bool view = false;
  std::string bind = "127.0.0.1";
  int port = 0;
  bool serverOptionGiven = false;
};

// `vkrt diff A.png B.png`: compare two images. Its command line is the render command's.
struct DiffOptions : CommonOptions {
  std::string a, b;
  ComparisonOptions comparison;
};

// `vkrt merge -o OUT.png TILE.png ...`: assemble crops (or sample batches) into their image.
struct MergeOptions : CommonOptions {
  std::vector<std::string> tiles;
  std::string output;
  bool allowGaps = false;   // pixels no tile covers stay black
  bool strict = false;
};

// `vkrt convert IN OUT`: the image IN written in the format of OUT's name.
struct ConvertOptions : CommonOptions {
  std::string input, output;
};

// `vkrt grade REFS/ SUBMISSIONS/... -o REPORT/`: submissions (folders of images, or scene
// files to render) against references, into a report folder (cli/grade.h).
struct GradeOptions : CommonOptions {
  RenderRequest request;   // for the scenes rendered
  std::string references;
  std::vector<std::string> inputs;
  std::string output;
  std::optional<std::string> thresholdsFile;   // --thresholds FILE: per scene
  std::optional<std::string> gradescopePath;   // --gradescope FILE: Gradescope's results.json
  bool oneStudent = false;                      // --one-student: each folder given is one student's
  bool strict = false;                          // --strict: a teacher's input set aside is an error
  GradeThresholds thresholds;                  // given once on the command line
  int heatmapScale = 16;
};

using CommandOptions = std::variant<RenderOptions, DiffOptions, MergeOptions, ConvertOptions, GradeOptions>;

// Throws UsageError.
CommandOptions parseOptions(const std::vector<std::string>& args);

// The whole usage, for --help (a usage error prints its one line and points here).
const char* usageText();

// Every option that --help, its paragraphs or the man page name, each command's in its
// table's order: "--output", "-o", ... (for the test that holds them together).
std::vector<std::string> documentedOptions();

}  // namespace vkrt
