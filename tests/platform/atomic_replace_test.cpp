// Writing an output through the platform layer (image/atomic_file.h over host/platform/): the
// new file replaces the old whole, with the old one's permission bits, every one of them;
// a file with two names is refused, on Windows too (where mingw's stat says every file has
// one name); on Windows, a target that another program holds open is waited for, then
// refused with a message that says so. Standard C++, gtest and vkrt's headers only: the
// Windows build compiles it too.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "image/atomic_file.h"
#include "platform/file_status.h"
#include "test_folder.h"
#include "util/errors.h"

using namespace vkrt;
namespace fs = std::filesystem;

namespace {

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeAtomic(const std::string& path, const std::string& bytes) {
  writeFileAtomic(path, ".bin.tmp", [&](ByteSink& file) {
    file.write(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  });
}

TEST(AtomicReplace, TheNewContentReplacesTheOldWholeAndNothingIsLeft) {
  const std::string dir = test::freshFolder("atomic-whole");
  const std::string path = (fs::path(dir) / "out.bin").string();
  writeAtomic(path, "a first content, longer than the second\r\n");
  EXPECT_EQ(readBytes(path), "a first content, longer than the second\r\n");
  writeAtomic(path, std::string("2nd\r\n\x1A", 6));
  EXPECT_EQ(readBytes(path), std::string("2nd\r\n\x1A", 6));
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  EXPECT_EQ(n, 1u);
}

// The replaced file keeps every permission bit, set-user-ID, set-group-ID and sticky too.
TEST(AtomicReplace, AReplacedFileKeepsItsSpecialModeBits) {
#ifdef _WIN32
  GTEST_SKIP() << "Windows keeps no set-user-ID, set-group-ID or sticky bits";
#else
  const std::string dir = test::freshFolder("atomic-modes");
  const std::string path = (fs::path(dir) / "out.bin").string();
  for (fs::perms mode : {fs::perms(04755), fs::perms(02750), fs::perms(01644), fs::perms(07711)}) {
    writeAtomic(path, "old");
    fs::permissions(path, mode);
    const fs::perms set = fs::status(path).permissions();
    if ((set & fs::perms(07000)) != (mode & fs::perms(07000)))   // a system that drops one
      GTEST_SKIP() << "this file system did not keep mode " << std::oct << static_cast<unsigned>(mode);
    writeAtomic(path, "new");
    EXPECT_EQ(readBytes(path), "new");
    EXPECT_EQ(static_cast<unsigned>(fs::status(path).permissions()), static_cast<unsigned>(mode))
        << "mode " << std::oct << static_cast<unsigned>(mode);
  }
#endif
}

// A hard-linked output is refused: renaming over one name would leave the other with the old
// bytes. On Windows the number of names comes from an open handle (stat says 1).
TEST(AtomicReplace, AFileWithTwoNamesIsRefused) {
  const std::string dir = test::freshFolder("atomic-hard-link");
  const std::string a = (fs::path(dir) / "a.bin").string(), b = (fs::path(dir) / "b.bin").string();
  writeAtomic(a, "shared");
  fs::create_hard_link(a, b);
  try {
    writeAtomic(b, "new");
    ADD_FAILURE() << "a file with two names was replaced";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("it has 2 names (hard links)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readBytes(a), "shared");
  EXPECT_EQ(readBytes(b), "shared");
  const OutputFile other = resolveOutputFile((fs::path(dir) / "c.bin").string());
  EXPECT_FALSE(other.exists);
  writeAtomic(a + ".single", "one");
  const OutputFile single = resolveOutputFile(a + ".single");
  EXPECT_TRUE(single.exists);
  EXPECT_EQ(single.identity, platform::statusOf(a + ".single").identity);
  EXPECT_NE(single.identity.file, 0u);
}

#ifdef _WIN32
// A viewer that holds the output open (without letting it be deleted, as the C runtime's
// fopen does) makes Windows refuse the rename: vkrt waits a moment, then says why, and the
// old file and no temporary file are left.
TEST(AtomicReplace, AnOutputHeldOpenIsRefusedWithAMessageThatSaysSo) {
  const std::string dir = test::freshFolder("atomic-held");
  const std::string path = (fs::path(dir) / "out.bin").string();
  writeAtomic(path, "old");
  {
    std::ifstream viewer(path, std::ios::binary);
    ASSERT_TRUE(viewer);
    try {
      writeAtomic(path, "new");
      ADD_FAILURE() << "replaced a file held open";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find("another program has the file open"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(readBytes(path), "old");
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  EXPECT_EQ(n, 1u);
  writeAtomic(path, "new");   // let go: replaced
  EXPECT_EQ(readBytes(path), "new");
}
#endif

}  // namespace
