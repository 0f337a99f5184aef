// Gradescope's results.json from a grading report.
#include "grade/gradescope.h"

#include <cmath>
#include <cstdio>

#include "util/json.h"

namespace vkrt {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::isfinite(v) ? v : 0.0);
  return buf;
}

std::string box(const PixelRect& r) {
  return "(" + std::to_string(r.x0) + "," + std::to_string(r.y0) + ")-(" + std::to_string(r.x1) + "," +
         std::to_string(r.y1) + ")";
}

// What the student reads under a test: the outcome, why, the key figure and where it failed.
std::string testOutput(const ReportScene& scene, const ReportEntry& e) {
  const Grade& g = e.grade;
  switch (g.outcome) {
    case GradeOutcome::Missing:
      return "missing: the submission has no image for " + scene.name + " (" + scene.name +
             ".png, or .ppm, .pfm, .exr, .jpg; any case, in any folder)";
    case GradeOutcome::Unreadable: {
      std::string s = "unreadable: " + e.source;
      for (const std::string& f : g.failures) s += "\n" + f;
      return s;
    }
    case GradeOutcome::Pass:
    case GradeOutcome::Fail:
      break;
  }
  std::string s = std::string(g.outcome == GradeOutcome::Pass ? "pass" : "fail") + " (" + scene.thresholds + ")";
  for (const std::string& f : g.failures) s += "\n" + f;
  s += "\n" + g.key.label + ": " + g.key.text;
  if (!g.regions.empty()) {
    s += "\nwhere (pixels, x right and y down from the top left):";
    for (const PixelRect& r : g.regions) s += " " + box(r);
    if (g.moreRegions > 0) s += " and " + std::to_string(g.moreRegions) + " more";
  }
  return s;
}

}  // namespace

std::string gradescopeResults(const GradeReport& r, const std::vector<double>& points) {
  const bool several = r.submissions.size() > 1;
  double score = 0;
  std::size_t passed = 0, tests = 0;
  std::string list;
  for (const ReportSubmission& sub : r.submissions)
    for (std::size_t c = 0; c < sub.entries.size(); ++c) {
      const ReportEntry& e = sub.entries[c];
      const bool pass = e.grade.outcome == GradeOutcome::Pass;
      const double worth = c < points.size() ? points[c] : 1.0;
      score += pass ? worth : 0.0;
      passed += pass;
      list += std::string(tests++ ? "," : "") + "\n  {\"name\": " +
              jsonQuoted(several ? sub.name + ": " + r.scenes[c].name : r.scenes[c].name) +
              ", \"score\": " + number(pass ? worth : 0.0) + ", \"max_score\": " + number(worth) +
              ", \"status\": \"" + (pass ? "passed" : "failed") + "\", \"output\": " +
              jsonQuoted(testOutput(r.scenes[c], e)) + "}";
    }
  // The teacher's inputs set aside: a test of no points that only the course staff see
  // (Gradescope's "hidden"), so that the one who can mend them reads it where they look.
  if (!r.setAside.empty()) {
    std::string said = "The autograder's configuration has inputs that were not used:";
    for (const SetAside& a : r.setAside) said += "\n" + a.text();
    list += std::string(tests ? "," : "") +
            "\n  {\"name\": \"autograder configuration\", \"score\": 0, \"max_score\": 0, \"status\": \"failed\", "
            "\"visibility\": \"hidden\", \"output\": " + jsonQuoted(said) + "}";
  }
  std::string output = "vkrt " VKRT_VERSION ": " + std::to_string(passed) + " of " + std::to_string(tests) +
                       (tests == 1 ? " image passes" : " images pass");
  for (const ReportSubmission& sub : r.submissions)
    for (const std::string& note : sub.notes) output += "\n" + (several ? sub.name + ": " : std::string()) + note;
  return "{\"score\": " + number(score) + ", \"execution_time\": " + number(std::round(r.seconds)) +
         ", \"output\": " + jsonQuoted(output) + ",\n\"tests\": [" + list + "\n]}\n";
}

}  // namespace vkrt
