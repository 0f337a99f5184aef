// Telling a run's outputs from its inputs (run_files.h).
#include "cli/run_files.h"

#include "image/atomic_file.h"
#include "platform/file_names.h"
#include "util/text.h"   // abbreviated

namespace vkrt {

bool RunFiles::same(const File& a, const File& b) {
  if (a.exists && b.exists) return a.identity == b.identity;
  return a.canonical == b.canonical;
}

RunFiles::File RunFiles::fileNamed(const std::string& path, const std::string& role) {
  File f{path, role, platform::canonicalName(path)};
  if (const platform::FileStatus st = platform::statusOf(path); st.found()) {
    f.exists = true;
    f.identity = st.identity;
  }
  return f;
}

void RunFiles::addInput(const std::string& path, const std::string& role) { inputs_.push_back(fileNamed(path, role)); }

RunFiles::File RunFiles::resolvedOutput(const std::string& path, const std::string& role) const {
  OutputFile out = resolveOutputFile(path);
  return File{path, role, out.canonical, out.exists, out.identity};
}

void RunFiles::checkOutput(const std::string& path, const std::string& role) const {
  auto spelt = [](const File& f) {
    return "'" + abbreviated(f.path) + "'";
  };
  auto refuseInput = [&](const File& out, const File& in) {
    throw RefusedOutput("refusing to write " + role + " " + spelt(out) + ": it is " + in.role + " " + spelt(in) +
                        ", which this run reads; writing it would destroy that file (name another output)");
  };
  // An input first, by what the file is: resolveOutputFile refuses some existing files (a hard
  // link among them) with an I/O error, and an input should be told as one.
  if (const File existing = fileNamed(path, role); existing.exists)
    for (const File& in : inputs_)
      if (same(existing, in)) refuseInput(existing, in);
  File out = resolvedOutput(path, role);
  for (const File& in : inputs_)
    if (same(out, in)) refuseInput(out, in);
  for (const File& earlier : outputs_)
    if (same(out, earlier))
      throw RefusedOutput("refusing to write " + role + " " + spelt(out) + ": it is also " + earlier.role + " " +
                          spelt(earlier) + ", written by this run (two outputs, one file)");
}

void RunFiles::addOutput(const std::string& path, const std::string& role) {
  checkOutput(path, role);
  outputs_.push_back(resolvedOutput(path, role));
}

}  // namespace vkrt
