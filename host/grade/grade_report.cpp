// The grading report's pages, style, script and summaries.
#include "grade/grade_report.h"

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>

#include "grade.css.h"   // kGradeCss: host/grade/report/grade.css, embedded by the build
#include "grade.js.h"    // kGradeJs: host/grade/report/grade.js
#include "util/counted.h"
#include "util/json.h"
#include "image/atomic_file.h"

namespace vkrt {

namespace {

// Which FLIP a grade's figures are: HDR-FLIP of two float images, else LDR-FLIP.
std::string flipKind(const FlipStats& f) { return f.hdr ? "HDR-FLIP" : "LDR-FLIP"; }

// The page's look (host/grade/report/grade.css): light or dark as the reader's system is;
// pass, fail and missing told apart by colour and by word. What the pages do with JavaScript
// (host/grade/report/grade.js; without it they read the same): the overview's columns sort on
// a click or Enter (numbers as numbers; the address keeps the order, #sort=COLUMN or
// #sort=COLUMN-down, so that a sorted view can be kept or sent), and a comparison page shows
// the reference and the submission in one frame, split where the slider is ('t' flips). Both
// are embedded at build time (CMakeLists.txt, vkrt_embed) and written as they are.
std::string embedded(const unsigned char* bytes, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(bytes), size);
}

std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

// `v` as `fmt` says; -0 (a mean of zeros, negated) as 0.
std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v == 0 ? 0.0 : v);
  return buf;
}

// Whether the two images were compared (the figures mean something): both read, one size.
bool compared(const Grade& g) {
  return g.outcome == GradeOutcome::Pass || (g.outcome == GradeOutcome::Fail && std::isfinite(g.key.value));
}

// A number for JSON: finite ones as they are, infinity (the PSNR of identical images) as null.
std::string jsonNumber(double v) { return std::isfinite(v) ? format("%.6g", v) : "null"; }

std::string pageName(std::size_t submission, std::size_t scene) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "pages/s%04zu-c%03zu.html", submission + 1, scene + 1);
  return buf;
}

std::string submissionFolder(std::size_t submission) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "images/s%04zu", submission + 1);
  return buf;
}

void writeText(const std::string& path, const std::string& text) {
  writeFileAtomic(path, ".tmp", [&](ByteSink& file) {
    file.write(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  });
}

std::string head(const std::string& title, const std::string& up) {
  return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<link rel=\"icon\" href=\"data:,\">\n<title>" + escaped(title) + "</title>\n"
         "<link rel=\"stylesheet\" href=\"" + up + "grade.css\">\n</head>\n<body>\n";
}

std::string foot(const std::string& up) { return "<script src=\"" + up + "grade.js\"></script>\n</body>\n</html>\n"; }

// "37 (0.012%)" or "size differs", or the outcome for one without figures.
std::string cellFigure(const ReportEntry& e) {
  if (e.grade.outcome == GradeOutcome::Missing || e.grade.outcome == GradeOutcome::Unreadable) return "";
  return e.grade.key.text;
}

// The overview's sort value of a cell: its key figure, failures after passes, missing last.
double sortValue(const ReportEntry& e) {
  switch (e.grade.outcome) {
    case GradeOutcome::Pass: return std::isfinite(e.grade.key.value) ? e.grade.key.value : 1e300;
    case GradeOutcome::Fail: return 1e15 + (std::isfinite(e.grade.key.value) ? e.grade.key.value : 1e14);
    case GradeOutcome::Unreadable: return 2e15;
    case GradeOutcome::Missing: return 3e15;
  }
  return 0;
}

// The boxes around failing pixels over an image of `width` x `height`, in shares of it, so
// that they stay in place however large the image is shown.
std::string regionBoxes(const Grade& g, int width, int height) {
  std::string s;
  for (const PixelRect& r : g.regions)
    s += "<span class=\"region\" style=\"left:" + format("%.3f", 100.0 * r.x0 / width) + "%;top:" +
         format("%.3f", 100.0 * r.y0 / height) + "%;width:" + format("%.3f", 100.0 * r.width() / width) +
         "%;height:" + format("%.3f", 100.0 * r.height() / height) + "%\" title=\"" + std::to_string(r.width()) +
         "x" + std::to_string(r.height()) + " at " + std::to_string(r.x0) + "," + std::to_string(r.y0) + "\"></span>";
  return s;
}

std::string indexPage(const GradeReport& r) {
  const OutcomeCounts n = countOutcomes(r);
  const std::size_t total = n.pass + n.fail + n.missing + n.unreadable;
  std::string s = head("Grading: " + counted(r.submissions.size(), "submission", "submissions") + ", " +
                           counted(r.scenes.size(), "scene", "scenes"), "");
  s += "<h1>Grading report</h1>\n<p>" + counted(r.submissions.size(), "submission", "submissions") + " against " +
       counted(r.scenes.size(), "reference", "references") + " in <code>" + escaped(r.references) + "</code>: <strong>" +
       std::to_string(n.pass) + " of " + std::to_string(total) + " pass</strong>, " + std::to_string(n.fail) +
       " fail, " + std::to_string(n.missing) + " missing" +
       (n.unreadable ? ", " + std::to_string(n.unreadable) + " unreadable" : "") + ". Graded by vkrt " +
       VKRT_VERSION + format(" in %.1f s.", r.seconds) +
       " Click a column's heading to sort by it; a cell opens its comparison. The figures for scripts: "
       "<a href=\"summary.json\">summary.json</a>, <a href=\"summary.csv\">summary.csv</a>.</p>\n";
  if (!r.setAside.empty()) {   // the teacher's inputs not used: before anything graded without them
    s += "<section class=\"set-aside\">\n<h2>Set aside: " +
         counted(r.setAside.size(), "input", "inputs") + " of yours not used</h2>\n<ul>\n";
    for (const SetAside& a : r.setAside) s += "<li><code>" + escaped(a.text()) + "</code></li>\n";
    s += "</ul>\n</section>\n";
  }
  s += "<table class=\"sortable\" id=\"overview\">\n<thead><tr><th>submission</th><th>passed</th>";
  for (const ReportScene& sc : r.scenes)
    s += "<th>" + escaped(sc.name) + "<br><span class=\"key\">" + escaped(sc.keyLabel) + "</span></th>";
  s += "</tr></thead>\n<tbody>\n";
  std::vector<std::size_t> passedPerScene(r.scenes.size(), 0);
  for (std::size_t i = 0; i < r.submissions.size(); ++i) {
    const ReportSubmission& sub = r.submissions[i];
    std::size_t passed = 0;
    for (std::size_t c = 0; c < sub.entries.size(); ++c)
      if (sub.entries[c].grade.outcome == GradeOutcome::Pass) ++passed, ++passedPerScene[c];
    s += "<tr><th scope=\"row\">" + escaped(sub.name) + "</th><td class=\"num\" data-sort=\"" + std::to_string(passed) +
         "\">" + std::to_string(passed) + "/" + std::to_string(sub.entries.size()) + "</td>";
    for (std::size_t c = 0; c < sub.entries.size(); ++c) {
      const ReportEntry& e = sub.entries[c];
      const char* outcome = outcomeName(e.grade.outcome);
      s += "<td class=\"" + std::string(outcome) + "\" data-sort=\"" + format("%.17g", sortValue(e)) + "\">";
      std::string inner;
      if (e.hasImage)
        inner += "<img class=\"thumb\" loading=\"lazy\" src=\"" + entryImagePath(i, c, ReportImage::Thumbnail) +
                 "\" alt=\"\">";
      inner += "<span class=\"word\">" + std::string(outcome) + "</span> <span class=\"num\">" +
               escaped(cellFigure(e)) + "</span>";
      if (e.grade.outcome == GradeOutcome::Missing)
        s += inner;
      else
        s += "<a href=\"" + pageName(i, c) + "\">" + inner + "</a>";
      s += "</td>";
    }
    s += "</tr>\n";
  }
  s += "</tbody>\n<tfoot><tr><th>passed</th><td></td>";
  for (std::size_t c = 0; c < r.scenes.size(); ++c)
    s += "<td class=\"num\">" + std::to_string(passedPerScene[c]) + "/" + std::to_string(r.submissions.size()) + "</td>";
  s += "</tr></tfoot>\n</table>\n";
  s += "<h2>Scenes</h2>\n<table>\n<thead><tr><th>scene</th><th>reference</th><th>size</th><th>passes when</th></tr></thead>\n<tbody>\n";
  for (std::size_t c = 0; c < r.scenes.size(); ++c) {
    const ReportScene& sc = r.scenes[c];
    s += "<tr><td>" + escaped(sc.name) + "</td><td><a href=\"" + referenceImagePath(c) + "\">" + escaped(sc.reference) +
         "</a></td><td class=\"num\">" + std::to_string(sc.width) + "x" + std::to_string(sc.height) + "</td><td><code>" +
         escaped(sc.thresholds) + "</code></td></tr>\n";
  }
  s += "</tbody>\n</table>\n";
  std::string notes;
  for (const ReportSubmission& sub : r.submissions)
    for (const std::string& note : sub.notes) notes += "<li>" + escaped(sub.name) + ": " + escaped(note) + "</li>\n";
  if (!notes.empty()) s += "<h2>Notes</h2>\n<ul class=\"notes\">\n" + notes + "</ul>\n";
  return s + foot("");
}

// The bias test's worst square: "2.31: green, square (32,16), -1.8 levels, standard error 0.77".
std::string biasZText(const BiasTest& b) {
  static const char* const kChannels[] = {"red", "green", "blue"};
  const SquareBias& w = b.worst;
  return (std::isfinite(w.z) ? format("%.3g", w.z) : std::string("infinite")) + ": " + kChannels[w.channel] +
         ", square (" + std::to_string(w.square.x0) + "," + std::to_string(w.square.y0) + "), " +
         format("%+.3g", w.mean) + " levels, standard error " + format("%.3g", w.standardError) +
         (w.saturated && w.mean < 0 ? " (clamped at 255: darkness excused)" : "");
}

std::string figureRow(const std::string& name, const std::string& value) {
  return "<tr><th scope=\"row\">" + name + "</th><td class=\"num\">" + value + "</td></tr>\n";
}

// A comparison's figures, as a table.
std::string figuresTable(const Grade& g) {
  std::string s;
  s += "<h2>Figures</h2>\n<table>\n";
  s += figureRow("largest channel difference", std::to_string(g.maxDiff) + "/255");
  s += figureRow("RMSE", format("%.4f/255", g.rmse));
  s += figureRow("PSNR", std::isfinite(g.psnr) ? format("%.2f dB", g.psnr) : "infinite (identical)");
  const double pixels = static_cast<double>(g.width) * g.height;
  auto share = [&](long long n) { return std::to_string(n) + format(" (%.4g%%)", 100.0 * static_cast<double>(n) / pixels); };
  s += figureRow("pixels that differ", share(g.differing));
  s += figureRow("pixels over 1/255", share(g.over1));
  s += figureRow("pixels over 2/255", share(g.over2));
  s += figureRow("bias, mean(reference &minus; image)", format("%.4f", g.stats.bias));
  s += figureRow("variance of (image &minus; reference)", format("%.4f", g.stats.variance));
  s += figureRow("bias z: the largest of the 16x16 squares' (per channel, against its standard error)",
                 biasZText(g.bias));
  s += figureRow("FLIP error (" + flipKind(g.flip) + ", " + format("%.3g", g.flip.pixelsPerDegree) +
                     " pixels per degree" +
                     (g.flip.hdr ? ", exposures " + format("%.3g", g.flip.exposures.start) + " to " +
                                       format("%.3g", g.flip.exposures.stop) + " stops"
                                 : std::string()) +
                     "): mean",
                 format("%.4f", g.flip.mean));
  s += figureRow("FLIP error: median, 95th, 99th percentile, max",
                 format("%.4f", g.flip.median) + ", " + format("%.4f", g.flip.p95) + ", " + format("%.4f", g.flip.p99) +
                     ", " + format("%.4f", g.flip.max));
  s += "</table>\n";
  return s;
}

std::string entryPage(const GradeReport& r, std::size_t i, std::size_t c) {
  const ReportSubmission& sub = r.submissions[i];
  const ReportScene& sc = r.scenes[c];
  const ReportEntry& e = sub.entries[c];
  const Grade& g = e.grade;
  const std::string outcome = outcomeName(g.outcome);
  std::string s = head(sub.name + ": " + sc.name + " (" + outcome + ")", "../");
  // Links: the overview, the same scene of the neighbouring submissions, the neighbouring
  // scenes of this submission (those with a page).
  auto link = [&](std::size_t si, std::size_t ci, const std::string& text) {
    if (si >= r.submissions.size() || ci >= r.scenes.size() ||
        r.submissions[si].entries[ci].grade.outcome == GradeOutcome::Missing)
      return std::string();
    return " &middot; <a href=\"../" + pageName(si, ci) + "\">" + text + "</a>";
  };
  s += "<nav><a href=\"../index.html\">overview</a>" + link(i - 1, c, "previous submission") +
       link(i + 1, c, "next submission") + link(i, c - 1, "previous scene") + link(i, c + 1, "next scene") + "</nav>\n";
  s += "<h1>" + escaped(sub.name) + ": " + escaped(sc.name) + " <span class=\"" + outcome + "\"><span class=\"word\">" +
       outcome + "</span></span></h1>\n";
  s += "<p>" + escaped(e.source) + " against the reference " + escaped(sc.reference) + "; passes when: <code>" +
       escaped(sc.thresholds) + "</code>.</p>\n";
  if (!g.failures.empty()) {
    s += "<ul class=\"failures\">\n";
    for (const std::string& f : g.failures) s += "<li>" + escaped(f) + "</li>\n";
    s += "</ul>\n";
  }
  if (e.hasImage) {
    const std::string ref = "../" + referenceImagePath(c), img = "../" + entryImagePath(i, c, ReportImage::Submission);
    const bool sameSize = g.width == sc.width && g.height == sc.height;
    const std::string boxes = sameSize ? regionBoxes(g, sc.width, sc.height) : "";
    if (!g.regions.empty())
      s += "<p>Boxed in magenta: the " + counted(g.regions.size(), "region", "regions") + " of failing pixels" +
           (g.moreRegions ? " with the most of them (" + std::to_string(g.moreRegions) + " smaller ones not boxed)" : "") +
           ".</p>\n";
    s += "<div class=\"images\">\n";
    s += "<figure><div class=\"frame\"><img src=\"" + ref + "\" width=\"" + std::to_string(sc.width) + "\" height=\"" +
         std::to_string(sc.height) + "\" alt=\"the reference image\">" + boxes + "</div><figcaption>reference</figcaption></figure>\n";
    s += "<figure><div class=\"frame\"><img src=\"" + img + "\" width=\"" + std::to_string(g.width) + "\" height=\"" +
         std::to_string(g.height) + "\" alt=\"the submitted image\">" + boxes + "</div><figcaption>submission</figcaption></figure>\n";
    if (e.hasDiff)
      s += "<figure><div class=\"frame\"><img src=\"../" + entryImagePath(i, c, ReportImage::Difference) +
           "\" alt=\"the difference: black where equal, blue to red as it grows\"></div><figcaption>difference: black "
           "where equal, blue to red as it grows (legend below it)</figcaption></figure>\n";
    if (e.hasDiff)
      s += "<figure><div class=\"frame\"><img src=\"../" + entryImagePath(i, c, ReportImage::Flip) +
           "\" width=\"" + std::to_string(g.width) + "\" height=\"" + std::to_string(g.height) +
           "\" alt=\"the FLIP error map: black for none, through purple and orange to pale yellow for the "
           "largest\"></div><figcaption>FLIP error (" + flipKind(g.flip) + ", mean " +
           format("%.4f", g.flip.mean) + "): black none, purple, orange, pale yellow 1</figcaption></figure>\n";
    s += "</div>\n";
    if (sameSize)
      s += "<section class=\"compare\" hidden>\n<h2>Reference and submission in one frame</h2>\n<div class=\"split\"><div class=\"frame\"><img src=\"" +
           ref + "\" width=\"" + std::to_string(sc.width) + "\" height=\"" + std::to_string(sc.height) +
           "\" alt=\"the reference image\"><img class=\"top\" src=\"" + img + "\" alt=\"the submitted image\">" + boxes +
           "</div>\n<input type=\"range\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"where the submission starts\"></div>\n"
           "<p>Left of the split: the reference; right of it: the submission. Drag the slider, or press t to flip "
           "between the two.</p>\n</section>\n";
  }
  if (g.outcome != GradeOutcome::Unreadable && g.width == sc.width && g.height == sc.height) s += figuresTable(g);
  return s + foot("../");
}

std::string summaryJson(const GradeReport& r) {
  const OutcomeCounts n = countOutcomes(r);
  std::string s = kSummaryJsonStart + jsonQuoted(VKRT_VERSION) + ",\n\"references\": " + jsonQuoted(r.references) +
                  ",\n\"set_aside\": [";
  for (std::size_t k = 0; k < r.setAside.size(); ++k)
    s += std::string(k ? "," : "") + "\n  {\"file\": " + jsonQuoted(r.setAside[k].file) +
         ", \"line\": " + std::to_string(r.setAside[k].line) + ", \"reason\": " + jsonQuoted(r.setAside[k].reason) + "}";
  s += std::string(r.setAside.empty() ? "" : "\n") + "]" +
       ",\n\"counts\": {\"pass\": " + std::to_string(n.pass) + ", \"fail\": " + std::to_string(n.fail) +
                  ", \"missing\": " + std::to_string(n.missing) + ", \"unreadable\": " + std::to_string(n.unreadable) +
                  "},\n\"scenes\": [";
  for (std::size_t c = 0; c < r.scenes.size(); ++c) {
    const ReportScene& sc = r.scenes[c];
    s += std::string(c ? "," : "") + "\n  {\"name\": " + jsonQuoted(sc.name) + ", \"reference\": " + jsonQuoted(sc.reference) +
         ", \"width\": " + std::to_string(sc.width) + ", \"height\": " + std::to_string(sc.height) +
         ", \"thresholds\": " + jsonQuoted(sc.thresholds) + ", \"key_figure\": " + jsonQuoted(sc.keyLabel) + "}";
  }
  s += "\n],\n\"submissions\": [";
  for (std::size_t i = 0; i < r.submissions.size(); ++i) {
    const ReportSubmission& sub = r.submissions[i];
    s += std::string(i ? "," : "") + "\n  {\"name\": " + jsonQuoted(sub.name) + ", \"folder\": " + jsonQuoted(sub.folder) +
         ", \"notes\": [";
    for (std::size_t k = 0; k < sub.notes.size(); ++k) s += (k ? ", " : "") + jsonQuoted(sub.notes[k]);
    s += "],\n   \"results\": [";
    for (std::size_t c = 0; c < sub.entries.size(); ++c) {
      const ReportEntry& e = sub.entries[c];
      const Grade& g = e.grade;
      s += std::string(c ? "," : "") + "\n    {\"scene\": " + jsonQuoted(r.scenes[c].name) + ", \"status\": \"" +
           outcomeName(g.outcome) + "\", \"image\": " + jsonQuoted(e.source);
      if (g.outcome != GradeOutcome::Missing) s += ", \"page\": " + jsonQuoted(pageName(i, c));
      if (g.outcome == GradeOutcome::Pass || g.outcome == GradeOutcome::Fail)
        s += ", \"width\": " + std::to_string(g.width) + ", \"height\": " + std::to_string(g.height);
      if (compared(g)) {
        s += ", \"key_figure\": " + jsonNumber(g.key.value);
        s += ", \"max_channel_diff\": " + std::to_string(g.maxDiff) + ", \"rmse\": " + jsonNumber(g.rmse) +
             ", \"psnr_db\": " + jsonNumber(g.psnr) + ", \"pixels_differing\": " + std::to_string(g.differing) +
             ", \"pixels_over_1\": " + std::to_string(g.over1) + ", \"pixels_over_2\": " + std::to_string(g.over2) +
             ", \"bias\": " + jsonNumber(g.stats.bias) + ", \"variance\": " + jsonNumber(g.stats.variance) +
             ", \"flip\": {\"kind\": " + (g.flip.hdr ? "\"hdr\"" : "\"ldr\"") + ", \"mean\": " + jsonNumber(g.flip.mean) + ", \"median\": " + jsonNumber(g.flip.median) +
             ", \"p95\": " + jsonNumber(g.flip.p95) + ", \"p99\": " + jsonNumber(g.flip.p99) +
             ", \"max\": " + jsonNumber(g.flip.max) + "}";
        const SquareBias& w = g.bias.worst;
        s += ", \"bias_z\": {\"z\": " + jsonNumber(w.z) + ", \"square\": [" + std::to_string(w.square.x0) + ", " +
             std::to_string(w.square.y0) + ", " + std::to_string(w.square.x1) + ", " + std::to_string(w.square.y1) +
             "], \"channel\": " + std::to_string(w.channel) + ", \"mean\": " + jsonNumber(w.mean) +
             ", \"standard_error\": " + jsonNumber(w.standardError) + "}";
      }
      s += ", \"failures\": [";
      for (std::size_t k = 0; k < g.failures.size(); ++k) s += (k ? ", " : "") + jsonQuoted(g.failures[k]);
      s += "]}";
    }
    s += "]}";
  }
  return s + "\n]\n}\n";
}

// A CSV field of text (a name, a path, a message): quoted when it holds a comma, a quote or
// a line break (RFC 4180), and a leading = + - @ or tab made harmless with a ' before it, so
// that a spreadsheet shows a folder named "=HYPERLINK(...)" instead of running it.
std::string csvField(std::string v) {
  if (!v.empty() && std::string("=+-@\t\r").find(v[0]) != std::string::npos) v = "'" + v;
  if (v.find_first_of(",\"\n\r") == std::string::npos) return v;
  std::string q = "\"";
  for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string summaryCsv(const GradeReport& r) {
  std::string s = "submission,scene,status,key_figure,max_channel_diff,rmse,psnr_db,pixels_differing,pixels_over_1,"
                  "pixels_over_2,bias,variance,flip_mean,flip_median,flip_p95,flip_p99,flip_max,bias_z,image,failures\n";
  for (const ReportSubmission& sub : r.submissions)
    for (std::size_t c = 0; c < sub.entries.size(); ++c) {
      const Grade& g = sub.entries[c].grade;
      const bool figures = compared(g);
      std::string failures;
      for (const std::string& f : g.failures) failures += (failures.empty() ? "" : "; ") + f;
      s += csvField(sub.name) + "," + csvField(r.scenes[c].name) + "," + outcomeName(g.outcome) + ",";
      if (figures)
        s += format("%.6g", g.key.value) + "," + std::to_string(g.maxDiff) + "," + format("%.6g", g.rmse) + "," +
             (std::isfinite(g.psnr) ? format("%.6g", g.psnr) : "inf") + "," + std::to_string(g.differing) + "," +
             std::to_string(g.over1) + "," + std::to_string(g.over2) + "," + format("%.6g", g.stats.bias) + "," +
             format("%.6g", g.stats.variance) + "," + format("%.6g", g.flip.mean) + "," + format("%.6g", g.flip.median) +
             "," + format("%.6g", g.flip.p95) + "," + format("%.6g", g.flip.p99) + "," + format("%.6g", g.flip.max) + "," +
             (std::isfinite(g.bias.worst.z) ? format("%.6g", g.bias.worst.z) : "inf") + ",";
      else
        s += ",,,,,,,,,,,,,,,";
      s += csvField(sub.entries[c].source) + "," + csvField(failures) + "\n";
    }
  return s;
}

// Whether `text` from `at` is `prefix` and then one or more digits; `at` moves past them.
bool digitsAfter(const std::string& text, std::size_t& at, const char* prefix) {
  const std::size_t n = std::strlen(prefix);
  if (text.compare(at, n, prefix) != 0) return false;
  at += n;
  const std::size_t start = at;
  while (at < text.size() && text[at] >= '0' && text[at] <= '9') ++at;
  return at > start;
}

// Whether `text` from `at` to its end is one of `endings`.
bool rest(const std::string& text, std::size_t at, std::initializer_list<const char*> endings) {
  for (const char* e : endings)
    if (text.compare(at, std::string::npos, e) == 0) return true;
  return false;
}

}  // namespace

std::string referenceImagePath(std::size_t scene) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "images/ref/c%03zu.png", scene + 1);
  return buf;
}

std::string entryImagePath(std::size_t submission, std::size_t scene, ReportImage which) {
  const char* suffix = "";
  switch (which) {
    case ReportImage::Submission: suffix = ""; break;
    case ReportImage::Thumbnail: suffix = "-thumb"; break;
    case ReportImage::Difference: suffix = "-diff"; break;
    case ReportImage::Flip: suffix = "-flip"; break;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "/c%03zu%s.png", scene + 1, suffix);
  return submissionFolder(submission) + buf;
}

std::vector<std::string> reportImageFolders(std::size_t submissions) {
  std::vector<std::string> folders{"images", "images/ref", "pages"};
  for (std::size_t i = 0; i < submissions; ++i) folders.push_back(submissionFolder(i));
  return folders;
}

bool isReportPath(const std::string& relative) {
  for (const char* entry : {"index.html", "grade.css", "grade.js", "summary.json", "summary.csv", "images", "pages",
                            "images/ref"})
    if (relative == entry) return true;
  if (relative.rfind(kTemporaryPrefix, 0) == 0) return true;
  std::size_t at = 0;
  if (relative.rfind("pages/", 0) == 0)   // pages/sNNNN-cNNN.html
    return digitsAfter(relative, at = 6, "s") && digitsAfter(relative, at, "-c") && rest(relative, at, {".html"});
  if (relative.rfind("images/ref/", 0) == 0)   // images/ref/cNNN.png
    return digitsAfter(relative, at = 11, "c") && rest(relative, at, {".png"});
  if (relative.rfind("images/", 0) == 0 && digitsAfter(relative, at = 7, "s")) {   // images/sNNNN[/cNNN[-x].png]
    if (at == relative.size()) return true;
    return digitsAfter(relative, at, "/c") && rest(relative, at, {".png", "-thumb.png", "-diff.png", "-flip.png"});
  }
  return false;
}

OutcomeCounts countOutcomes(const GradeReport& report) {
  OutcomeCounts n;
  for (const ReportSubmission& sub : report.submissions)
    for (const ReportEntry& e : sub.entries) {
      switch (e.grade.outcome) {
        case GradeOutcome::Pass: ++n.pass; break;
        case GradeOutcome::Fail: ++n.fail; break;
        case GradeOutcome::Missing: ++n.missing; break;
        case GradeOutcome::Unreadable: ++n.unreadable; break;
      }
    }
  return n;
}

void writeReportPages(const GradeReport& report, const std::string& folder) {
  writeText(folder + "/grade.css", embedded(kGradeCss, kGradeCssSize));
  writeText(folder + "/grade.js", embedded(kGradeJs, kGradeJsSize));
  for (std::size_t i = 0; i < report.submissions.size(); ++i)
    for (std::size_t c = 0; c < report.scenes.size(); ++c)
      if (report.submissions[i].entries[c].grade.outcome != GradeOutcome::Missing)
        writeText(folder + "/" + pageName(i, c), entryPage(report, i, c));
  writeText(folder + "/summary.json", summaryJson(report));
  writeText(folder + "/summary.csv", summaryCsv(report));
  writeText(folder + "/index.html", indexPage(report));   // last: a folder with it is whole
}

}  // namespace vkrt
