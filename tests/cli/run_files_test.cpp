// RunFiles::same: what makes two files the same file of a run (cli/run_files.h).
#include <gtest/gtest.h>

#include "cli/run_files.h"

using namespace vkrt;

namespace {

RunFiles::File existing(const std::string& name, std::uint64_t device, std::uint64_t inode) {
  RunFiles::File f{name, "a file", "/c/" + name};
  f.exists = true;
  f.identity = {device, inode};
  return f;
}

// Inode numbers are per file system: the same number on two devices is two files.
TEST(RunFiles, SameInodeOnTwoDevicesIsTwoFiles) {
  EXPECT_FALSE(RunFiles::same(existing("a", 1, 42), existing("b", 2, 42)));
  EXPECT_TRUE(RunFiles::same(existing("a", 1, 42), existing("b", 1, 42)));   // a hard link
  EXPECT_FALSE(RunFiles::same(existing("a", 1, 42), existing("a", 1, 43)));   // replaced since
}

// A file that does not exist (yet) is known by its canonical name alone.
TEST(RunFiles, FilesNotThereAreKnownByTheirCanonicalNames) {
  RunFiles::File a{"x.png", "an output", "/d/x.png"}, b{"./x.png", "an output", "/d/x.png"},
      c{"y.png", "an output", "/d/y.png"};
  EXPECT_TRUE(RunFiles::same(a, b));
  EXPECT_FALSE(RunFiles::same(a, c));
  RunFiles::File there = existing("x.png", 1, 7);
  there.canonical = "/d/x.png";
  EXPECT_TRUE(RunFiles::same(a, there));   // one of the two not there: the names decide
}

}  // namespace
