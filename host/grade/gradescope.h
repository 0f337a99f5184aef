// Gradescope's autograder results (its results.json: a list of tests, each with a name, a
// score out of max_score, passed or failed, and output the student reads): a test per scene
// of each submission graded, named for the scene (and the submission, when a class is
// graded), worth that scene's points when it passes and nothing otherwise, its output saying
// what failed and where. Built from a GradeReport; knows nothing of files.
#pragma once

#include <string>
#include <vector>

#include "grade/grade_report.h"

namespace vkrt {

// The results as JSON; `points[c]` is scene c's worth (GradeThresholds::points).
std::string gradescopeResults(const GradeReport& report, const std::vector<double>& points);

}  // namespace vkrt
