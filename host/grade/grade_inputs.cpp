// Finding the references and the submissions of `vkrt grade` in their folders.
#include "grade/grade_inputs.h"

#include <algorithm>
#include <cerrno>
#include <cctype>
#include <filesystem>
#include <set>
#include <system_error>

#include "util/errors.h"
#include "image/image_file.h"
#include "platform/error_text.h"
#include "platform/file_names.h"
#include "platform/path_text.h"
#include "util/text.h"   // abbreviated

namespace vkrt {

namespace fs = std::filesystem;
using platform::pathFromUtf8;
using platform::utf8FromPath;

namespace {

constexpr int kSubmissionDepth = 4;   // how deep a student's folder is searched for images

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Hidden entries, and the folder of resource forks that a zip made on a Mac unpacks into.
bool hidden(const fs::path& p) {
  const std::string name = utf8FromPath(p.filename());
  return (!name.empty() && name[0] == '.') || name == "__MACOSX";
}

// The entries of `folder` (not hidden), sorted naturally; IoError when it cannot be listed.
std::vector<fs::directory_entry> entriesOf(const std::string& folder) {
  std::error_code ec;
  fs::directory_iterator it(pathFromUtf8(folder), ec);
  if (ec) throw IoError("cannot read the folder '" + abbreviated(folder) + "': " + ec.message());
  std::vector<fs::directory_entry> entries;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) throw IoError("cannot read the folder '" + abbreviated(folder) + "': " + ec.message());
    if (!hidden(it->path())) entries.push_back(*it);
  }
  if (ec) throw IoError("cannot read the folder '" + abbreviated(folder) + "': " + ec.message());
  std::sort(entries.begin(), entries.end(), [](const fs::directory_entry& a, const fs::directory_entry& b) {
    return naturalLess(utf8FromPath(a.path().filename()), utf8FromPath(b.path().filename()));
  });
  return entries;
}

bool isFolder(const fs::directory_entry& e) {
  std::error_code ec;
  return e.is_directory(ec);   // follows links
}

bool isImageFile(const fs::directory_entry& e) {
  std::error_code ec;
  return e.is_regular_file(ec) && imageKindByName(utf8FromPath(e.path()));
}

// A submitted entry named as an image, and not a folder: a regular file, or anything else
// (a FIFO, a device, a link to nothing) that grading then refuses to read (grade_guard.h),
// failing its scene rather than leaving it missing without a word.
bool isImageName(const fs::directory_entry& e) { return imageKindByName(utf8FromPath(e.path())) && !isFolder(e); }

bool isOtherFile(const fs::directory_entry& e) {
  std::error_code ec;
  return e.is_regular_file(ec) && !imageKindByName(utf8FromPath(e.path()));
}

// The images under `folder` (itself and `depth` levels below), in path order, and the other
// files there (`others`). A link to a folder that leads out of `root` (the student's folder,
// links resolved) is not searched, and said in `notes`: it would grade what is not the
// student's, and lead the search anywhere (to '/').
void collectImages(const std::string& folder, int depth, const std::string& root, std::vector<std::string>& out,
                   std::vector<std::string>& others, std::vector<std::string>& notes) {
  const std::vector<fs::directory_entry> entries = entriesOf(folder);
  for (const fs::directory_entry& e : entries) {
    if (isImageName(e)) out.push_back(utf8FromPath(e.path()));
    if (isOtherFile(e)) others.push_back(utf8FromPath(e.path()));
  }
  if (depth == 0) return;
  for (const fs::directory_entry& e : entries) {
    if (!isFolder(e)) continue;
    const std::string path = utf8FromPath(e.path());
    std::error_code ec;
    if (e.is_symlink(ec)) {
      const std::optional<std::string> real = platform::realPath(path);
      if (!real || !pathInside(pathFromUtf8(*real), pathFromUtf8(root))) {
        notes.push_back(abbreviated(path) + ": a link to a folder outside the submission" +
                        (real ? " ('" + abbreviated(*real) + "')" : std::string()) + "; not searched");
        continue;
      }
    }
    collectImages(path, depth - 1, root, out, others, notes);
  }
}

// The images of the student's folder `folder`, `depth` levels down (collectImages).
void collectStudentImages(const std::string& folder, int depth, std::vector<std::string>& out,
                          std::vector<std::string>& others, std::vector<std::string>& notes) {
  const std::string root = platform::realPath(folder).value_or(folder);
  collectImages(folder, depth, root, out, others, notes);
}

constexpr std::size_t kOtherFilesNoted = 5;   // per submission; then "and N more"

// The notes for files that are not images vkrt reads.
void noteOthers(Submission& s, const std::vector<std::string>& others) {
  for (std::size_t i = 0; i < others.size() && i < kOtherFilesNoted; ++i)
    s.notes.push_back(abbreviated(others[i]) + ": not an image vkrt reads (" + imageExtensionsText() +
                      ", .jpg); not graded");
  if (others.size() > kOtherFilesNoted)
    s.notes.push_back("and " + std::to_string(others.size() - kOtherFilesNoted) + " more files that are not images");
}

// The submission made of `images` in the student's folder `folder`, matched to `references`
// (by key); an image not the student's own is refused.
Submission matched(const std::string& name, const std::string& folder, const std::vector<std::string>& images,
                   const std::set<std::string>& keys, const std::vector<TeachersFile>& teachers) {
  Submission s;
  s.name = name;
  s.folder = folder;
  std::size_t ofNoScene = 0;
  for (const std::string& image : images) {
    const std::string key = sceneKey(sceneOfFileName(image));
    if (!keys.count(key)) {
      if (++ofNoScene <= kOtherFilesNoted)
        s.notes.push_back(abbreviated(image) + ": no reference image is named for this scene; not graded");
    } else if (auto [at, added] = s.images.emplace(key, image); !added) {
      s.notes.push_back(abbreviated(image) + ": a second image for " + sceneOfFileName(image) + " (" +
                        abbreviated(at->second) + " is graded)");
    } else if (std::string why = notStudentsOwn(image, folder, teachers); !why.empty()) {
      s.refused[key] = why;
    }
  }
  if (ofNoScene > kOtherFilesNoted)
    s.notes.push_back("and " + std::to_string(ofNoScene - kOtherFilesNoted) + " more images of no scene; not graded");
  return s;
}

std::string baseName(const std::string& folder) {
  fs::path p = pathFromUtf8(folder).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  std::string name = utf8FromPath(p.filename());
  if (name.empty() || name == ".") name = utf8FromPath(fs::absolute(p).lexically_normal().filename());
  return name.empty() ? folder : name;
}

}  // namespace

bool pathInside(const fs::path& inner, const fs::path& outer) {
  return std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end()).first == outer.end();
}

std::optional<TeachersFile> teachersFile(const std::string& path, const std::string& role) {
  const platform::FileStatus st = platform::statusOf(path);
  if (!st.found()) return std::nullopt;
  return TeachersFile{path, role, st.identity};
}

std::string notStudentsOwn(const std::string& path, const std::string& folder, const std::vector<TeachersFile>& teachers) {
  const std::string graded = "; only the student's own files are graded";
  if (const platform::FileStatus st = platform::statusOf(path); st.found())
    for (const TeachersFile& t : teachers)
      if (st.identity == t.identity)
        return "'" + abbreviated(path) + "' is the same file as " + t.role + " '" + abbreviated(t.path) +
               "' (a link to it)" + graded;
  const std::optional<std::string> real = platform::realPath(path), root = platform::realPath(folder);
  if (!real || !root)
    return "'" + abbreviated(path) + "': where it leads cannot be told (" + platform::errorText(errno) + ")" + graded;
  if (!pathInside(pathFromUtf8(*real), pathFromUtf8(*root)))
    return "'" + abbreviated(path) + "' is a link to a file outside the submission ('" + abbreviated(*real) + "')" +
           graded;
  return "";
}

std::string sceneOfFileName(const std::string& path, bool reference) {
  std::string stem = utf8FromPath(pathFromUtf8(path).stem());
  if (reference && stem.size() > 4 && (lower(stem.substr(0, 4)) == "ref_" || lower(stem.substr(0, 4)) == "ref-"))
    stem = stem.substr(4);
  return stem;
}

std::string sceneKey(const std::string& scene) { return lower(scene); }

bool naturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const bool da = std::isdigit(static_cast<unsigned char>(a[i])), db = std::isdigit(static_cast<unsigned char>(b[j]));
    if (da && db) {
      std::size_t i0 = i, j0 = j;
      while (i < a.size() && a[i] == '0') ++i;
      while (j < b.size() && b[j] == '0') ++j;
      std::size_t i1 = i, j1 = j;
      while (i1 < a.size() && std::isdigit(static_cast<unsigned char>(a[i1]))) ++i1;
      while (j1 < b.size() && std::isdigit(static_cast<unsigned char>(b[j1]))) ++j1;
      if (i1 - i != j1 - j) return i1 - i < j1 - j;   // fewer digits: smaller
      if (int c = a.compare(i, i1 - i, b, j, j1 - j); c != 0) return c < 0;
      if (i1 - i0 != j1 - j0) return i1 - i0 < j1 - j0;   // "2" before "02"
      i = i1, j = j1;
      continue;
    }
    const char ca = static_cast<char>(std::tolower(static_cast<unsigned char>(a[i])));
    const char cb = static_cast<char>(std::tolower(static_cast<unsigned char>(b[j])));
    if (ca != cb) return ca < cb;
    ++i, ++j;
  }
  if (a.size() - i != b.size() - j) return a.size() - i < b.size() - j;
  return a < b;   // equal but for case: a fixed order
}

std::vector<SceneReference> findReferences(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(pathFromUtf8(folder), ec))
    throw IoError("the references '" + abbreviated(folder) + "' are not a folder (vkrt grade REFS/ SUBMISSIONS/)");
  std::vector<SceneReference> refs;
  std::map<std::string, std::string> byKey;
  for (const fs::directory_entry& e : entriesOf(folder)) {
    if (!isImageFile(e)) continue;
    SceneReference r{sceneOfFileName(utf8FromPath(e.path()), true), utf8FromPath(e.path())};
    if (auto [at, added] = byKey.emplace(sceneKey(r.scene), r.path); !added)
      throw UsageError("two reference images for the scene " + r.scene + ": " + abbreviated(at->second) + " and " +
                       abbreviated(r.path) + " (keep one)");
    refs.push_back(r);
  }
  if (refs.empty())
    throw UsageError("no reference image in '" + abbreviated(folder) + "' (images named for their scenes: scene5" +
                     defaultImageExtension() + ", ...)");
  return refs;
}

std::string SetAside::text() const {
  return abbreviated(file) + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + reason;
}

std::vector<SetAside> unusedReferenceEntries(const std::string& folder, const std::vector<SceneReference>& references,
                                             const std::optional<std::string>& thresholdsFile) {
  const std::optional<TeachersFile> thresholds =
      thresholdsFile ? teachersFile(*thresholdsFile, "the thresholds file") : std::nullopt;
  std::set<std::string> keys, used;
  for (const SceneReference& r : references) {
    keys.insert(sceneKey(r.scene));
    used.insert(r.path);
  }
  std::vector<SetAside> unused;
  for (const fs::directory_entry& e : entriesOf(folder)) {
    const std::string path = utf8FromPath(e.path());
    if (used.count(path)) continue;
    const platform::FileStatus st = platform::statusOf(path);
    if (thresholds && st.found() && st.identity == thresholds->identity) continue;
    const bool sceneFile = lower(utf8FromPath(e.path().extension())) == ".test";
    std::string why;
    if (st.is(platform::FileKind::Directory)) {
      why = "a folder: the references are the images directly in '" + abbreviated(folder) + "'; not searched";
    } else if (!st.is(platform::FileKind::Regular)) {
      why = std::string(st.found() ? "not a regular file" : "a link to nothing") + "; not read";
    } else if (sceneFile && keys.count(sceneKey(sceneOfFileName(path)))) {
      continue;   // the scene file of a reference (read by the caller)
    } else if (sceneFile) {
      why = "a scene file whose scene has no reference image (" + sceneOfFileName(path) + defaultImageExtension() +
            ", or another format vkrt reads); not used";
    } else if (imageKindByName(path)) {
      continue;   // (a second image of a scene is refused by findReferences)
    } else {
      why = "neither an image vkrt reads (" + imageExtensionsText() + ", .jpg) nor a scene file; not used";
    }
    unused.push_back({path, 0, why});
  }
  return unused;
}

std::vector<Submission> findSubmissions(const std::vector<std::string>& folders,
                                        const std::vector<SceneReference>& references, bool oneStudentEach,
                                        const std::vector<TeachersFile>& teachers) {
  std::set<std::string> keys;
  for (const SceneReference& r : references) keys.insert(sceneKey(r.scene));
  std::vector<Submission> found;
  for (const std::string& folder : folders) {
    std::error_code ec;
    if (!fs::is_directory(pathFromUtf8(folder), ec))
      throw IoError("the submissions '" + abbreviated(folder) + "' are not a folder (a folder per student, or a "
                    "folder of images)");
    if (oneStudentEach) {   // the folder is one student's, whatever its sub-folders are called
      std::vector<std::string> images, others, notes;
      collectStudentImages(folder, kSubmissionDepth, images, others, notes);
      Submission s = matched(baseName(folder), folder, images, keys, teachers);
      s.notes.insert(s.notes.end(), notes.begin(), notes.end());
      if (images.empty()) s.notes.push_back("no image in " + abbreviated(folder));
      noteOthers(s, others);
      found.push_back(std::move(s));
      continue;
    }
    const std::vector<fs::directory_entry> entries = entriesOf(folder);
    std::vector<std::string> own, ownOthers;
    for (const fs::directory_entry& e : entries) {
      if (isImageName(e)) own.push_back(utf8FromPath(e.path()));
      if (isOtherFile(e)) ownOthers.push_back(utf8FromPath(e.path()));
    }
    std::vector<Submission> here;
    if (!own.empty()) {
      here.push_back(matched(baseName(folder), folder, own, keys, teachers));
      noteOthers(here.back(), ownOthers);
    }
    for (const fs::directory_entry& e : entries) {
      if (!isFolder(e)) continue;
      std::vector<std::string> images, others, notes;
      collectStudentImages(utf8FromPath(e.path()), kSubmissionDepth - 1, images, others, notes);
      here.push_back(matched(utf8FromPath(e.path().filename()), utf8FromPath(e.path()), images, keys, teachers));
      here.back().notes.insert(here.back().notes.end(), notes.begin(), notes.end());
      if (images.empty()) here.back().notes.push_back("no image in " + abbreviated(utf8FromPath(e.path())));
      noteOthers(here.back(), others);
    }
    for (Submission& s : here) {
      bool taken = std::any_of(found.begin(), found.end(), [&](const Submission& f) { return f.name == s.name; });
      if (taken) s.name = baseName(folder) + "/" + s.name;
      found.push_back(std::move(s));
    }
  }
  if (found.empty())
    throw UsageError("no submitted image found in " + std::string(folders.size() == 1 ? "'" + abbreviated(folders[0]) + "'" : "the folders given") +
                     " (a folder per student holding images named for their scenes, or a folder of images)");
  return found;
}

}  // namespace vkrt
