// File names in non-ASCII letters through std::filesystem::path (platform/path_text.h): on
// Windows libstdc++'s path(std::string) reads UTF-8 as Latin-1, so that a name taken apart by
// std::filesystem and put back names another file; pathFromUtf8 and utf8FromPath keep it.
// Every name here is there on disk, found again by the layer's file functions, which take
// UTF-8. Standard C++, gtest and vkrt's headers only: the Windows build compiles it too. The
// names are written as bytes (the source stays ASCII); u8"" gives the letters to compare with.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/atomic_file.h"
#include "platform/file_io.h"
#include "platform/file_names.h"
#include "platform/file_status.h"
#include "platform/path_text.h"
#include "test_folder.h"

using namespace vkrt::platform;
namespace fs = std::filesystem;

namespace {

// Omega, u-umlaut, e-acute, n-tilde, and a CJK letter (U+56FE), in UTF-8.
const std::string kFolder = "Szene \xce\xa9 \xc3\xbc\xc3\xa9\xc3\xb1 \xe5\x9b\xbe";
const std::string kFile = "Bild-\xc3\xb1\xc3\xa9\xc3\xbc\xce\xa9\xe5\x9b\xbe.txt";

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(PathText, NamesRoundTripAndMeanTheLettersTheyHold) {
  for (const std::string& name : {kFolder, kFile, std::string("plain.txt"), std::string("a/b\xc3\xa9/c")})
    EXPECT_EQ(utf8FromPath(pathFromUtf8(name)), name);
  // The path holds the letters: what libstdc++ makes of char8_t text, on both systems.
  EXPECT_EQ(pathFromUtf8("\xce\xa9"), fs::path(u8"\u03a9"));
  EXPECT_EQ(pathFromUtf8(kFile), fs::path(u8"Bild-\u00f1\u00e9\u00fc\u03a9\u56fe.txt"));
  EXPECT_EQ(utf8FromPath(fs::path(u8"\u00fc")), "\xc3\xbc");
  // Taken apart, each part is still the name it was.
  const fs::path whole = pathFromUtf8(kFolder + "/" + kFile);
  EXPECT_EQ(utf8FromPath(whole.filename()), kFile);
  EXPECT_EQ(utf8FromPath(whole.parent_path()), kFolder);
  EXPECT_EQ(utf8FromPath(whole.stem()), "Bild-\xc3\xb1\xc3\xa9\xc3\xbc\xce\xa9\xe5\x9b\xbe");
  EXPECT_EQ(pathFromUtf8(kFolder) / pathFromUtf8(kFile), whole);   // equal, whichever separator each has
}

TEST(PathText, AFolderAndAFileInNonAsciiLettersAreFoundByTheirUtf8Names) {
  const fs::path root = pathFromUtf8(vkrt::test::freshFolder("path-text"));
  const fs::path folder = root / pathFromUtf8(kFolder);
  ASSERT_TRUE(fs::create_directories(folder));
  const fs::path file = folder / pathFromUtf8(kFile);
  std::ofstream(file, std::ios::binary) << "abc";

  // The layer's functions, given the UTF-8 names, find what std::filesystem made.
  const std::string folderName = utf8FromPath(folder), fileName = utf8FromPath(file);
  EXPECT_TRUE(isDirectory(folderName));
  EXPECT_TRUE(isRegularFile(fileName));
  const FileStatus st = statusOf(fileName);
  ASSERT_TRUE(st.found()) << st.error;
  EXPECT_EQ(st.size, 3u);
  const int fd = openForReading(fileName);
  ASSERT_GE(fd, 0);
  EXPECT_EQ(statusOfOpen(fd).identity, st.identity);
  closeFile(fd);
  // Its one name ends in the names it was given.
  const fs::path real = pathFromUtf8(canonicalName(fileName));
  EXPECT_EQ(utf8FromPath(real.filename()), kFile);
  EXPECT_EQ(utf8FromPath(real.parent_path().filename()), kFolder);
  EXPECT_EQ(canonicalName(utf8FromPath(folder / "new.txt")), utf8FromPath(real.parent_path() / "new.txt"));

  // Listed by std::filesystem, the folder holds exactly that name.
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) names.push_back(utf8FromPath(e.path().filename()));
  EXPECT_EQ(names, std::vector<std::string>{kFile});
  std::set<std::string> top;
  for (const fs::directory_entry& e : fs::directory_iterator(root)) top.insert(utf8FromPath(e.path().filename()));
  EXPECT_EQ(top, std::set<std::string>{kFolder});
}

// An output in such a folder is resolved and written there (a name read as Latin-1 and
// written back as UTF-8 would name a folder that does not exist).
TEST(PathText, AnOutputInANonAsciiFolderIsWrittenThere) {
  const fs::path root = pathFromUtf8(vkrt::test::freshFolder("path-text-output"));
  const fs::path folder = root / pathFromUtf8(kFolder);
  ASSERT_TRUE(fs::create_directories(folder));
  const std::string out = utf8FromPath(folder / pathFromUtf8(kFile));
  const vkrt::OutputFile resolved = vkrt::resolveOutputFile(out);
  EXPECT_FALSE(resolved.exists);
  EXPECT_EQ(utf8FromPath(pathFromUtf8(resolved.canonical).filename()), kFile);
  vkrt::writeFileAtomic(out, ".txt.tmp", [&](vkrt::ByteSink& file) {
    file.write(reinterpret_cast<const std::uint8_t*>("written"), 7);
  });
  EXPECT_EQ(readBytes(folder / pathFromUtf8(kFile)), "written");
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) names.push_back(utf8FromPath(e.path().filename()));
  EXPECT_EQ(names, std::vector<std::string>{kFile});
}

}  // namespace
