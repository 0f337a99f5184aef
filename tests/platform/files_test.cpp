// The platform layer's file functions (host/platform/file_*.h), on the system the tests run on:
// Linux, and Windows under Wine. Each test is the trap it guards against on one system or the
// other: mingw's stat gives every file the identity 0 and one name; a read without _O_BINARY
// turns CRLF into LF and stops at byte 0x1A; a positional write that moves the file's position.
// Standard C++ and the layer only, so that the Windows build compiles the same file.
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "platform/file_changes.h"
#include "platform/file_io.h"
#include "platform/file_names.h"
#include "platform/file_permissions.h"
#include "platform/file_status.h"
#include "test_folder.h"

using namespace vkrt::platform;
namespace fs = std::filesystem;

namespace {

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Everything `fd` reads from where it is to the end, by the layer's readSome.
std::string readToEnd(int fd) {
  std::string text;
  char buf[4];   // small: several reads, so that a read stopping early shows
  for (;;) {
    const std::int64_t n = readSome(fd, buf, sizeof buf);
    if (n <= 0) return n < 0 ? "(read failed)" : text;
    text.append(buf, static_cast<std::size_t>(n));
  }
}

std::size_t entries(const std::string& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(PlatformFiles, StatusTellsRegularFilesFoldersAndNothing) {
  const std::string dir = vkrt::test::freshFolder("status");
  const std::string file = (fs::path(dir) / "three.bin").string();
  writeBytes(file, "abc");

  const FileStatus f = statusOf(file);
  ASSERT_TRUE(f.found()) << f.error;
  EXPECT_EQ(f.kind, FileKind::Regular);
  EXPECT_EQ(f.size, 3u);
  EXPECT_EQ(f.links, 1u);
  EXPECT_TRUE(isRegularFile(file));
  EXPECT_FALSE(isDirectory(file));

  const FileStatus d = statusOf(dir);
  ASSERT_TRUE(d.found()) << d.error;
  EXPECT_EQ(d.kind, FileKind::Directory);
  EXPECT_TRUE(isDirectory(dir));
  EXPECT_FALSE(isRegularFile(dir));

  const FileStatus missing = statusOf((fs::path(dir) / "missing.bin").string());
  EXPECT_FALSE(missing.found());
  EXPECT_EQ(missing.error, ENOENT);
  EXPECT_FALSE(isRegularFile((fs::path(dir) / "missing.bin").string()));
  EXPECT_FALSE(statusOf("").found());

  // A regular file on the way: POSIX says ENOTDIR, Windows ENOENT; either way nothing.
  const FileStatus through = statusOf((fs::path(file) / "x").string());
  EXPECT_FALSE(through.found());
  EXPECT_TRUE(through.error == ENOTDIR || through.error == ENOENT) << through.error;

  std::FILE* stream = std::fopen(file.c_str(), "rb");
  ASSERT_NE(stream, nullptr);
  const FileStatus open = statusOfOpen(stream);
  std::fclose(stream);
  EXPECT_TRUE(open.is(FileKind::Regular));
  EXPECT_EQ(open.size, 3u);
  EXPECT_EQ(open.identity, f.identity);
}

// Two names of one file are one file, with two names; a copy is another file. (mingw's stat
// gives st_ino 0 and st_nlink 1: every file would be the same, and none hard-linked.)
TEST(PlatformFiles, TwoNamesOfOneFileAreOneFileAndACopyIsAnother) {
  const std::string dir = vkrt::test::freshFolder("identity");
  const std::string a = (fs::path(dir) / "a.png").string(), b = (fs::path(dir) / "b.png").string(),
                    copy = (fs::path(dir) / "copy.png").string(), other = (fs::path(dir) / "other.png").string();
  writeBytes(a, "the same bytes");
  writeBytes(other, "the same bytes");
  fs::create_hard_link(a, b);
  fs::copy_file(a, copy);

  const FileStatus sa = statusOf(a), sb = statusOf(b), sc = statusOf(copy), so = statusOf(other);
  ASSERT_TRUE(sa.found() && sb.found() && sc.found() && so.found());
  EXPECT_EQ(sa.identity, sb.identity);
  EXPECT_EQ(sa.links, 2u);
  EXPECT_EQ(sb.links, 2u);
  EXPECT_NE(sa.identity.file, 0u);
  EXPECT_FALSE(sa.identity == sc.identity);
  EXPECT_FALSE(sa.identity == so.identity);
  EXPECT_FALSE(sc.identity == so.identity);
  EXPECT_EQ(sc.links, 1u);
  EXPECT_EQ(linkStatusOf(a).identity, sa.identity);   // not a link: the file itself

  // The identity of an open file is the identity of its name.
  const int fd = openForReading(b);
  ASSERT_GE(fd, 0) << errno;
  EXPECT_EQ(statusOfOpen(fd).identity, sa.identity);
  closeFile(fd);
}

// A read gives the bytes that are there: a CR before an LF and a byte 0x1A (which Windows'
// text mode takes as the end of the file) come back as they are.
TEST(PlatformFiles, ReadingIsBinary) {
  const std::string dir = vkrt::test::freshFolder("binary-read");
  const std::string path = (fs::path(dir) / "crlf.test").string();
  const std::string bytes = std::string("size 2 2\r\n\x1A after\r\nend\n\0tail", 27);
  writeBytes(path, bytes);

  const int fd = openForReading(path);
  ASSERT_GE(fd, 0) << errno;
  EXPECT_EQ(readToEnd(fd), bytes);
  char at[5] = {};
  EXPECT_EQ(readSomeAt(fd, at, 4, 8), 4);   // "\r\n\x1A "
  EXPECT_EQ(std::string(at, 4), std::string("\r\n\x1A ", 4));
  EXPECT_EQ(closeFile(fd), 0);

  EXPECT_LT(openForReading((fs::path(dir) / "missing.test").string()), 0);
  EXPECT_EQ(errno, ENOENT);
}

// write appends at the file's position; a write at an offset leaves that position alone.
TEST(PlatformFiles, WriteAndWriteAtAnOffset) {
  const std::string dir = vkrt::test::freshFolder("write");
  std::string path = (fs::path(dir) / "x-XXXXXX.bin").string();
  const int fd = createTemporaryFile(path, 4);
  ASSERT_GE(fd, 0) << errno;
  EXPECT_EQ(fs::path(path).parent_path(), fs::path(dir));
  EXPECT_EQ(fs::path(path).extension(), ".bin");
  EXPECT_EQ(fs::path(path).filename().string().size(), std::string("x-XXXXXX.bin").size());
  EXPECT_EQ(fs::path(path).filename().string().find("XXXXXX"), std::string::npos);
  EXPECT_TRUE(isRegularFile(path));

  EXPECT_EQ(writeSome(fd, "hello world", 11), 11);
  EXPECT_EQ(writeSomeAt(fd, "W", 1, 6), 1);
  EXPECT_EQ(writeSome(fd, "!\r\n", 3), 3);   // after "world", not after "W"; no CR added
  EXPECT_EQ(writeSomeAt(fd, "\x1A", 1, 16), 1);   // past the end: a gap of zeros
  EXPECT_EQ(syncFile(fd), 0);
  EXPECT_EQ(statusOfOpen(fd).size, 17u);
  EXPECT_EQ(closeFile(fd), 0);
  EXPECT_EQ(readBytes(path), std::string("hello World!\r\n\0\0\x1A", 17));
}

TEST(PlatformFiles, TemporaryNamesAreNew) {
  const std::string dir = vkrt::test::freshFolder("temporary-names");
  std::set<std::string> names;
  for (int i = 0; i < 20; ++i) {
    std::string path = (fs::path(dir) / ".vkrt-XXXXXX.png.tmp").string();
    const int fd = createTemporaryFile(path, 8);
    ASSERT_GE(fd, 0) << errno;
    closeFile(fd);
    EXPECT_TRUE(names.insert(path).second) << path;
  }
  EXPECT_EQ(entries(dir), 20u);

  std::string folder = (fs::path(dir) / "folder-XXXXXX").string();
  ASSERT_TRUE(createTemporaryDirectory(folder)) << errno;
  EXPECT_TRUE(isDirectory(folder));
  EXPECT_EQ(folder.find("XXXXXX"), std::string::npos);

  std::string bad = (fs::path(dir) / "no-pattern").string();
  EXPECT_LT(createTemporaryFile(bad, 0), 0);
}

// A finished temporary file takes the target's place whole: nothing of the old content
// remains (it was longer), and no temporary file is left.
TEST(PlatformFiles, ReplacingPutsTheNewFileInPlaceWhole) {
  const std::string dir = vkrt::test::freshFolder("replace");
  const std::string target = (fs::path(dir) / "image.png").string();
  writeBytes(target, "the old image, longer than the new one");
  std::string temporary = (fs::path(dir) / ".vkrt-XXXXXX.png.tmp").string();
  const int fd = createTemporaryFile(temporary, 8);
  ASSERT_GE(fd, 0) << errno;
  EXPECT_EQ(writeSome(fd, "new", 3), 3);
  EXPECT_EQ(closeFile(fd), 0);
  const FileIdentity made = statusOf(temporary).identity;

  ASSERT_EQ(replaceFile(temporary, target), 0) << errno;
  EXPECT_EQ(readBytes(target), "new");
  EXPECT_FALSE(statusOf(temporary).found());
  EXPECT_EQ(statusOf(target).identity, made);
  EXPECT_EQ(entries(dir), 1u);

  // A new target, and a folder moved into place.
  const std::string folder = (fs::path(dir) / "report").string(), moved = (fs::path(dir) / "report2").string();
  fs::create_directory(folder);
  ASSERT_EQ(replaceFile(folder, moved), 0) << errno;
  EXPECT_TRUE(isDirectory(moved));
  EXPECT_FALSE(statusOf(folder).found());

  EXPECT_NE(replaceFile((fs::path(dir) / "missing").string(), target), 0);
  EXPECT_EQ(errno, ENOENT);
  EXPECT_EQ(readBytes(target), "new");
  EXPECT_EQ(removeFile(target), 0);
  EXPECT_FALSE(statusOf(target).found());
}

TEST(PlatformFiles, CanonicalNamesResolveDotsAndMissingFiles) {
  const std::string dir = vkrt::test::freshFolder("canonical");
  fs::create_directory(fs::path(dir) / "a");
  const std::string b = (fs::path(dir) / "b").string();
  writeBytes(b, "b");
  const std::optional<std::string> realDir = realPath(dir), realB = realPath(b);
  ASSERT_TRUE(realDir && realB);
  EXPECT_TRUE(fs::path(*realB).is_absolute());
  EXPECT_EQ(*realB, (fs::path(*realDir) / "b").string());

  EXPECT_EQ(canonicalName(b), *realB);
  EXPECT_EQ(canonicalName((fs::path(dir) / "a" / ".." / "b").string()), *realB);
  EXPECT_EQ(canonicalName((fs::path(dir) / "." / "b").string()), *realB);
  // Not there: its folder's real name and its own.
  EXPECT_EQ(canonicalName((fs::path(dir) / "a" / ".." / "c").string()), (fs::path(*realDir) / "c").string());
  // Neither it nor its folder: the part that is there, and the rest made normal.
  EXPECT_EQ(canonicalName((fs::path(dir) / "x" / "y" / ".." / "z").string()),
            (fs::path(*realDir) / "x" / "z").string());
  EXPECT_EQ(canonicalName((fs::path(dir) / "x" / ".." / "a" / "w").string()),
            (fs::path(*realDir) / "a" / "w").string());

  errno = 0;
  EXPECT_FALSE(realPath((fs::path(dir) / "c").string()));
  EXPECT_EQ(errno, ENOENT);
}

// A symbolic link is seen as a link without following it, its text read back, and followed
// by statusOf. (Windows lets only an administrator or developer mode make one.)
TEST(PlatformFiles, SymbolicLinksAreReadAndFollowed) {
  const std::string dir = vkrt::test::freshFolder("links");
  const std::string target = (fs::path(dir) / "target.png").string(), link = (fs::path(dir) / "link.png").string();
  writeBytes(target, "12345");
  std::error_code ec;
  fs::create_symlink("target.png", link, ec);
  if (ec) GTEST_SKIP() << "cannot make a symbolic link here: " << ec.message();

  EXPECT_EQ(linkStatusOf(link).kind, FileKind::SymbolicLink);
  EXPECT_EQ(statusOf(link).kind, FileKind::Regular);
  EXPECT_EQ(statusOf(link).size, 5u);
  EXPECT_EQ(statusOf(link).identity, statusOf(target).identity);
  EXPECT_EQ(readSymbolicLink(link), std::optional<std::string>("target.png"));
  EXPECT_EQ(canonicalName(link), *realPath(target));
  errno = 0;
  EXPECT_FALSE(readSymbolicLink(target));
  EXPECT_EQ(errno, EINVAL);

  // A name that is not there, through a linked folder: the link is resolved all the same.
  fs::create_directory(fs::path(dir) / "real");
  fs::create_directory_symlink("real", fs::path(dir) / "linked", ec);
  if (ec) GTEST_SKIP() << "cannot make a symbolic link to a folder here: " << ec.message();
  const std::string realFolder = *realPath((fs::path(dir) / "real").string());
  EXPECT_EQ(canonicalName((fs::path(dir) / "linked" / "new.png").string()),
            (fs::path(realFolder) / "new.png").string());
  EXPECT_EQ(canonicalName((fs::path(dir) / "linked" / "x" / "y" / ".." / "z.png").string()),
            (fs::path(realFolder) / "x" / "z.png").string());
}

// Permission bits as the system keeps them: all of them on POSIX, the write bit alone on
// Windows (the read-only attribute).
TEST(PlatformFiles, PermissionBits) {
  const std::string dir = vkrt::test::freshFolder("permissions");
  const std::string path = (fs::path(dir) / "file").string();
  writeBytes(path, "x");
  ASSERT_EQ(setMode(path, 0444), 0) << errno;
  EXPECT_EQ(statusOf(path).mode & 0222, 0u);
  if (!changesOwners()) {   // root may write anything
    EXPECT_FALSE(isWritable(path));
  }
  ASSERT_EQ(setMode(path, 0640), 0) << errno;
  EXPECT_NE(statusOf(path).mode & 0200, 0u);
  EXPECT_TRUE(isWritable(path));
#ifndef _WIN32
  EXPECT_EQ(statusOf(path).mode, 0640u);
  const int fd = openForReading(path);
  ASSERT_GE(fd, 0);
  EXPECT_EQ(setOpenMode(fd, 04751), 0);
  EXPECT_EQ(statusOf(path).mode, 04751u);
  closeFile(fd);
#endif
  EXPECT_EQ(creationMask() & ~0777u, 0u);
}

}  // namespace
