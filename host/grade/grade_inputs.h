// What `vkrt grade` compares: the reference images of a folder, each named for its scene,
// and the submissions (a folder per student, or one folder of images), matched to the
// references by name. Reads folders only; no image is decoded here.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "platform/file_status.h"

namespace vkrt {

// A reference image and the scene it is for: its file name without the extension, and
// without a leading "ref_" or "ref-" (the course graders' "ref_scene5.png" is scene5).
struct SceneReference {
  std::string scene;   // as the file spells it
  std::string path;
};

// The scene a file name is for: the name without its folder and its extension, and for a
// reference (`reference`) without a leading "ref_" or "ref-" too. A submitted
// "ref_scene5.png" is no scene's: a copy of the reference is not the student's image.
std::string sceneOfFileName(const std::string& path, bool reference = false);

// The key names are matched by: the scene in lower case ("Scene5.PNG" is scene5).
std::string sceneKey(const std::string& scene);

// The images directly in `folder`, in the order people count them (scene2 before scene10).
// Throws IoError when `folder` is not a folder that can be listed, UsageError when it holds
// no image or two images for one scene.
std::vector<SceneReference> findReferences(const std::string& folder);

// A file of the teacher's that no submission may be: a reference image, a reference scene
// file, the thresholds file. A student's link to one would be graded as the student's work.
struct TeachersFile {
  std::string path;
  std::string role;                  // "the reference image", "the thresholds file"...
  platform::FileIdentity identity;
};
// Whether the path `inner` is `outer` or lies in it, by their components (both absolute and
// normal, or both alike).
bool pathInside(const std::filesystem::path& inner, const std::filesystem::path& outer);

// The teacher's file `path`, by its identity (through links); nothing when it is not there.
std::optional<TeachersFile> teachersFile(const std::string& path, const std::string& role);

// Why the submitted file `path`, found in the student's folder `folder`, is not the student's
// own: it is the same file as one of `teachers` (a hard link, or a symbolic link, to it), or
// a symbolic link on its way down from `folder` leads out of that folder (to another student's
// file, to anything). Empty when it is the student's. `folder` may itself be a link (a class
// folder of links to the students' folders): the files must lie in the folder it leads to.
std::string notStudentsOwn(const std::string& path, const std::string& folder, const std::vector<TeachersFile>& teachers);

// An input of the teacher's that grading sets aside: a scene file beside the references that
// cannot be read (its scene is then graded without it), one whose scene has no reference, a
// file or folder there that is neither. Said on the terminal, in the report, summary.json and
// Gradescope's results; with --strict, an error.
struct SetAside {
  std::string file;
  int line = 0;         // 0: the file as a whole
  std::string reason;
  // "refs/box.test:3: a scene file ... (why); its scene is graded without it"
  std::string text() const;
};

// The entries of the references' folder `folder` that grading does not use: neither a
// reference image (`references`) nor a scene file for one, nor the thresholds file (kept
// there, perhaps). Hidden entries are passed over.
std::vector<SetAside> unusedReferenceEntries(const std::string& folder, const std::vector<SceneReference>& references,
                                             const std::optional<std::string>& thresholdsFile);

// One student's images (or one render's, for scene files), by scene key.
struct Submission {
  std::string name;                             // the student's folder name
  std::string folder;                           // as found, for the report
  std::map<std::string, std::string> images;    // sceneKey -> image path
  std::map<std::string, std::string> refused;   // sceneKey -> why its image is not graded (notStudentsOwn)
  std::vector<std::string> notes;               // images left out, and why
};

// The submissions in each of `folders`: each sub-folder (hidden ones skipped) is one
// student's, its images looked for down to four levels; images directly in a folder are
// that folder's own submission. A student's folder without an image is still a submission
// (every image missing). Noted: images that match no reference, second images for one scene
// (the first in path order is graded), and files vkrt does not read as images. Names that
// repeat across folders get the folder's name in front. Throws IoError for a folder that
// cannot be listed, UsageError when no submission is found. With `oneStudentEach` each folder
// is one student's submission, its images looked for down to four levels, and one without an
// image is a submission with every image missing (as Gradescope hands a submission over).
// An image that is not the student's own (notStudentsOwn, against `teachers`) is in `refused`
// too: its scene fails with that reason.
std::vector<Submission> findSubmissions(const std::vector<std::string>& folders,
                                        const std::vector<SceneReference>& references, bool oneStudentEach = false,
                                        const std::vector<TeachersFile>& teachers = {});

// a < b in the order people count: runs of digits compared as numbers ("scene2" < "scene10").
bool naturalLess(const std::string& a, const std::string& b);

}  // namespace vkrt
