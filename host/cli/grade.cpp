// vkrt grade: find, render, compare (on every core), write the report folder, swap it in.
#include "cli/grade.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "cli/exit_status.h"
#include "cli/run_files.h"   // RefusedOutput
#include "cli/warning_printers.h"
#include "util/counted.h"
#include "util/errors.h"
#include "grade/grade_guard.h"
#include "grade/grade_inputs.h"
#include "grade/grade_report.h"
#include "grade/gradescope.h"
#include "image/atomic_file.h"
#include "image/encode.h"
#include "image/image_file.h"
#include "image/image_read.h"
#include "image/png.h"   // isPngFile
#include "image/thumbnail.h"
#include "platform/error_text.h"
#include "platform/file_changes.h"
#include "platform/file_names.h"
#include "platform/file_permissions.h"
#include "platform/path_text.h"
#include "util/interrupt.h"
#include "util/parallel_for.h"
#include "render/progress.h"
#include "render/render.h"
#include "scene/parse.h"
#include "util/text.h"   // abbreviated

namespace vkrt {

namespace fs = std::filesystem;
using platform::pathFromUtf8;
using platform::utf8FromPath;

namespace {

// A folder, as one name per folder (links and '..' resolved, no trailing '/'), for telling
// folders apart.
fs::path canonicalFolder(const std::string& path) {
  fs::path p = fs::absolute(pathFromUtf8(path)).lexically_normal();
  if (p.filename().empty() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();   // "report/"
  return pathFromUtf8(platform::canonicalName(utf8FromPath(p)));
}

// Whether `folder` may take a new report: it is empty, or it holds a report this command
// wrote (its summary.json says so) and nothing else, at any depth (a file someone added is
// kept by refusing).
bool replaceableReport(const fs::path& folder) {
  std::error_code ec;
  bool empty = true;   // but for temporary folders that a killed run left
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string relative = it->path().lexically_relative(folder).generic_string();
    if (!isReportPath(relative)) return false;
    if (relative.rfind(kTemporaryPrefix, 0) != 0) empty = false;
  }
  if (ec) return false;
  if (empty) return true;
  std::ifstream f(folder / "summary.json", std::ios::binary);
  if (!f) return false;
  char buf[16] = {};
  f.read(buf, sizeof buf - 1);
  return std::string(buf, static_cast<std::size_t>(f.gcount())).rfind(kSummaryJsonStart, 0) == 0;
}

// Where the report goes: refused (UsageError) when it is, holds or lies in a folder the run
// reads, or is something other than a folder this command may fill. Returns its path with
// links resolved (a link to a folder is written through, and stays a link).
fs::path checkReportFolder(const std::string& output, const std::vector<std::string>& inputs) {
  const fs::path out = canonicalFolder(output);
  for (const std::string& in : inputs) {
    const fs::path p = canonicalFolder(in);
    if (pathInside(p, out) || pathInside(out, p))
      throw RefusedOutput("-o " + abbreviated(output) + ": the report folder " +
                          (out == p ? "is" : pathInside(out, p) ? "lies in" : "holds") +
                          " '" + abbreviated(in) + "', which this run reads; name a folder apart from them");
  }
  std::error_code ec;
  fs::file_status st = fs::status(out, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) throw RefusedOutput("-o " + abbreviated(output) + " is a file, not a folder for the report");
    if (!replaceableReport(out))
      throw RefusedOutput("-o " + abbreviated(output) + " is a folder that holds other files than a vkrt report; "
                          "name a new folder (or an empty one, or an earlier report, which is replaced)");
    return out;
  }
  const fs::path parent = out.parent_path();
  if (!fs::is_directory(parent, ec))
    throw IoError("cannot write the report '" + abbreviated(output) + "': the folder '" +
                  abbreviated(utf8FromPath(parent)) + "' does not exist");
  return out;
}

// Where --gradescope's file goes: refused (RefusedOutput) when it is or lies in something the
// run reads or the report folder (which is replaced whole), IoError when it cannot be written
// (a folder, a missing folder on the way: atomic_file.h). Checked before anything is graded.
void checkGradescopeFile(const std::string& path, const std::vector<std::string>& inputs, const fs::path& report) {
  const fs::path file = canonicalFolder(resolveOutputFile(path).target);
  std::vector<std::string> around = inputs;
  around.push_back(utf8FromPath(report));
  for (const std::string& in : around)
    if (pathInside(file, canonicalFolder(in)))
      throw RefusedOutput("--gradescope " + abbreviated(path) + ": " +
                          (file == canonicalFolder(in) ? "is" : "lies in") + " '" + abbreviated(in) +
                          "', which this run " + (in == utf8FromPath(report) ? "writes whole" : "reads") +
                          "; name a file apart from them");
  checkOutputWritable(path);
}

// A fresh folder in `folder`, named .vkrt-grade-XXXXXX, readable as a new folder would be.
std::string temporaryFolderIn(const fs::path& folder) {
  std::string pattern = utf8FromPath(folder / (std::string(kTemporaryPrefix) + "XXXXXX"));
  if (!platform::createTemporaryDirectory(pattern))
    throw IoError("cannot write the report in '" + abbreviated(utf8FromPath(folder)) + "': " + std::strerror(errno));
  // It is made for this user alone; the report is for whoever may read a new folder.
  platform::setMode(pattern, 0777 & ~platform::creationMask());
  return pattern;
}

// Where the report is written until it is whole: beside a new report folder, inside one that
// exists (an empty folder, an earlier report; perhaps a mount point, which cannot be renamed).
std::string temporaryFolderFor(const fs::path& out) {
  std::error_code ec;
  return temporaryFolderIn(fs::exists(out, ec) ? out : out.parent_path());
}

// Moves every entry of `from` but those in `except` into `to` (renames, one folder apart, by
// the platform's replaceFile: on Windows it waits a moment for a viewer that holds a file of
// the report); on a failure, moves back what it moved and throws IoError naming `out`.
void moveEntries(const fs::path& from, const fs::path& to, const std::vector<fs::path>& except, const fs::path& out) {
  std::error_code ec;
  std::vector<fs::path> entries, moved;
  for (fs::directory_iterator it(from, ec), end; !ec && it != end; it.increment(ec))
    if (std::find(except.begin(), except.end(), it->path()) == except.end()) entries.push_back(it->path());
  for (const fs::path& e : entries) {
    if (platform::replaceFile(utf8FromPath(e), utf8FromPath(to / e.filename())) != 0) {
      const std::string why = platform::errorText(errno);
      for (const fs::path& m : moved) platform::replaceFile(utf8FromPath(to / m.filename()), utf8FromPath(m));
      throw IoError("cannot put the report in '" + abbreviated(utf8FromPath(out)) + "': " + why);
    }
    moved.push_back(e);
  }
}

// Puts the whole report written in `temporary` at `out`: a new folder renamed into place;
// into an existing one, its earlier report moved aside (into a second temporary folder in
// it), the new one's entries moved in, then the earlier one removed. Throws IoError.
void swapIntoPlace(const std::string& temporary, const fs::path& out) {
  std::error_code ec;
  if (!fs::exists(out, ec)) {
    if (platform::replaceFile(temporary, utf8FromPath(out)) != 0)
      throw IoError("cannot put the report at '" + abbreviated(utf8FromPath(out)) + "': " + platform::errorText(errno));
    return;
  }
  const fs::path old = pathFromUtf8(temporaryFolderIn(out));
  struct RemoveOld {
    fs::path path;
    ~RemoveOld() {
      std::error_code e;
      fs::remove_all(path, e);
    }
  } removeOld{old};
  // The earlier report's entries (and any grade left of an earlier, killed run) aside, then
  // the new ones in; a failure puts the earlier ones back.
  moveEntries(out, old, {old, pathFromUtf8(temporary)}, out);
  try {
    moveEntries(pathFromUtf8(temporary), out, {}, out);
  } catch (...) {
    moveEntries(old, out, {}, out);
    throw;
  }
  fs::remove(pathFromUtf8(temporary), ec);
}

// The temporary folder, removed unless the report was put in place.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(std::string path) : path_(std::move(path)) {}
  ~TemporaryFolder() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(pathFromUtf8(path_), ec);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::string& path() const { return path_; }
  void release() { path_.clear(); }

 private:
  std::string path_;
};

// A folder is a folder of submissions, a file named .test a scene file to render. A name of
// nothing is an error (IoError), and so is anything else (UsageError: a zip file, a typo),
// before anything is read.
bool isSceneArgument(const std::string& path) {
  std::error_code ec;
  fs::file_status st = fs::status(pathFromUtf8(path), ec);
  if (!fs::exists(st))
    throw IoError("'" + abbreviated(path) + "' does not exist (give a folder of submissions, or a scene file to render)");
  if (fs::is_directory(st)) return false;
  std::string ext = utf8FromPath(pathFromUtf8(path).extension());
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".test")
    throw UsageError("grade: '" + abbreviated(path) + "' is neither a folder of submissions nor a scene file (.test)");
  return true;
}

// One comparison to make: a submission's image of a scene (a file, or a render held here).
// A reference: its 8-bit image, and its linear one when it is a float file (HDR-FLIP).
struct GradeReference {
  Image bytes;
  std::optional<RadianceImage> linear;
};

struct Job {
  std::size_t submission, scene;
  std::string path;                 // the file to read
  const Image* rendered = nullptr;  // or the image rendered in this run
  const RadianceImage* renderedLinear = nullptr;   // and its linear image (HDR-FLIP against a float reference)
};

// The rendered submission: each scene file rendered (sharing the device), matched to the
// reference of its name. A scene that fails is reported (its message printed) and graded as
// unreadable; `status` receives the worst of their statuses.
struct Rendered {
  Submission submission;
  std::map<std::string, Image> images;                       // sceneKey -> image
  std::map<std::string, RadianceImage> linear;               // sceneKey -> its linear image
  std::map<std::string, std::pair<std::string, int>> errors;   // sceneKey -> what went wrong, its status
  std::map<std::string, std::string> pastLimit;              // sceneKey -> the limit it went past (it fails)
};

// The render's bounds for a scene whose reference has `referencePixels` pixels: the limits
// `given` (command line, thresholds file), else the defaults (grade/grade_thresholds.h); 0
// given is no limit.
RenderLimits renderLimits(const GradeLimits& given, std::uint64_t referencePixels) {
  RenderLimits r;
  r.seconds = given.seconds.value_or(kDefaultLimitSeconds);
  r.spp = given.spp.value_or(kDefaultLimitSpp);
  r.pixels = given.pixels.value_or(referencePixels);
  const int depth = given.depth.value_or(kDefaultLimitDepth);
  r.depth = depth > 0 ? depth : -1;
  return r;
}

// The option that sets a limit, for the reason a scene past it fails.
const char* limitOption(LimitExceeded::Which which) {
  switch (which) {
    case LimitExceeded::Which::Seconds: return "--limit-time";
    case LimitExceeded::Which::Spp: return "--limit-spp";
    case LimitExceeded::Which::Pixels: return "--limit-pixels";
    case LimitExceeded::Which::Depth: return "--limit-depth";
  }
  return "";
}

Rendered renderScenes(const GradeOptions& o, const std::vector<std::string>& scenes,
                      const std::vector<SceneReference>& refs, const std::vector<GradeReference>& references,
                      const ThresholdTable& thresholds, const std::vector<TeachersFile>& teachers, int& status) {
  Rendered r;
  r.submission.name = "vkrt";
  r.submission.folder = "rendered by this run";
  std::map<std::string, std::uint64_t> referencePixels;   // by scene key
  for (std::size_t c = 0; c < refs.size(); ++c)
    referencePixels[sceneKey(refs[c].scene)] = static_cast<std::uint64_t>(references[c].bytes.width) *
                                                static_cast<std::uint64_t>(references[c].bytes.height);
  RenderSession session;
  for (const std::string& scene : scenes) {
    const std::string key = sceneKey(sceneOfFileName(scene));
    if (!referencePixels.count(key)) {
      r.submission.notes.push_back(abbreviated(scene) + ": no reference image is named for this scene; not rendered");
      continue;
    }
    if (r.submission.images.count(key)) {
      r.submission.notes.push_back(abbreviated(scene) + ": a second scene file for " + sceneOfFileName(scene) +
                                   " (" + abbreviated(r.submission.images[key]) + " is graded)");
      continue;
    }
    r.submission.images[key] = scene;
    // A scene file given is the student's when it is not the teacher's, nor a link out of its folder.
    fs::path folder = pathFromUtf8(scene).parent_path();
    if (folder.empty()) folder = ".";
    if (std::string why = notStudentsOwn(scene, utf8FromPath(folder), teachers); !why.empty()) {
      r.errors[key] = {why, 0};
      continue;
    }
    if (std::string why = submittedSceneProblem(scene); !why.empty()) {
      r.errors[key] = {why, kExitIo};
      status = worseExitStatus(status, kExitIo);
      if (!o.quiet) std::fprintf(stderr, "vkrt: %s\n", controlsEscaped(why).c_str());
      continue;
    }
    RenderRequest request = o.request;
    request.scenePath = scene;
    request.onWarnings = warningPrinter(o.quiet);
    request.onOptionWarning = optionWarningPrinter(o.quiet);
    request.limits = renderLimits(thresholds.forScene(key).limits, referencePixels[key]);
    try {
      ProgressBar progress(!o.quiet);
      RenderReport report;
      RadianceImage image = renderSceneInMemory(request, progress, report, false, &session);
      r.images[key] = encodeImage(image, report.gamma);
      r.linear[key] = std::move(image);
      if (!o.quiet)
        std::fprintf(stderr, "vkrt: rendered %s (%dx%d) in %.2f s\n", abbreviated(scene).c_str(), report.width, report.height,
                     report.parseSeconds + report.buildSeconds + report.renderSeconds);
    } catch (const LimitExceeded& e) {
      // Not an error of the scene's or of the run's: the submission fails this scene.
      if (!o.quiet) std::fprintf(stderr, "vkrt: %s (%s)\n", controlsEscaped(e.what()).c_str(), limitOption(e.which()));
      r.pastLimit[key] = std::string(e.what()) + " (" + limitOption(e.which()) + ")";
    } catch (...) {
      std::exception_ptr e = std::current_exception();
      if (int signal = pendingInterrupt()) throw Interrupted(signal);
      // The messages go to the terminal and, for the report (and a student on Gradescope), into the entry.
      std::string said;
      const int s = reportErrorKeepingText(e, {scene, o.quiet}, said);
      while (!said.empty() && said.back() == '\n') said.pop_back();
      status = worseExitStatus(status, s);
      r.errors[key] = {"cannot be rendered: " + exitStatusName(s) + (said.empty() ? "" : ":\n" + said), s};
    }
  }
  return r;
}

// Compares one image and writes its images into the report folder.
void gradeOne(const Job& job, const GradeReference& reference, const GradeThresholds& t, int heatmapScale,
              const std::string& folder, ReportEntry& entry) {
  AnyImage loaded;
  const Image* image = job.rendered;
  const RadianceImage* linear = job.renderedLinear;
  if (!image) {
    // Nothing is decoded that cannot be graded: a file that is not a regular one, or longer than
    // an image of the reference's size can be, is not read, and an image of another size is
    // judged by its header (an image bomb's pixels never reach memory).
    const SubmittedImage checked = checkSubmittedImage(job.path, reference.bytes.width, reference.bytes.height);
    if (!checked.problem.empty()) {
      entry.grade.outcome = GradeOutcome::Unreadable;
      entry.grade.failures.push_back(checked.problem);
      return;
    }
    if (checked.width != reference.bytes.width || checked.height != reference.bytes.height) {
      entry.grade = sizeDiffers(checked.width, checked.height, reference.bytes.width, reference.bytes.height, t);
      return;
    }
    try {
      loaded = readAnyImage(job.path);
    } catch (const IoError& e) {
      entry.grade.outcome = GradeOutcome::Unreadable;
      entry.grade.failures.push_back(e.what());
      return;
    }
    if (loaded.radiance) loaded.bytes = asBytes(*loaded.radiance);
    image = &loaded.bytes;
    linear = loaded.radiance ? &*loaded.radiance : nullptr;
  }
  ImageDiff diff;
  FlipMap flipMap;
  entry.grade = gradeImage(*image, reference.bytes, t, &diff, &flipMap, linear,
                           reference.linear ? &*reference.linear : nullptr);
  auto write = [&](const Image& img, ReportImage which) {
    writeImageAtomic(img, folder + "/" + entryImagePath(job.submission, job.scene, which));
  };
  // A PNG as it was sent (a browser shows it as it is, and copying costs less than encoding);
  // any other format as the PNG of its bytes.
  const std::string copy = folder + "/" + entryImagePath(job.submission, job.scene, ReportImage::Submission);
  std::error_code ec;
  if (job.rendered || !isPngFile(job.path) || !fs::copy_file(pathFromUtf8(job.path), pathFromUtf8(copy), ec))
    write(*image, ReportImage::Submission);
  write(thumbnail(*image, kThumbnailWidth, kThumbnailHeight), ReportImage::Thumbnail);
  entry.hasImage = true;
  if (diff.width > 0) {
    write(differenceHeatmap(diff, heatmapScale), ReportImage::Difference);
    write(flipMagmaImage(flipMap), ReportImage::Flip);
    entry.hasDiff = true;
  }
}

// Runs `jobs` on `threads` threads; the first exception (a write that failed, memory, a
// signal) stops the rest and is thrown here.
void runJobs(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job, ProgressBar& progress) {
  std::atomic<std::size_t> done{0};
  try {
    parallelFor(count, threads, [&](std::size_t i) {
      throwIfInterrupted();
      job(i);
      progress.update(++done, count);
    });
  } catch (...) {
    progress.finish();
    throw;
  }
  progress.finish();
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + controlsEscaped(n);
  return s;
}

// On stderr: an unreadable image's error, a line per submission (its failures named), the
// notes, then the summary (with -q: the errors, and the summary when something failed).
// Returns the run's exit status: `status` (the rendered scenes') made worse by what the
// comparisons found.
int printOutcomes(const GradeOptions& o, const GradeReport& report, int status) {
  for (const ReportSubmission& s : report.submissions) {
    std::vector<std::string> fail, missing, unreadable;
    std::size_t pass = 0;
    for (std::size_t c = 0; c < s.entries.size(); ++c) {
      const std::string& scene = report.scenes[c].name;
      switch (s.entries[c].grade.outcome) {
        case GradeOutcome::Pass: ++pass; break;
        case GradeOutcome::Fail: fail.push_back(scene); break;
        case GradeOutcome::Missing: missing.push_back(scene); break;
        case GradeOutcome::Unreadable:
          unreadable.push_back(scene);
          // A scene that could not be rendered has its status (in `status` already) and
          // printed its messages; an image that cannot be read is an I/O error.
          if (s.entries[c].renderStatus == 0) status = worseExitStatus(status, kExitIo);
          std::fprintf(stderr, "vkrt: %s: %s: %s\n", controlsEscaped(s.name).c_str(), controlsEscaped(scene).c_str(),
                       s.entries[c].grade.failures.empty() ? "unreadable" : controlsEscaped(s.entries[c].grade.failures[0]).c_str());
          break;
      }
    }
    if (!fail.empty() || !missing.empty()) status = worseExitStatus(status, kExitDiffers);
    if (!o.quiet)
      std::fprintf(stderr, "vkrt: %-20s %zu/%zu pass%s%s%s\n", controlsEscaped(s.name).c_str(), pass, s.entries.size(),
                   fail.empty() ? "" : ("; fail: " + joined(fail)).c_str(),
                   missing.empty() ? "" : ("; missing: " + joined(missing)).c_str(),
                   unreadable.empty() ? "" : ("; unreadable: " + joined(unreadable)).c_str());
  }
  if (!o.quiet)
    for (const ReportSubmission& s : report.submissions)
      for (const std::string& note : s.notes)
        std::fprintf(stderr, "vkrt: note: %s: %s\n", controlsEscaped(s.name).c_str(), controlsEscaped(note).c_str());
  const OutcomeCounts n = countOutcomes(report);
  if (o.quiet && status == kExitOk) return status;
  std::fprintf(stderr, "vkrt: graded %s x %s in %.2f s: %zu pass, %zu fail, %zu missing%s; report: %s; exit status %d\n",
               counted(report.submissions.size(), "submission", "submissions").c_str(),
               counted(report.scenes.size(), "scene", "scenes").c_str(), report.seconds, n.pass, n.fail, n.missing,
               n.unreadable ? (", " + std::to_string(n.unreadable) + " unreadable").c_str() : "",
               utf8FromPath(pathFromUtf8(o.output) / "index.html").c_str(), status);
  return status;
}


// What a scene file tells the grading of its images: whether it renders by Monte Carlo
// (`integrator direct` or `pathtracer`: noise around the reference, not the reference itself)
// and its images' `gamma`. Nothing when it cannot be read (its render, if any, says why).
struct SceneGrading {
  bool monteCarlo = false;
  double gamma = 1.0;
};
// A file that cannot be read as a scene: none, and `why` says why (its first error's message,
// at `line`: 0 for the file as a whole).
std::optional<SceneGrading> sceneGrading(const std::string& path, std::string& why, int& line) {
  try {
    const PathSettings p = parseSceneFile(path).path;
    return SceneGrading{p.integrator == Integrator::Direct || p.integrator == Integrator::PathTracer, p.gamma};
  } catch (const SceneError& e) {
    for (const Diagnostic& d : e.diagnostics())
      if (d.isError()) {
        why = d.message;
        line = d.line;
        break;
      }
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (why.empty()) why = "it cannot be read as a scene";
  return std::nullopt;
}

// The scene files that say which scenes are path-traced, by scene key: those in the
// references' folder beside their images (REFS/cornellNEE.test), else those given to render.
// The teacher's decides: a student's scene file must not choose how its own image is judged.
std::map<std::string, std::string> sceneFilesByKey(const std::vector<std::string>& scenes, const std::string& refs) {
  std::map<std::string, std::string> files;
  for (const std::string& scene : scenes) files[sceneKey(sceneOfFileName(scene))] = scene;
  std::error_code ec;
  for (fs::directory_iterator it(pathFromUtf8(refs), ec), end; !ec && it != end; it.increment(ec)) {
    std::string ext = utf8FromPath(it->path().extension());
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::string file = utf8FromPath(it->path());
    if (ext == ".test" && it->is_regular_file(ec)) files[sceneKey(sceneOfFileName(file))] = file;
  }
  return files;
}

// What the scene files known to the run say of the grading of their scenes (sceneGrading):
// their images' gamma, which the bias test decodes, and for a path-traced scene that nothing
// else judges, judgement by its noise: square by square, bias against its own standard error
// (compare/bias_test.h), not "any difference fails".
// Returns the scene files beside the references that cannot be read, set aside (the scene is
// then judged without it); one given to render says its errors when it is rendered.
std::vector<SetAside> applySceneFiles(ThresholdTable& thresholds, const std::vector<std::string>& keys,
                                      const std::vector<std::string>& scenes, const std::string& references) {
  std::vector<SetAside> setAside;
  for (const auto& [key, file] : sceneFilesByKey(scenes, references)) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) continue;
    const bool given = std::find(scenes.begin(), scenes.end(), file) != scenes.end();
    if (given && !submittedSceneProblem(file).empty()) continue;   // not read (a FIFO, 2 GB): its render says why
    std::string why;
    int line = 0;
    const std::optional<SceneGrading> g = sceneGrading(file, why, line);
    if (!g) {
      if (!given)
        setAside.push_back({file, line,
                            "a scene file beside the references that cannot be read (" + why +
                                "); its scene is graded without it (not as path-traced, gamma 1)"});
      continue;
    }
    GradeThresholds t = thresholds.forScene(key);
    if (!t.any() && g->monteCarlo) {
      t.maxBiasZ = kDefaultMaxBiasZ;
      t.monteCarloDefault = true;
    }
    t.gamma = g->gamma;
    thresholds.byScene[key] = t;
  }
  return setAside;
}

// The teacher's inputs set aside: on the terminal (but with -q), or with --strict an error
// (UsageError) naming the first and counting the rest.
void sayOrRefuseSetAside(const GradeOptions& o, const std::vector<SetAside>& setAside) {
  if (setAside.empty()) return;
  if (o.strict)
    throw UsageError("grade --strict: " + setAside[0].text() +
                     (setAside.size() > 1 ? " (and " + counted(setAside.size() - 1, "more input", "more inputs") +
                                                " set aside)"
                                          : ""));
  if (o.quiet) return;
  for (const SetAside& a : setAside)
    std::fprintf(stderr, "vkrt: warning: grade: set aside: %s\n", controlsEscaped(a.text()).c_str());
}

// The teacher's files that no submitted file may be: the reference images, the scene files
// beside them, the thresholds file.
std::vector<TeachersFile> teachersFiles(const std::vector<SceneReference>& refs, const std::string& references,
                                        const std::optional<std::string>& thresholdsFile) {
  std::vector<TeachersFile> files;
  auto add = [&](const std::string& path, const std::string& role) {
    if (std::optional<TeachersFile> f = teachersFile(path, role)) files.push_back(std::move(*f));
  };
  for (const SceneReference& r : refs) add(r.path, "the reference image");
  for (const auto& [key, file] : sceneFilesByKey({}, references)) add(file, "the reference scene file");
  if (thresholdsFile) add(*thresholdsFile, "the thresholds file");
  return files;
}

// Gradescope's results.json of the report, written whole (--gradescope).
void writeGradescope(const std::string& path, const GradeReport& report, const ThresholdTable& thresholds,
                     const std::vector<std::string>& keys) {
  std::vector<double> points;
  for (const std::string& key : keys) points.push_back(thresholds.forScene(key).points);
  const std::string json = gradescopeResults(report, points);
  writeFileAtomic(path, ".json.tmp", [&](ByteSink& file) {
    file.write(reinterpret_cast<const std::uint8_t*>(json.data()), json.size());
  });
}

// The comparisons to make, a job each, and the report's rows they fill (a submission's entry
// per scene: missing, a render that failed (unreadable, with its error), or a job's).
// `rendered` (may be null) is the first submission's renders.
std::vector<Job> listJobs(const std::vector<Submission>& submissions, const std::vector<std::string>& keys,
                          const Rendered* rendered, GradeReport& report) {
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < submissions.size(); ++i) {
    const Submission& s = submissions[i];
    ReportSubmission rs{s.name, s.folder, s.notes, std::vector<ReportEntry>(keys.size())};
    for (std::size_t c = 0; c < keys.size(); ++c) {
      auto at = s.images.find(keys[c]);
      if (at == s.images.end()) continue;   // missing
      rs.entries[c].source = at->second;
      if (auto why = s.refused.find(keys[c]); why != s.refused.end()) {   // not the student's own file
        rs.entries[c].grade.outcome = GradeOutcome::Unreadable;
        rs.entries[c].grade.failures.push_back(why->second);
        continue;
      }
      if (rendered && i == 0) {
        if (auto past = rendered->pastLimit.find(keys[c]); past != rendered->pastLimit.end()) {
          rs.entries[c].grade.outcome = GradeOutcome::Fail;
          rs.entries[c].grade.failures.push_back(past->second);
          continue;
        }
        if (auto err = rendered->errors.find(keys[c]); err != rendered->errors.end()) {
          rs.entries[c].grade.outcome = GradeOutcome::Unreadable;
          rs.entries[c].grade.failures.push_back(err->second.first);
          rs.entries[c].renderStatus = err->second.second;
          continue;
        }
        jobs.push_back({i, c, at->second, &rendered->images.at(keys[c]), &rendered->linear.at(keys[c])});
      } else {
        jobs.push_back({i, c, at->second, nullptr});
      }
    }
    report.submissions.push_back(std::move(rs));
  }
  return jobs;
}

}  // namespace

int gradeCommand(const GradeOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> folders, scenes;
  for (const std::string& in : o.inputs) (isSceneArgument(in) ? scenes : folders).push_back(in);
  std::vector<std::string> inputs = o.inputs;
  inputs.push_back(o.references);
  if (o.thresholdsFile) inputs.push_back(*o.thresholdsFile);
  const fs::path out = checkReportFolder(o.output, inputs);
  if (o.gradescopePath) checkGradescopeFile(*o.gradescopePath, inputs, out);

  const std::vector<SceneReference> refs = findReferences(o.references);
  std::vector<std::string> keys;
  for (const SceneReference& r : refs) keys.push_back(sceneKey(r.scene));
  ThresholdTable thresholds;
  thresholds.all = o.thresholds;
  if (o.thresholdsFile) thresholds = readThresholdFile(*o.thresholdsFile, o.thresholds, keys);
  const std::vector<TeachersFile> teachers = teachersFiles(refs, o.references, o.thresholdsFile);
  std::vector<SetAside> setAside = unusedReferenceEntries(o.references, refs, o.thresholdsFile);
  for (SetAside& a : applySceneFiles(thresholds, keys, scenes, o.references)) setAside.push_back(std::move(a));
  sayOrRefuseSetAside(o, setAside);
  std::vector<Submission> submissions;
  if (!folders.empty()) submissions = findSubmissions(folders, refs, o.oneStudent, teachers);

  // The references, read before anything is rendered: one that cannot be read stops the run.
  std::vector<GradeReference> references;
  for (const SceneReference& r : refs) {
    AnyImage image = readAnyImage(r.path);
    references.push_back(image.radiance ? GradeReference{asBytes(*image.radiance), std::move(image.radiance)}
                                        : GradeReference{std::move(image.bytes), std::nullopt});
  }

  int status = kExitOk;
  std::optional<Rendered> rendered;
  if (!scenes.empty()) {
    rendered = renderScenes(o, scenes, refs, references, thresholds, teachers, status);
    submissions.insert(submissions.begin(), rendered->submission);
  }

  TemporaryFolder folder(temporaryFolderFor(out));
  for (const std::string& sub : reportImageFolders(submissions.size()))
    fs::create_directories(pathFromUtf8(folder.path() + "/" + sub));
  GradeReport report;
  report.references = o.references;
  report.setAside = setAside;
  for (std::size_t c = 0; c < refs.size(); ++c) {
    const GradeThresholds& t = thresholds.forScene(keys[c]);
    report.scenes.push_back({refs[c].scene, refs[c].path, t.text(), keyFigureLabel(t), references[c].bytes.width,
                             references[c].bytes.height});
    writeImageAtomic(references[c].bytes, folder.path() + "/" + referenceImagePath(c));
  }
  const std::vector<Job> jobs = listJobs(submissions, keys, rendered ? &*rendered : nullptr, report);

  const unsigned threads = o.request.threads > 0 ? static_cast<unsigned>(o.request.threads)
                                                  : std::max(1u, std::thread::hardware_concurrency());
  ProgressBar progress(!o.quiet);
  runJobs(jobs.size(), threads, [&](std::size_t k) {
    const Job& job = jobs[k];
    gradeOne(job, references[job.scene], thresholds.forScene(keys[job.scene]), o.heatmapScale, folder.path(),
             report.submissions[job.submission].entries[job.scene]);
  }, progress);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeReportPages(report, folder.path());
  waitForSignalIfTesting("grade");
  throwIfInterrupted();
  swapIntoPlace(folder.path(), out);
  folder.release();
  if (o.gradescopePath) writeGradescope(*o.gradescopePath, report, thresholds, keys);

  return printOutcomes(o, report, status);
}

}  // namespace vkrt
