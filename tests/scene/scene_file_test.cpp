// Reading a scene file in process (host/scene/scene_file.h): the bytes as they are, from a
// regular file and from a pipe, over many read chunks; the stop after the first byte that is
// not text; the line limit at its exact edge and its line; a file that cannot be read.
#include <random>
#include <string>
#include <thread>

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "util/errors.h"
#include "scene/diagnostic.h"
#include "scene/scene_file.h"
#include "test_support.h"

namespace vkrt {
namespace {

// `n` bytes of text: every byte that is text (blanks, printable ASCII, bytes >= 0x80), with
// newlines often enough that no line nears the limit.
std::string generatedText(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::string s;
  s.reserve(n);
  while (s.size() < n) {
    const int c = static_cast<int>(rng() % 256);
    if (rng() % 64 == 0) s += '\n';
    else if (c >= 0x20 && c != 0x7F) s += static_cast<char>(c);
    else if (c == '\t' || c == '\r' || c == '\v' || c == '\f') s += static_cast<char>(c);
  }
  return s;
}

// The text `readSceneText` reads from a pipe while a thread writes `text` into it.
std::string readThroughPipe(const std::string& text) {
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  std::thread writer([&] {
    // A reader that stops early makes the next write fail with EPIPE: no SIGPIPE for it.
    sigset_t pipeSignal;
    sigemptyset(&pipeSignal);
    sigaddset(&pipeSignal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipeSignal, nullptr);
    std::size_t at = 0;
    while (at < text.size()) {
      const ssize_t n = ::write(fds[1], text.data() + at, text.size() - at);
      if (n <= 0) break;   // the reader stopped early
      at += static_cast<std::size_t>(n);
    }
    ::close(fds[1]);
  });
  std::string read;
  try {
    read = readSceneText("/dev/fd/" + std::to_string(fds[0]));
  } catch (...) {
    ::close(fds[0]);
    writer.join();
    throw;
  }
  ::close(fds[0]);
  writer.join();
  return read;
}

TEST(SceneFile, ARegularFileIsReadAsItIs) {
  const std::string dir = test::freshDir("scene-file/regular");
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{70000}, std::size_t{(3 << 20) + 17}}) {
    const std::string text = generatedText(n, static_cast<unsigned>(n));
    const std::string path = dir + "/s" + std::to_string(n) + ".test";
    test::writeFile(path, text);
    const std::string read = readSceneText(path);
    EXPECT_EQ(read.size(), text.size());
    EXPECT_TRUE(read == text) << n << " bytes";
  }
}

TEST(SceneFile, APipeIsReadAsItIs) {
  for (std::size_t n : {std::size_t{0}, std::size_t{5}, std::size_t{(1 << 16) + 1}, std::size_t{(5 << 20) + 3}}) {
    const std::string text = generatedText(n, static_cast<unsigned>(n) + 1);
    const std::string read = readThroughPipe(text);
    EXPECT_EQ(read.size(), text.size());
    EXPECT_TRUE(read == text) << n << " bytes";
  }
}

TEST(SceneFile, ReadingEndsWithTheFirstByteThatIsNotText) {
  const std::string dir = test::freshDir("scene-file/binary");
  const std::string head = generatedText((2 << 20) + 5, 9);   // past the first read's mebibyte
  for (char bad : {'\0', '\x01', '\x1B', '\x7F'}) {
    const std::string text = head + bad + "size 1 1\n" + std::string(1, '\0');
    test::writeFile(dir + "/b.test", text);
    const std::string read = readSceneText(dir + "/b.test");
    ASSERT_EQ(read.size(), head.size() + 1);
    EXPECT_TRUE(read.compare(0, head.size(), head) == 0);
    EXPECT_EQ(read.back(), bad);
    EXPECT_TRUE(readThroughPipe(text) == read);   // (not EXPECT_EQ: it would print megabytes)
  }
}

// The line number of the SceneError that reading `text` gives, or 0 when it gives none.
int lineOfLimitError(const std::string& path, const std::string& text, bool pipe) {
  try {
    if (pipe) readThroughPipe(text);
    else {
      test::writeFile(path, text);
      readSceneText(path);
    }
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diagnostics().size(), 1u);
    const Diagnostic& d = e.diagnostics().front();
    EXPECT_NE(d.message.find("the line is longer than 1048576 bytes"), std::string::npos) << d.message;
    if (!pipe) {
      EXPECT_EQ(d.file, path);
    }
    return d.line;
  }
  return 0;
}

TEST(SceneFile, ALineMayHoldOneMebibyteAndNoMore) {
  const std::string dir = test::freshDir("scene-file/line");
  const std::string path = dir + "/l.test";
  const std::string first = "size 10 10\n# two\n";   // the long line is line 3
  const std::string edge(kMaxSceneLineBytes, 'x'), over(kMaxSceneLineBytes + 1, 'x');
  for (bool pipe : {false, true}) {
    EXPECT_EQ(lineOfLimitError(path, first + edge + "\nend\n", pipe), 0) << "pipe " << pipe;
    EXPECT_EQ(lineOfLimitError(path, first + edge, pipe), 0) << "pipe " << pipe;
    EXPECT_EQ(lineOfLimitError(path, first + over + "\nend\n", pipe), 3) << "pipe " << pipe;
    EXPECT_EQ(lineOfLimitError(path, first + over, pipe), 3) << "pipe " << pipe;   // the last line, no newline
  }
}

TEST(SceneFile, AFileThatCannotBeReadIsAnIoError) {
  const std::string dir = test::freshDir("scene-file/missing");
  try {
    readSceneText(dir + "/none.test");
    FAIL() << "no IoError";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot open scene file '" + dir + "/none.test': No such file or directory");
  }
  try {
    readSceneText(dir);
    FAIL() << "no IoError";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read scene file '" + dir + "': Is a directory");
  }
}

}  // namespace
}  // namespace vkrt
