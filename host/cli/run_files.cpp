// Telling a run's outputs from its inputs (run_files.h).
#include "cli/run_files.h"

#include <cstdlib>
#include <filesystem>
#include <memory>

#include <sys/stat.h>

#include "image/atomic_file.h"
#include "util/text.h"   // abbreviated

namespace vkrt {
namespace {

// An absolute, link-free name for `path`: realpath() of the file, or of its folder and then
// its name when the file is not there; the lexically normal absolute path when neither is.
std::string canonicalName(const std::string& path) {
  std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr), &std::free);
  if (real) return real.get();
  std::filesystem::path p(path);
  std::filesystem::path dir = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
  std::unique_ptr<char, decltype(&std::free)> realDir(::realpath(dir.c_str(), nullptr), &std::free);
  if (realDir) return (std::filesystem::path(realDir.get()) / p.filename()).string();
  std::error_code ec;
  std::filesystem::path absolute = std::filesystem::absolute(p, ec);
  return (ec ? p : absolute).lexically_normal().string();
}

}  // namespace

bool RunFiles::same(const File& a, const File& b) {
  if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
  return a.canonical == b.canonical;
}

RunFiles::File RunFiles::fileNamed(const std::string& path, const std::string& role) {
  File f{path, role, canonicalName(path)};
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    f.exists = true;
    f.device = static_cast<std::uint64_t>(st.st_dev);
    f.inode = static_cast<std::uint64_t>(st.st_ino);
  }
  return f;
}

void RunFiles::addInput(const std::string& path, const std::string& role) { inputs_.push_back(fileNamed(path, role)); }

RunFiles::File RunFiles::resolvedOutput(const std::string& path, const std::string& role) const {
  OutputFile out = resolveOutputFile(path);
  return File{path, role, out.canonical, out.exists, out.device, out.inode};
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
