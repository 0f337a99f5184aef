// Command-line options of `vkrt`: argv -> Options. No rendering here.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/image_check.h"
#include "grade/grade_thresholds.h"
#include "errors.h"   // UsageError
#include "render/render.h"

namespace vkrt {

struct Options {
  RenderRequest request;             // scenePath: the first scene
  std::vector<std::string> scenes;   // every scene given, in order (more than one: a batch)
  // Warnings about the command line itself (-o FILE with an extension vkrt does not write),
  // for main() to print; with --strict they are usage errors instead.
  std::vector<std::string> warnings;
  bool stats = false;
  bool quiet = false;            // print nothing but errors (warnings left out)
  bool help = false;
  bool version = false;
  bool listDevices = false;
  // `vkrt diff A.png B.png`: compare two images instead of rendering.
  bool diffCommand = false;
  std::string diffA, diffB;
  // `vkrt merge -o OUT.png TILE.png ...`: assemble crops into their full image.
  bool mergeCommand = false;
  std::vector<std::string> mergeTiles;
  std::string mergeOutput;
  bool allowGaps = false;       // merge: pixels no tile covers stay black
  // `vkrt convert IN OUT`: the image IN written in the format of OUT's name.
  bool convertCommand = false;
  std::string convertInput, convertOutput;

  // `vkrt grade REFS/ SUBMISSIONS/... -o REPORT/`: submissions (folders of images, or scene
  // files to render) against references, into a report folder (cli/grade.h).
  bool gradeCommand = false;
  std::string gradeReferences;
  std::vector<std::string> gradeInputs;
  std::string gradeOutput;
  std::optional<std::string> gradeThresholdsFile;   // --thresholds FILE: per scene
  GradeThresholds gradeThresholds;                  // given once on the command line

  // `vkrt --compare SCENE`: render with both backends, report both and their difference.
  bool compare = false;
  // `vkrt --watch SCENE`: render again at each change of the scene file (cli/watch.h).
  bool watch = false;
  // `vkrt SCENE --check REF.png`: compare the render with REF.
  std::optional<std::string> checkAgainst;
  CheckThresholds thresholds;   // for diff and --check
  bool json = false;            // the comparison as one JSON object on stdout
  std::optional<std::string> heatmapPath;   // --diff FILE.png
  int heatmapScale = 16;        // --diff-scale N: steps at which the heatmap turns red
};

// Throws UsageError.
Options parseOptions(const std::vector<std::string>& args);

// The whole usage, for --help (a usage error prints its one line and points here).
const char* usageText();

}  // namespace vkrt
