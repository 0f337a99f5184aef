// `vkrt grade REFS/ SUBMISSIONS/... -o REPORT/`: every submitted image (or every scene file
// given, rendered in this run) compared with the reference of its scene, the outcome of each
// on stderr, and a report folder to open in a browser (grade/grade_report.h). The exit status
// is the worst: 5 when an image fails or is missing, 4 when one cannot be read, a scene's
// own status when it cannot be rendered.
#pragma once

#include "cli/options.h"

namespace vkrt {

int gradeCommand(const GradeOptions& options);

}  // namespace vkrt
