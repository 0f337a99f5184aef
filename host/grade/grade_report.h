// The grading report as files: a self-contained folder that a browser opens with no network
// (index.html: the overview table; pages/: one page per comparison; grade.css and grade.js;
// images/), and the same figures for scripts (summary.json, summary.csv). The images are
// written by the caller at the paths this file names; everything else here.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "grade/grade_compare.h"
#include "grade/grade_inputs.h"   // SetAside

namespace vkrt {

struct ReportScene {
  std::string name;           // as the reference's file spells it
  std::string reference;      // the reference's path, as found
  std::string thresholds;     // GradeThresholds::text()
  std::string keyLabel;       // keyFigureLabel()
  int width = 0, height = 0;  // the reference's size
};

struct ReportEntry {
  Grade grade;
  std::string source;   // the submitted image's path, or the scene file rendered; empty when missing
  bool hasImage = false;   // the submission's image (and its thumbnail) written
  bool hasDiff = false;    // the difference image and the FLIP map written
  int renderStatus = 0;    // a scene file that could not be rendered: its exit status
};

struct ReportSubmission {
  std::string name, folder;
  std::vector<std::string> notes;
  std::vector<ReportEntry> entries;   // one per scene, in the scenes' order
};

struct GradeReport {
  std::string references;   // the folder given
  std::vector<ReportScene> scenes;
  std::vector<ReportSubmission> submissions;
  std::vector<SetAside> setAside;   // the teacher's inputs not used, and why
  double seconds = 0;       // how long the grading took
};

// Where a comparison's images go inside the report folder (relative paths):
// the reference once per scene, and per comparison the submission, its thumbnail and the
// difference image (compare/image_diff.h's heatmap, with its legend) and FLIP's error map
// (compare/flip.h's magma picture).
enum class ReportImage { Submission, Thumbnail, Difference, Flip };
std::string referenceImagePath(std::size_t scene);
std::string entryImagePath(std::size_t submission, std::size_t scene, ReportImage which);
// The folders those paths lie in, to make before writing them.
std::vector<std::string> reportImageFolders(std::size_t submissions);

// The largest size of a thumbnail (the overview's cells).
inline constexpr int kThumbnailWidth = 96, kThumbnailHeight = 72;

// Writes index.html, pages/*.html, grade.css, grade.js, summary.json and summary.csv into
// `folder` (which exists). Throws IoError.
void writeReportPages(const GradeReport& report, const std::string& folder);

// Whether `relative` (a path inside a report folder, '/' between its parts) is one that a
// report writes: index.html, pages/s0001-c001.html, images/s0001/c001-thumb.png, ... (or
// lies in a temporary folder of grade's, ".vkrt-grade-..."); and how its summary.json
// starts: what tells a report this command wrote from a folder of someone's files.
bool isReportPath(const std::string& relative);
inline constexpr const char* kTemporaryPrefix = ".vkrt-grade-";
inline constexpr const char* kSummaryJsonStart = "{\n\"vkrt\": ";

// Counts of the report's comparisons by outcome.
struct OutcomeCounts {
  std::size_t pass = 0, fail = 0, missing = 0, unreadable = 0;
};
OutcomeCounts countOutcomes(const GradeReport& report);

}  // namespace vkrt
