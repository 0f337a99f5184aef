// vkrt never loses a user's file: an output that is a file the run reads (the scene, the
// --check reference, diff's images, merge's tiles, another scene of a batch) or another of
// its outputs is refused before anything is rendered or written, however it is spelt; a
// symbolic link is written through, an existing file keeps its permissions and owner, a
// device, FIFO or hard-linked file is never replaced; a signal or a failure while writing
// leaves no temporary file. And reading a scene is bounded: a device, an endless stream, a
// line or a file past the limits stop the read at once, and Ctrl-C stops a read that waits.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "util/errors.h"
#include "image/atomic_file.h"
#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

namespace {

const std::string kScene = "size 20 15\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\ndiffuse 0.5 0 0\n"
                           "sphere 0 0 0 1\n";
const std::string kPrecious = "the user's file: must survive";

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Files vkrt left beside its output (temporary files or write probes).
std::vector<std::string> leftovers(const std::string& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().rfind(".vkrt-", 0) == 0) found.push_back(e.path().string());
  return found;
}

// A black 20x15 PNG (a "reference" that the render does not match).
void writeBlackPng(const std::string& path) {
  writePngAtomic(Image(20, 15), path);
}

::testing::AssertionResult waitingForSignal(const std::string& logPath, const std::string& stage) {
  const std::string line = "vkrt: test hook: waiting for a signal during the " + stage;
  for (int i = 0; i < 60000; ++i) {
    if (contains(readFile(logPath), line)) return ::testing::AssertionSuccess();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return ::testing::AssertionFailure() << "vkrt never got to the " << stage << ": " << readFile(logPath);
}

// Runs `command` with sh (stdout and stderr together), from `dir`.
RunResult runShell(const std::string& dir, const std::string& command) {
  return runCommand("cd '" + dir + "' && " + command);
}

const std::string kVkrt = "'" + vkrtBinary() + "'";

// "ulimit -v KB && ": caps vkrt's address space, so that a vkrt that reads without end
// fails the test instead of taking the machine's memory. Not under AddressSanitizer, which
// reserves more address space than any such cap (the bounds hold without it).
std::string memoryCap(long kb) {
#if defined(VKRT_SANITIZE_BUILD)   // GCC defines __SANITIZE_ADDRESS__, clang 14 does not
  (void)kb;
  return "";
#else
  return "ulimit -v " + std::to_string(kb) + " && ";
#endif
}

}  // namespace

// --check REF where the render's own output is REF (the scene's `output` line, -o, another
// spelling, a symbolic link, a hard link): refused before the render, REF untouched.
TEST(FileSafety, TheCheckReferenceIsNeverTheOutput) {
  std::string dir = freshDir("file-safety/check-reference");
  writeBlackPng(dir + "/ref.png");
  const std::string before = readFile(dir + "/ref.png");
  writeFile(dir + "/line.test", kScene + "output " + dir + "/ref.png\n");
  writeFile(dir + "/plain.test", kScene);
  fs::create_symlink("ref.png", dir + "/link.png");
  for (const std::string& args :
       {dir + "/line.test --check " + dir + "/ref.png", dir + "/plain.test -o " + dir + "/ref.png --check " + dir +
                                                            "/ref.png",
        dir + "/plain.test -o " + dir + "/./ref.png --check " + dir + "/ref.png",
        dir + "/plain.test -o " + dir + "/link.png --check " + dir + "/ref.png",
        dir + "/plain.test -o " + dir + "/ref.png --check " + dir + "/link.png"}) {
    RunResult r = runVkrt("--backend cpu " + args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "it is the reference image (--check)")) << r.output;
    EXPECT_FALSE(contains(r.output, "usage:")) << r.output;   // a refusal, not a syntax error
    EXPECT_FALSE(contains(r.output, "PASS")) << r.output;
    EXPECT_EQ(readFile(dir + "/ref.png"), before) << args;
  }
  // A hard link to the reference is the reference too, and told as such (not as a file of two
  // names that cannot be replaced); so is a hard link to the scene, and to a tile of merge.
  fs::create_hard_link(dir + "/ref.png", dir + "/hard.png");
  RunResult hard = runVkrt("--backend cpu " + dir + "/plain.test -o " + dir + "/hard.png --check " + dir + "/ref.png");
  EXPECT_EQ(hard.exitCode, 1) << hard.output;
  EXPECT_TRUE(contains(hard.output, "refusing to write the image '" + dir + "/hard.png': it is the reference image "
                                    "(--check)")) << hard.output;
  EXPECT_EQ(readFile(dir + "/ref.png"), before);
  const std::string scene = readFile(dir + "/plain.test");
  fs::create_hard_link(dir + "/plain.test", dir + "/hard.test");
  RunResult hardScene = runVkrt("--backend cpu -o " + dir + "/hard.test " + dir + "/plain.test");
  EXPECT_EQ(hardScene.exitCode, 1) << hardScene.output;
  EXPECT_TRUE(contains(hardScene.output, "it is the scene file")) << hardScene.output;
  EXPECT_EQ(readFile(dir + "/plain.test"), scene);
  RunResult hardTile = runVkrt("merge -o " + dir + "/hard.png " + dir + "/ref.png");
  EXPECT_EQ(hardTile.exitCode, 1) << hardTile.output;
  EXPECT_TRUE(contains(hardTile.output, "it is the tile")) << hardTile.output;
  EXPECT_EQ(readFile(dir + "/ref.png"), before);
  EXPECT_TRUE(leftovers(dir).empty());
}

// The scene file as the output: by -o, by its own `output` line, through a symbolic link;
// in a batch, one scene's output naming another scene (later or earlier) of the batch.
TEST(FileSafety, TheSceneFileIsNeverTheOutput) {
  std::string dir = freshDir("file-safety/scene");
  const std::string self = kScene + "output " + dir + "/self.test\n";
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/self.test", self);
  fs::create_symlink("s.test", dir + "/scene-link.png");
  struct Case {
    std::string args, scene;
  };
  for (const Case& c : {Case{"-o " + dir + "/s.test " + dir + "/s.test", "s.test"},
                        Case{"-o " + dir + "/../scene/s.test " + dir + "/s.test", "s.test"},
                        Case{"-o " + dir + "/scene-link.png " + dir + "/s.test", "s.test"},
                        Case{dir + "/self.test", "self.test"}}) {
    const std::string text = readFile(dir + "/" + c.scene);
    RunResult r = runVkrt("--backend cpu " + c.args);
    EXPECT_EQ(r.exitCode, 1) << c.args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "it is the scene file")) << r.output;
    EXPECT_EQ(readFile(dir + "/" + c.scene), text) << c.args;
  }
  EXPECT_TRUE(fs::is_symlink(dir + "/scene-link.png"));
  // A batch: a.test writes b.test (the next scene), c.test writes a.test (an earlier one).
  writeFile(dir + "/a.test", kScene + "output " + dir + "/b.test\n");
  writeFile(dir + "/b.test", kScene + "output " + dir + "/b.png\n");
  writeFile(dir + "/c.test", kScene + "output " + dir + "/a.test\n");
  const std::string a = readFile(dir + "/a.test"), b = readFile(dir + "/b.test");
  RunResult batch = runVkrt("--backend cpu " + dir + "/a.test " + dir + "/b.test " + dir + "/c.test");
  EXPECT_EQ(batch.exitCode, 1) << batch.output;
  EXPECT_TRUE(contains(batch.output, "1 rendered, 2 failed")) << batch.output;
  EXPECT_EQ(readFile(dir + "/a.test"), a);
  EXPECT_EQ(readFile(dir + "/b.test"), b);
  EXPECT_EQ(readImage(dir + "/b.png").width, 20);   // the scene that writes elsewhere renders
}

// Two outputs of a batch that are one file: through a linked folder, or a symbolic link to
// the first one's image. The second is refused; the first image stays.
TEST(FileSafety, TwoOutputsOfABatchAreNeverOneFile) {
  std::string dir = freshDir("file-safety/batch-collision");
  fs::create_directories(dir + "/out");
  fs::create_directory_symlink("out", dir + "/linked");
  fs::create_symlink("out/same.png", dir + "/same-link.png");
  writeFile(dir + "/a.test", kScene + "output " + dir + "/out/same.png\n");
  writeFile(dir + "/b.test", "size 20 15\ncamera 0 0 5 0 0 0 0 1 0 45\noutput " + dir + "/linked/same.png\n");
  writeFile(dir + "/c.test", "size 20 15\ncamera 0 0 5 0 0 0 0 1 0 45\noutput " + dir + "/same-link.png\n");
  RunResult r = runVkrt("--backend cpu " + dir + "/a.test " + dir + "/b.test " + dir + "/c.test");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(contains(r.output, "1 rendered, 2 failed")) << r.output;
  EXPECT_TRUE(contains(r.output, "it is also the output of " + dir + "/a.test")) << r.output;
  EXPECT_GT(readImage(dir + "/out/same.png").pixel(10, 7)[0], 50);   // a's red sphere, not b's black
  EXPECT_TRUE(fs::is_symlink(dir + "/same-link.png"));
}

// diff A B --diff A, and merge -o TILE: refused; the inputs stay.
TEST(FileSafety, DiffAndMergeNeverWriteTheirInputs) {
  std::string dir = freshDir("file-safety/diff-merge");
  writeFile(dir + "/s.test", kScene);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/a.png " + dir + "/s.test").exitCode, 0);
  writeBlackPng(dir + "/b.png");
  const std::string a = readFile(dir + "/a.png"), b = readFile(dir + "/b.png");
  for (const std::string& heatmap : {dir + "/a.png", dir + "/./b.png"}) {
    RunResult r = runVkrt("diff " + dir + "/a.png " + dir + "/b.png --diff " + heatmap);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "refusing to write the heatmap (--diff)")) << r.output;
  }
  EXPECT_EQ(readFile(dir + "/a.png"), a);
  EXPECT_EQ(readFile(dir + "/b.png"), b);
  // --check with a heatmap that is the scene file, or the render's own output.
  RunResult check = runVkrt("--backend cpu " + dir + "/s.test -o " + dir + "/o.png --check " + dir + "/b.png --diff " +
                            dir + "/o.png");
  EXPECT_EQ(check.exitCode, 1) << check.output;
  EXPECT_TRUE(contains(check.output, "it is also the heatmap (--diff)")) << check.output;
  EXPECT_FALSE(fileExists(dir + "/o.png"));
  ASSERT_EQ(runVkrt("-q --backend cpu --crop 0,0,10,15 -o " + dir + "/t1.png " + dir + "/s.test").exitCode, 0);
  ASSERT_EQ(runVkrt("-q --backend cpu --crop 10,0,20,15 -o " + dir + "/t2.png " + dir + "/s.test").exitCode, 0);
  const std::string t2 = readFile(dir + "/t2.png");
  RunResult merge = runVkrt("merge -o " + dir + "/t2.png " + dir + "/t1.png " + dir + "/t2.png");
  EXPECT_EQ(merge.exitCode, 1) << merge.output;
  EXPECT_TRUE(contains(merge.output, "it is the tile")) << merge.output;
  EXPECT_EQ(readFile(dir + "/t2.png"), t2);
  EXPECT_TRUE(leftovers(dir).empty());
}

// An output named as a scene file (*.test, any case) is refused, however it is named (-o, the
// scene's `output` line, merge -o, convert, diff --diff), and the scene that had that name is
// as it was: swapped arguments must not turn a scene into a PNG.
TEST(FileSafety, AnOutputNamedAsASceneIsRefused) {
  std::string dir = freshDir("file-safety/scene-named-output");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/other.test", kScene);
  writeFile(dir + "/line.test", kScene + "output " + dir + "/out.TEST\n");
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/a.png " + dir + "/s.test").exitCode, 0);
  const std::string refused = "': that is a scene file's name (.test)";
  struct Case {
    std::string args, says;
  };
  const std::vector<Case> cases = {
      {"--backend cpu -o " + dir + "/other.test " + dir + "/s.test", "cannot write '" + dir + "/other.test" + refused},
      {"--backend cpu " + dir + "/line.test", "cannot write '" + dir + "/out.TEST" + refused},
      {"merge -o " + dir + "/other.test " + dir + "/a.png", "cannot write '" + dir + "/other.test" + refused},
      {"diff " + dir + "/a.png " + dir + "/a.png --diff " + dir + "/other.test",
       "cannot write '" + dir + "/other.test" + refused},
      // convert's output name must say its format anyway.
      {"convert " + dir + "/a.png " + dir + "/other.test", "is not named .png, .ppm, .pfm or .exr"},
  };
  for (const Case& c : cases) {
    RunResult r = runVkrt(c.args);
    EXPECT_NE(r.exitCode, 0) << c.args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, c.says)) << r.output;
    // The refusal alone: no warning first that the name will be written as PNG.
    if (c.args.rfind("convert", 0) != 0) {
      EXPECT_FALSE(contains(r.output, "vkrt writes PNG")) << r.output;
    }
  }
  // -o: an I/O error; the scene's `output` line: a scene error at that line.
  EXPECT_EQ(runVkrt("--backend cpu -o " + dir + "/other.test " + dir + "/s.test").exitCode, 4);
  RunResult line = runVkrt("--backend cpu " + dir + "/line.test");
  EXPECT_EQ(line.exitCode, 2);
  EXPECT_TRUE(contains(line.output, "line.test:6: error: cannot write")) << line.output;
  EXPECT_EQ(readFile(dir + "/other.test"), kScene);
  EXPECT_FALSE(fileExists(dir + "/out.TEST"));
  EXPECT_TRUE(leftovers(dir).empty());
}

// merge reads each input more than once (records, then pixels): an input that can be read
// only once (a pipe), whose opening waits for a writer (a FIFO), or a folder is an I/O error
// naming it, before anything is opened. (A pipe crashed merge of float tiles: the second
// look at its format found nothing.)
TEST(FileSafety, MergeRefusesInputsThatAreNotFiles) {
  std::string dir = freshDir("file-safety/merge-not-files");
  writeFile(dir + "/c.test", "size 16 12\nintegrator pathtracer\nspp 2\ncamera 0 0 4 0 0 0 0 1 0 45\n"
                             "quadLight -1 2 -1 2 0 0 0 0 2 5 5 5\ndiffuse 0.5 0.5 0.5\nsphere 0 0 0 1\n");
  for (int seed : {1, 2})
    ASSERT_EQ(runVkrt("-q --backend cpu --seed " + std::to_string(seed) + " -o " + dir + "/b" + std::to_string(seed) +
                      ".pfm " + dir + "/c.test").exitCode, 0);
  ASSERT_EQ(::mkfifo((dir + "/fifo.pfm").c_str(), 0600), 0);
  fs::create_directories(dir + "/folder.pfm");
  struct Case {
    std::string inputs, named, why;
  };
  const std::vector<Case> cases = {
      {"<(cat " + dir + "/b1.pfm) <(cat " + dir + "/b2.pfm)", "/dev/fd/", "it is not a regular file"},
      {dir + "/b1.pfm <(cat " + dir + "/b2.pfm)", "/dev/fd/", "it is not a regular file"},
      {dir + "/b1.pfm " + dir + "/fifo.pfm", dir + "/fifo.pfm", "it is not a regular file"},
      {dir + "/b1.pfm " + dir + "/folder.pfm", dir + "/folder.pfm", "Is a directory"},
  };
  for (const Case& c : cases) {
    // bash for <(...); timeout in case a FIFO is opened after all.
    RunResult r =
        runCommand("timeout 20 bash -c '\"" + vkrtBinary() + "\" merge -o " + dir + "/out.pfm " + c.inputs + "'");
    EXPECT_EQ(r.exitCode, 4) << c.inputs << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "cannot read image '" + c.named)) << r.output;
    EXPECT_TRUE(contains(r.output, c.why)) << r.output;
    EXPECT_FALSE(fileExists(dir + "/out.pfm"));
  }
  EXPECT_EQ(runVkrt("merge -q -o " + dir + "/out.pfm " + dir + "/b1.pfm " + dir + "/b2.pfm").exitCode, 0);
  EXPECT_TRUE(leftovers(dir).empty());
}

// --check with a reference that is missing or no image: exit 4 before anything is
// rendered, the existing output as it was.
TEST(FileSafety, TheCheckReferenceIsReadBeforeTheRender) {
  std::string dir = freshDir("file-safety/reference-first");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/o.png", kPrecious);
  writeFile(dir + "/garbage.png", "not an image");
  for (const std::string& ref : {dir + "/missing.png", dir + "/garbage.png"}) {
    RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/s.test --check " + ref);
    EXPECT_EQ(r.exitCode, 4) << r.output;
    EXPECT_FALSE(contains(r.output, "wrote")) << r.output;
    EXPECT_EQ(readFile(dir + "/o.png"), kPrecious) << ref;
  }
}

// -o onto a symbolic link writes the file it leads to (through a chain, or a dangling
// link: the file is created); the link stays a link.
TEST(FileSafety, ASymbolicLinkIsWrittenThrough) {
  std::string dir = freshDir("file-safety/symlink");
  writeFile(dir + "/s.test", kScene);
  fs::create_directories(dir + "/images");
  writeFile(dir + "/images/real.png", kPrecious);
  fs::create_symlink("images/real.png", dir + "/first.png");
  fs::create_symlink("first.png", dir + "/second.png");
  fs::create_symlink("images/new.png", dir + "/dangling.png");
  for (const char* link : {"second.png", "dangling.png"}) {
    RunResult r = runVkrt("-q --backend cpu -o " + dir + "/" + link + " " + dir + "/s.test");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::is_symlink(dir + "/" + link)) << link;
  }
  EXPECT_TRUE(fs::is_symlink(dir + "/first.png"));
  EXPECT_EQ(readImage(dir + "/images/real.png").width, 20);
  EXPECT_EQ(readImage(dir + "/images/new.png").width, 20);
  EXPECT_TRUE(leftovers(dir).empty());
}

// Every writer keeps an existing file's permission bits, whatever they are: a streamed render
// (PNG), a whole one (PPM) and convert (PFM), each over files of modes 0600 and 0751; a new
// file gets 0666 less the umask.
TEST(FileSafety, EveryWriterKeepsTheModesOfTheFilesItReplaces) {
  const std::string dir = freshDir("file-safety/modes");
  writeFile(dir + "/s.test", kScene);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/source.png " + dir + "/s.test").exitCode, 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat fresh {};
  ASSERT_EQ(::stat((dir + "/source.png").c_str(), &fresh), 0);
  EXPECT_EQ(fresh.st_mode & 07777, 0666u & ~mask);
  for (unsigned mode : {0600u, 0751u}) {
    const std::string m = std::to_string(mode);
    const std::pair<std::string, std::string> writes[] = {
        {dir + "/r" + m + ".png", "-q --backend cpu -o " + dir + "/r" + m + ".png " + dir + "/s.test"},
        {dir + "/r" + m + ".ppm", "-q --backend cpu -o " + dir + "/r" + m + ".ppm " + dir + "/s.test"},
        {dir + "/c" + m + ".pfm", "convert " + dir + "/source.png " + dir + "/c" + m + ".pfm"}};
    for (const auto& [file, args] : writes) {
      writeFile(file, kPrecious);
      ASSERT_EQ(::chmod(file.c_str(), mode), 0);
      RunResult r = runVkrt(args);
      ASSERT_EQ(r.exitCode, 0) << args << ": " << r.output;
      struct stat st {};
      ASSERT_EQ(::stat(file.c_str(), &st), 0);
      EXPECT_EQ(st.st_mode & 07777, mode) << file;
      EXPECT_NE(readFile(file), kPrecious) << file << " was written";
    }
  }
}

// An existing output keeps its permission bits, and (vkrt run as root) its owner and group.
TEST(FileSafety, AnExistingOutputKeepsItsModeAndOwner) {
  std::string dir = freshDir("file-safety/mode");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/o.png", kPrecious);
  ASSERT_EQ(::chmod((dir + "/o.png").c_str(), 0640), 0);
  const bool root = ::geteuid() == 0;
  if (root) {
    ASSERT_EQ(::chown((dir + "/o.png").c_str(), 1234, 5678), 0);
  }
  RunResult r = runVkrt("-q --backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  struct stat st {};
  ASSERT_EQ(::stat((dir + "/o.png").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640u);
  EXPECT_EQ(readImage(dir + "/o.png").width, 20);
  if (!root) GTEST_SKIP() << "the owner half needs root (chown to another user): not run as root";
  EXPECT_EQ(st.st_uid, 1234u);
  EXPECT_EQ(st.st_gid, 5678u);
}

// A file with two names (hard links) is not replaced: both names keep the same content.
TEST(FileSafety, AHardLinkedOutputIsRefused) {
  std::string dir = freshDir("file-safety/hard-link");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/o.png", kPrecious);
  fs::create_hard_link(dir + "/o.png", dir + "/other-name.png");
  RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_TRUE(contains(r.output, "2 names (hard links)")) << r.output;
  EXPECT_EQ(readFile(dir + "/o.png"), kPrecious);
  EXPECT_EQ(fs::hard_link_count(dir + "/o.png"), 2u);
}

// A device node, a FIFO, a socket as the output: refused (exit 4), never opened (a FIFO
// would block) nor replaced. The device nodes are made with mknod, which needs root.
TEST(FileSafety, DevicesFifosAndSocketsAreNeverOutputs) {
  std::string dir = freshDir("file-safety/devices");
  writeFile(dir + "/s.test", kScene);
  ASSERT_EQ(::mkfifo((dir + "/fifo").c_str(), 0644), 0);
  std::vector<std::string> nodes = {"fifo"};
  const bool root = ::geteuid() == 0;
  if (root) {
    ASSERT_EQ(::mknod((dir + "/null").c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);   // as /dev/null
    ASSERT_EQ(::mknod((dir + "/block").c_str(), S_IFBLK | 0600, makedev(7, 200)), 0);
    nodes.push_back("null");
    nodes.push_back("block");
  }
  fs::create_symlink("null", dir + "/to-null.png");
  if (root) nodes.push_back("to-null.png");
  for (const std::string& node : nodes) {
    struct stat before {};
    ASSERT_EQ(::lstat((dir + "/" + node).c_str(), &before), 0);
    RunResult r = runVkrt("--backend cpu -o " + dir + "/" + node + " " + dir + "/s.test");
    EXPECT_EQ(r.exitCode, 4) << node << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "vkrt writes images only into regular files")) << r.output;
    struct stat after {};
    ASSERT_EQ(::lstat((dir + "/" + node).c_str(), &after), 0);
    EXPECT_EQ(after.st_mode, before.st_mode) << node;
    EXPECT_EQ(after.st_rdev, before.st_rdev) << node;
    EXPECT_EQ(after.st_ino, before.st_ino) << node;
  }
  EXPECT_TRUE(leftovers(dir).empty());
  if (!root) GTEST_SKIP() << "the device-node half needs root (mknod): only the FIFO was tried";
}

// A write that fails after the temporary file exists (here the rename: the target became a
// directory meanwhile) throws IoError and leaves nothing behind; so does a failing writer.
TEST(FileSafety, AFailedWriteLeavesNoTemporaryFile) {
  std::string dir = freshDir("file-safety/failed-write");
  const std::string target = dir + "/o.png";
  writeFile(target, kPrecious);
  bool sawTemporary = false;
  auto replaceByDirectory = [&](ByteSink& file) {
    sawTemporary = leftovers(dir).size() == 1;
    const std::uint8_t bytes[] = {1, 2, 3};
    file.write(bytes, sizeof bytes);
    fs::remove(target);
    fs::create_directory(target);
    writeFile(target + "/inside", "x");   // a non-empty directory: rename onto it fails
  };
  EXPECT_THROW(writeFileAtomic(target, ".png.tmp", replaceByDirectory), IoError);
  EXPECT_TRUE(sawTemporary);
  EXPECT_TRUE(leftovers(dir).empty());
  EXPECT_TRUE(fileExists(target + "/inside"));
  fs::remove_all(target);
  writeFile(target, kPrecious);
  EXPECT_THROW(writeFileAtomic(target, ".png.tmp", [](ByteSink&) { throw IoError("disk full (test)"); }), IoError);
  EXPECT_TRUE(leftovers(dir).empty());
  EXPECT_EQ(readFile(target), kPrecious);
}

// A write past the file-size limit (`ulimit -f`, as a batch job may set): the kernel's
// SIGXFSZ would end vkrt with its temporary file left; vkrt ignores it, so the write fails
// with "File too large", the old file stays, and nothing is left behind.
TEST(FileSafety, AWriteBeyondTheFileSizeLimitLeavesNoTemporaryFile) {
  std::string dir = freshDir("file-safety/file-size-limit");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/o.pfm", kPrecious);
  // 8 blocks of 512 bytes: a 100x100 PFM is 120 KB.
  RunResult r = runShell(dir, "ulimit -f 8 && exec " + kVkrt + " --backend cpu --size 100x100 -o o.pfm s.test");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_TRUE(contains(r.output, "File too large")) << r.output;
  EXPECT_EQ(readFile(dir + "/o.pfm"), kPrecious);
  const std::vector<std::string> left = leftovers(dir);
  EXPECT_TRUE(left.empty()) << left.front();
}

// SIGHUP while the image is written (vkrt waits for the signal with its temporary file
// open), and SIGINT / SIGTERM while merge or diff --diff write: exit 128 + N, the old file
// as it was, no temporary file.
TEST(FileSafety, ASignalDuringAnyWriteLeavesNoTemporaryFile) {
  std::string dir = freshDir("file-safety/signals");
  writeFile(dir + "/s.test", kScene);
  ASSERT_EQ(runVkrt("-q --backend cpu --crop 0,0,10,15 -o " + dir + "/t1.pfm " + dir + "/s.test").exitCode, 0);
  ASSERT_EQ(runVkrt("-q --backend cpu --crop 10,0,20,15 -o " + dir + "/t2.pfm " + dir + "/s.test").exitCode, 0);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/a.png " + dir + "/s.test").exitCode, 0);
  writeBlackPng(dir + "/b.png");
  struct Case {
    std::vector<std::string> args;
    int signal;
    std::string output;
  };
  const std::vector<Case> cases = {
      {{"--backend", "cpu", "-q", "-o", dir + "/o.png", dir + "/s.test"}, SIGHUP, "o.png"},
      {{"merge", "-q", "-o", dir + "/m.pfm", dir + "/t1.pfm", dir + "/t2.pfm"}, SIGINT, "m.pfm"},
      {{"merge", "-q", "-o", dir + "/m.pfm", dir + "/t1.pfm", dir + "/t2.pfm"}, SIGTERM, "m.pfm"},
      {{"diff", dir + "/a.png", dir + "/b.png", "--diff", dir + "/h.png"}, SIGINT, "h.png"},
      {{"diff", dir + "/a.png", dir + "/b.png", "--diff", dir + "/h.png"}, SIGHUP, "h.png"}};
  int run = 0;
  for (const Case& c : cases) {
    writeFile(dir + "/" + c.output, kPrecious);
    Spawned p = spawnVkrt(c.args, dir + "/log" + std::to_string(++run), {"VKRT_TEST_WAIT_FOR_SIGNAL=write"});
    ASSERT_TRUE(waitingForSignal(p.logPath, "write")) << c.args[0];
    EXPECT_EQ(leftovers(dir).size(), 1u) << "no temporary file while writing " << c.output;
    ::kill(p.pid, c.signal);
    Finished r = waitVkrt(p);
    EXPECT_EQ(r.exitCode, 128 + c.signal) << c.args[0] << " " << c.signal << ": " << r.output;
    EXPECT_TRUE(contains(r.output, "interrupted; nothing written")) << r.output;
    EXPECT_EQ(readFile(dir + "/" + c.output), kPrecious) << c.output;
    EXPECT_TRUE(leftovers(dir).empty()) << c.args[0] << " " << c.signal;
  }
}

// A signal when the grading report is whole but not yet in place: exit 130, the earlier
// report as it was, the new one's folder removed.
TEST(FileSafety, ASignalWhileGradingLeavesTheEarlierReport) {
  std::string dir = freshDir("file-safety/grade");
  fs::create_directories(dir + "/refs");
  fs::create_directories(dir + "/class/ann");
  writeBlackPng(dir + "/refs/s.png");
  writeBlackPng(dir + "/class/ann/s.png");
  const std::vector<std::string> grade{"grade", "-q", dir + "/refs", dir + "/class", "-o", dir + "/report"};
  ASSERT_EQ(runVkrt("grade -q " + dir + "/refs " + dir + "/class -o " + dir + "/report").exitCode, 0);
  const std::string before = readFile(dir + "/report/summary.json");
  writeBlackPng(dir + "/class/ann/t.png");   // a note in the new report: it would differ
  Spawned p = spawnVkrt(grade, dir + "/log", {"VKRT_TEST_WAIT_FOR_SIGNAL=grade"});
  ASSERT_TRUE(waitingForSignal(p.logPath, "grade"));
  EXPECT_EQ(leftovers(dir).size(), 1u) << "the new report's folder, while it is written";
  ::kill(p.pid, SIGINT);
  Finished r = waitVkrt(p);
  EXPECT_EQ(r.exitCode, 130) << r.output;
  EXPECT_EQ(readFile(dir + "/report/summary.json"), before);
  EXPECT_TRUE(leftovers(dir).empty());
}

// Under nohup (SIGHUP ignored when vkrt starts) a hangup does not stop it.
TEST(FileSafety, AnIgnoredHangupStaysIgnored) {
  std::string dir = freshDir("file-safety/nohup");
  writeFile(dir + "/s.test", kScene);
  struct sigaction ignore {}, old {};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGHUP, &ignore, &old);
  Spawned p = spawnVkrt({"--backend", "cpu", "-q", "-o", dir + "/o.png", dir + "/s.test"}, dir + "/log",
                        {"VKRT_TEST_WAIT_FOR_SIGNAL=write"});
  ::sigaction(SIGHUP, &old, nullptr);
  ASSERT_TRUE(waitingForSignal(p.logPath, "write"));
  ::kill(p.pid, SIGHUP);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  int status = 0;
  EXPECT_EQ(::waitpid(p.pid, &status, WNOHANG), 0) << "the ignored SIGHUP stopped vkrt";
  ::kill(p.pid, SIGINT);
  Finished r = waitVkrt(p);
  EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.output;
  EXPECT_TRUE(leftovers(dir).empty());
}

// A device of zeros, an endless line, an endless stream of text stopping at the first bad
// byte: each stops the read at once with a located error (exit 2), far below the 2 GB that
// the shell lets vkrt have here, without waiting for the end of the stream.
TEST(SceneReading, ReadingStopsAtTheFirstByteOrLineItCannotUse) {
  std::string dir = freshDir("scene-reading/bounded");
  const std::string limited = memoryCap(2000000) + "exec timeout 60 " + kVkrt + " --backend cpu -o o.png ";
  RunResult zero = runShell(dir, limited + "/dev/zero");
  EXPECT_EQ(zero.exitCode, 2) << zero.output;
  EXPECT_TRUE(contains(zero.output, "/dev/zero:1: error: file is not text (byte 0x00 in column 1)")) << zero.output;
  RunResult line = runShell(dir, "yes abcdefgh | tr -d '\\n' | (" + limited + "/dev/stdin)");
  EXPECT_EQ(line.exitCode, 2) << line.output.substr(0, 500);
  EXPECT_TRUE(contains(line.output, "/dev/stdin:1: error: the line is longer than 1048576 bytes (1 MiB)"))
      << line.output.substr(0, 500);
  auto t0 = std::chrono::steady_clock::now();
  // The writer goes on (a line every 0.1 s) until the pipe breaks: vkrt must not wait for its end.
  RunResult control = runShell(dir, "(printf 'size 10 10\\n\\001\\n'; while sleep 0.1; do echo '# more'; done) "
                                    "2>/dev/null | (" + memoryCap(2000000) + "exec timeout 20 " + kVkrt +
                                    " --backend cpu -o o.png /dev/stdin)");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(control.exitCode, 2) << control.output;
  EXPECT_TRUE(contains(control.output, "/dev/stdin:2: error: file is not text (byte 0x01 in column 1)"))
      << control.output;
  EXPECT_LT(seconds, 20.0) << "vkrt waited for the end of the stream";
  EXPECT_FALSE(fileExists(dir + "/o.png"));
}

// A line over 1 MiB in a file, at its line; a regular file over 1 GiB, before reading it
// (a sparse file: no disk used); a stream over 1 GiB, once it is read that far.
TEST(SceneReading, TheLineAndFileSizesAreBounded) {
  std::string dir = freshDir("scene-reading/limits");
  writeFile(dir + "/long.test", "size 10 10\n# a comment\ncamera" + std::string(2 << 20, ' ') + "\n");
  RunResult line = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/long.test");
  EXPECT_EQ(line.exitCode, 2) << line.output.substr(0, 500);
  EXPECT_TRUE(contains(line.output, "long.test:3: error: the line is longer than 1048576 bytes (1 MiB)"))
      << line.output.substr(0, 500);
  // Exactly 1 MiB of line is fine (a warning for the padding, which is no argument).
  writeFile(dir + "/edge.test", kScene + "#" + std::string((1 << 20) - 1, 'x') + "\n");
  RunResult edge = runVkrt("-q --backend cpu -o " + dir + "/edge.png " + dir + "/edge.test");
  EXPECT_EQ(edge.exitCode, 0) << edge.output.substr(0, 500);
  {
    int fd = ::open((dir + "/huge.test").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::ftruncate(fd, (off_t{1} << 30) + 1), 0);
    ::close(fd);
  }
  auto t0 = std::chrono::steady_clock::now();
  RunResult huge = runShell(dir, memoryCap(2000000) + "exec " + kVkrt + " --backend cpu -o o.png huge.test");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fs::remove(dir + "/huge.test");
  EXPECT_EQ(huge.exitCode, 2) << huge.output;
  EXPECT_TRUE(contains(huge.output, "huge.test: error: the file is 1073741825 bytes, more than the 1073741824 (1 GiB)"))
      << huge.output;
  EXPECT_LT(seconds, 5.0) << "the size was not checked before reading";
  EXPECT_FALSE(fileExists(dir + "/o.png"));
}

// An endless stream of short lines stops once 1 GiB is read (a few seconds, 1 GiB of
// memory: labelled slow), at the line where it went past.
TEST(SceneReading, AnEndlessStreamStopsAtOneGibibyte) {
  std::string dir = freshDir("scene-reading/stream");
  RunResult stream = runShell(dir, "yes '# a line of comment' | (" + memoryCap(3000000) + "exec timeout 120 " + kVkrt +
                                       " --backend cpu -o o.png /dev/stdin)");
  EXPECT_EQ(stream.exitCode, 2) << stream.output;
  // 1073741824 bytes of 20-byte lines: the byte past the limit is on line 53687092.
  EXPECT_TRUE(contains(stream.output, "/dev/stdin:53687092: error: the file goes on past 1073741824 bytes (1 GiB)"))
      << stream.output;
  EXPECT_FALSE(fileExists(dir + "/o.png"));
}

// Ctrl-C while vkrt waits on a FIFO (for its writer, or for the next bytes): exit 130 (not
// an I/O error), and a batch stops there.
TEST(SceneReading, CtrlCStopsAReadThatWaits) {
  std::string dir = freshDir("scene-reading/fifo");
  ASSERT_EQ(::mkfifo((dir + "/fifo.test").c_str(), 0644), 0);
  writeFile(dir + "/b.test", kScene + "output " + dir + "/b.png\n");
  // No writer: vkrt waits in open().
  Spawned waiting = spawnVkrt({"--backend", "cpu", dir + "/fifo.test"}, dir + "/log-open");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ::kill(waiting.pid, SIGINT);
  Finished opened = waitVkrtWithin(waiting, 30);
  EXPECT_EQ(opened.exitCode, 130) << opened.output;
  EXPECT_TRUE(contains(opened.output, "interrupted")) << opened.output;
  // A writer that sends a line and then nothing: vkrt waits in read(); a batch.
  Spawned reading = spawnVkrt({"--backend", "cpu", "-o", dir + "/", dir + "/fifo.test", dir + "/b.test"}, dir + "/log-read");
  int fd = -1;
  for (int i = 0; i < 20000 && fd < 0; ++i) {   // O_NONBLOCK: ENXIO until vkrt opens it
    fd = ::open((dir + "/fifo.test").c_str(), O_WRONLY | O_NONBLOCK);
    if (fd < 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_GE(fd, 0) << "vkrt never opened the FIFO";
  ASSERT_EQ(::write(fd, "size 10 10\n", 11), 11);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ::kill(reading.pid, SIGINT);
  Finished read = waitVkrtWithin(reading, 30);
  ::close(fd);
  EXPECT_EQ(read.exitCode, 130) << read.output;
  EXPECT_TRUE(contains(read.output, "1 not rendered (stopped)")) << read.output;
  EXPECT_FALSE(fileExists(dir + "/b.png"));
  // An image read from a FIFO (diff, --check, merge) is stopped the same way.
  writeBlackPng(dir + "/b.png");
  Spawned diff = spawnVkrt({"diff", dir + "/fifo.test", dir + "/b.png"}, dir + "/log-diff");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ::kill(diff.pid, SIGTERM);
  Finished diffed = waitVkrtWithin(diff, 30);
  EXPECT_EQ(diffed.exitCode, 143) << diffed.output;
  EXPECT_TRUE(contains(diffed.output, "interrupted")) << diffed.output;
}
