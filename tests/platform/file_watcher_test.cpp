// The platform layer's file watcher (host/platform/file_watcher.h), on the system the tests run
// on: Linux's inotify, and Windows' ReadDirectoryChangesW under Wine. The watcher must name
// the file's own changes (a write, a file renamed over it as editors save, a deletion) and
// tell them from other files' in the same folder, and its identity must change with them.
// What a change is once settled is watch/file_watch's (tests/cli/watch_test.cpp). Standard
// C++, gtest and the layer only: the Windows build compiles the same file.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "platform/file_watcher.h"
#include "test_folder.h"

using vkrt::platform::FileWatcher;
using vkrt::platform::WatchError;
using Seen = FileWatcher::Seen;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// Waits up to 5 s for notices that name the file: whether some came (Whole, or Partial where a
// write is announced as it goes), reading every notice until a quiet 100 ms.
bool namedWithin(FileWatcher& watcher) {
  bool named = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < deadline) {
    const Seen seen = watcher.wait(named ? 100 : 500);
    if (seen == Seen::Whole || seen == Seen::Partial) named = true;
    else if (seen == Seen::Nothing && named) break;
  }
  return named;
}

// Reads whatever notices are pending, until a quiet 100 ms: whether one named the file.
bool drained(FileWatcher& watcher) {
  bool named = false;
  for (Seen seen; (seen = watcher.wait(100)) != Seen::Nothing;)
    named = named || seen == Seen::Whole || seen == Seen::Partial;
  return named;
}

}  // namespace

TEST(FileWatcher, SeesAWriteAndTellsItFromOtherFiles) {
  const fs::path dir = vkrt::test::freshFolder("watcher_write");
  const fs::path scene = dir / "scene.test";
  write(scene, "size 4 4\n");
  FileWatcher watcher(scene.string());
  EXPECT_EQ(watcher.wait(50), Seen::Nothing);
  const std::string before = watcher.identity();
  EXPECT_FALSE(before.empty());

  write(dir / "other.test", "not the scene\n");   // the same folder, another name
  EXPECT_FALSE(drained(watcher)) << "a write to another file was taken for the scene's";

  write(scene, "size 8 8\n");
  EXPECT_TRUE(namedWithin(watcher)) << "a write to the file was not seen";
  EXPECT_NE(watcher.identity(), before);
}

TEST(FileWatcher, SeesAFileRenamedOverItAndADeletion) {
  const fs::path dir = vkrt::test::freshFolder("watcher_rename");
  const fs::path scene = dir / "scene.test";
  write(scene, "size 4 4\n");
  FileWatcher watcher(scene.string());
  const std::string before = watcher.identity();

  // As an editor saves: a new file beside it, renamed over it.
  write(dir / "scene.test.swp", "size 16 16\n");
  drained(watcher);   // (the new file's own notices name another file)
  fs::rename(dir / "scene.test.swp", scene);
  EXPECT_TRUE(namedWithin(watcher)) << "a file renamed over the watched one was not seen";
  const std::string renamed = watcher.identity();
  EXPECT_NE(renamed, before);
  EXPECT_FALSE(renamed.empty());

  fs::remove(scene);
  EXPECT_TRUE(namedWithin(watcher)) << "the deletion was not seen";
  EXPECT_EQ(watcher.identity(), "");   // gone: no identity
}

TEST(FileWatcher, AFolderThatIsNotThereCannotBeWatched) {
  const fs::path dir = vkrt::test::freshFolder("watcher_missing");
  const fs::path scene = dir / "no such folder" / "scene.test";
  try {
    FileWatcher watcher(scene.string());
    FAIL() << "a file in a missing folder was watched";
  } catch (const WatchError& e) {
    EXPECT_EQ(fs::path(e.folder()), scene.parent_path());
    EXPECT_FALSE(std::string(e.what()).empty());
  }
}
