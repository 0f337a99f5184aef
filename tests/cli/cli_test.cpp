// The vkrt command line: options, exit statuses, messages, and what gets written where.
#include <cstdio>
#include <new>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "cli/exit_status.h"
#include "cli/options.h"
#include "cli/run_files.h"
#include "util/errors.h"
#include "gpu/context.h"
#include "gpu/device_error.h"
#include "image/png.h"
#include "util/interrupt.h"
#include "scene/diagnostic.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::string kScene =
    "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\ndiffuse 0.5 0 0\nsphere 0 0 0 1\n";

}  // namespace

TEST(Cli, HelpAndVersion) {
  RunResult h = runVkrt("--help");
  EXPECT_EQ(h.exitCode, 0);
  EXPECT_NE(h.output.find("usage: vkrt [options] SCENE.test"), std::string::npos) << h.output;
  EXPECT_NE(h.output.find("--backend"), std::string::npos);
  for (const char* line : {"--strict", "  2    scene error", "  3    device error", "  4    I/O error",
                           "  6    out of memory", "  70   internal error", "128+N"})
    EXPECT_NE(h.output.find(line), std::string::npos) << line << "\n" << h.output;
  RunResult v = runVkrt("--version");
  EXPECT_EQ(v.exitCode, 0);
  EXPECT_EQ(v.output.rfind("vkrt ", 0), 0u) << v.output;
}

TEST(Cli, UsageErrorsExitWith1) {
  for (const char* args : {"", "--bogus x.test", "--threads 0 x.test", "--threads abc x.test", "--backend gl x.test",
                           "-o", "-o x.png a.test b.test", "-o a.png -o b.png x.test", "merge -o a.png -o b.png t.png",
                           "merge --strict -o x.bmp t.png"}) {
    RunResult r = runVkrt(args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("vkrt: error: "), std::string::npos) << r.output;
  }
}

// merge --strict makes its output-name warning an error, as a render's --strict does.
TEST(Cli, MergeStrictRefusesAnOutputNameOfNoFormat) {
  RunResult r = runVkrt("merge --strict -o x.bmp t.png");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("output file 'x.bmp' is not named .png, .ppm, .pfm or .exr: vkrt writes PNG, under that "
                          "name [--strict]"), std::string::npos) << r.output;
}

TEST(Cli, RendersToTheScenesOutputRelativeToTheCurrentDirectory) {
  std::string dir = freshDir("cli/scene-output");
  writeFile(dir + "/s.test", kScene + "output img.png\n");
  RunResult r = runVkrt("--backend cpu " + dir + "/s.test");   // run from the build folder
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: wrote img.png (40x30)"), std::string::npos) << r.output;
  Image img = readImage("img.png");
  EXPECT_EQ(img.width, 40);
  EXPECT_EQ(img.height, 30);
  EXPECT_GT(img.pixel(20, 15)[0], 100);
  std::remove("img.png");
}

TEST(Cli, OutputOptionOverridesAndStatsArePrinted) {
  std::string dir = freshDir("cli/override");
  writeFile(dir + "/s.test", kScene + "output never.png\n");
  RunResult r = runVkrt("--backend cpu --stats --threads 1 -o " + dir + "/o.png " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fileExists(dir + "/o.png"));
  EXPECT_FALSE(fileExists("never.png"));
  for (const char* key : {"parse", "build", "render", "write", "rays", "primary 1200", "1 thread"})
    EXPECT_NE(r.output.find(key), std::string::npos) << key << "\n" << r.output;
  RunResult eq = runVkrt("-q --output=" + dir + "/eq.png " + dir + "/s.test");
  EXPECT_EQ(eq.exitCode, 0) << eq.output;
  EXPECT_EQ(eq.output, "");   // --quiet
  EXPECT_TRUE(fileExists(dir + "/eq.png"));
}

TEST(Cli, UnwritableOutputOptionIsAnIoErrorBeforeRendering) {
  std::string dir = freshDir("cli/io");
  writeFile(dir + "/s.test", kScene);
  RunResult r = runVkrt("-o " + dir + "/missing/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote"), std::string::npos);
  // A folder as the output: its error alone, no warning about the name first.
  for (const std::string& args : {"-o " + dir + " " + dir + "/s.test", "merge -o " + dir + " " + dir + "/t.png",
                                  "merge -o " + dir + "/ " + dir + "/t.png"}) {
    RunResult folder = runVkrt(args);
    EXPECT_EQ(folder.exitCode, 4) << args << "\n" << folder.output;
    EXPECT_NE(folder.output.find("directory"), std::string::npos) << folder.output;
    EXPECT_EQ(folder.output.find("warning"), std::string::npos) << folder.output;
  }
}

TEST(Cli, NonTerminalGetsAPlainFinalLineAndNoProgressBar) {
  std::string dir = freshDir("cli/plain");
  writeFile(dir + "/s.test", kScene);
  RunResult r = runVkrt("-o " + dir + "/o.png " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "progress bar drawn into a pipe";
  EXPECT_EQ(r.output.rfind("vkrt: wrote ", 0), 0u) << r.output;
}

// The scene's warnings go to stderr as FILE:LINE: warning: MESSAGE and the render goes on;
// -q leaves them out.
TEST(Cli, WarningsArePrintedAndTheRenderGoesOn) {
  std::string dir = freshDir("cli/warnings");
  writeFile(dir + "/s.test", kScene + "antialias 4\n");
  RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.rfind(dir + "/s.test:6: warning: unknown command 'antialias' (line skipped)\n", 0), 0u)
      << r.output;
  EXPECT_NE(r.output.find("vkrt: wrote"), std::string::npos) << r.output;
  EXPECT_TRUE(fileExists(dir + "/o.png"));
  RunResult q = runVkrt("-q --backend cpu -o " + dir + "/q.png " + dir + "/s.test");
  EXPECT_EQ(q.exitCode, 0) << q.output;
  EXPECT_EQ(q.output, "");
  EXPECT_TRUE(fileExists(dir + "/q.png"));
}

// Pixels whose colour came out NaN or infinite: a warning, or with --strict an error (exit
// 2) before anything is written.
TEST(Cli, StrictRefusesNonFinitePixels) {
  std::string dir = freshDir("cli/strict-nan");
  // Each value within float32, their sum beyond it.
  writeFile(dir + "/s.test", "size 20 10\ncamera 0 0 5 0 0 0 0 1 0 45\nambient 3e38 3e38 3e38\n"
                             "emission 3e38 0 0\nsphere 0 0 0 1\n");
  RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: warning: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pixels had a NaN or infinite colour"), std::string::npos) << r.output;
  RunResult strict = runVkrt("--strict --backend cpu -o " + dir + "/strict.png " + dir + "/s.test");
  EXPECT_EQ(strict.exitCode, 2) << strict.output;
  EXPECT_NE(strict.output.find(dir + "/s.test: error: "), std::string::npos) << strict.output;
  EXPECT_NE(strict.output.find("pixels had a NaN or infinite colour"), std::string::npos) << strict.output;
  EXPECT_FALSE(fileExists(dir + "/strict.png"));
}

// Exit statuses that a run can provoke (0, 1 and 5 have tests of their own; 2: the parse
// error and warning tests; 128+N: limits_test.cpp).
TEST(ExitStatus, NoSuchVulkanDeviceIs3) {
  std::string dir = freshDir("exit-status/device");
  writeFile(dir + "/s.test", kScene);
  // Without a Vulkan loader or driver the status is the same.
  RunResult r = runVkrt("--backend vulkan --device no-such-gpu-xyz -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_EQ(r.output.rfind("vkrt: error: ", 0), 0u) << r.output;
  EXPECT_FALSE(fileExists(dir + "/o.png"));
}

// The context is made while the scene is parsed; the scene's own errors still come first,
// and in a batch each scene meets the device error in turn.
TEST(ExitStatus, SceneErrorsComeBeforeTheDevicesOne) {
  std::string dir = freshDir("exit-status/device-order");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/bad.test", std::string(kScene) + "tri 0 1 2\n");
  RunResult bad = runVkrt("--backend vulkan --device no-such-gpu-xyz -o " + dir + "/o.png " + dir + "/bad.test");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find(dir + "/bad.test:"), std::string::npos) << bad.output;
  EXPECT_EQ(bad.output.find("no-such-gpu-xyz"), std::string::npos) << bad.output;
  RunResult batch = runVkrt("--backend vulkan --device no-such-gpu-xyz -o " + dir + "/ " + dir + "/bad.test " + dir +
                            "/s.test " + dir + "/s.test");
  EXPECT_EQ(batch.exitCode, 3) << batch.output;
  EXPECT_NE(batch.output.find("[1/3] exit 2"), std::string::npos) << batch.output;
  EXPECT_NE(batch.output.find("[2/3] exit 3"), std::string::npos) << batch.output;
  EXPECT_NE(batch.output.find("[3/3] exit 3"), std::string::npos) << batch.output;
  EXPECT_FALSE(fileExists(dir + "/s.png"));
}

TEST(ExitStatus, UnreadableFilesAre4) {
  std::string dir = freshDir("exit-status/io");
  writeFile(dir + "/s.test", kScene);
  RunResult scene = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/missing.test");
  EXPECT_EQ(scene.exitCode, 4) << scene.output;
  RunResult check = runVkrt("-q --backend cpu -o " + dir + "/o.png " + dir + "/s.test --check " + dir + "/none.png");
  EXPECT_EQ(check.exitCode, 4) << check.output;
  EXPECT_NE(check.output.find("cannot read image"), std::string::npos) << check.output;
}

// Out of memory is exit 6 whenever it is found: before allocating (an image larger than the
// memory available, refused up front; also limits_test.cpp), and when an allocation fails
// mid-way (here the 768 MB image under a 500 MB address-space limit, past that check).
TEST(ExitStatus, OutOfMemoryIs6WheneverFound) {
  std::string dir = freshDir("exit-status/memory");
  writeFile(dir + "/big.test", "size 16384 16384\ncamera 0 0 1 0 0 0 0 1 0 45\n");
  RunResult before = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/big.test",
                             "VKRT_TEST_MEMORY_AVAILABLE_MB=100");
  EXPECT_EQ(before.exitCode, 6) << before.output;
  EXPECT_NE(before.output.find("vkrt: error: out of memory: a 16384x16384 image"), std::string::npos)
      << before.output;
#if !defined(VKRT_SANITIZE_BUILD)   // GCC defines __SANITIZE_ADDRESS__, clang 14 does not
  // (AddressSanitizer reserves more address space than the limit, and ends the process
  // itself when an allocation fails: this half runs in the plain build only.) A path
  // integrator holds its running mean whole (a Whitted render streams in bands and fits).
  writeFile(dir + "/big-path.test", "size 16384 16384\nintegrator pathtracer\ncamera 0 0 1 0 0 0 0 1 0 45\n");
  RunResult limited = runCommand("ulimit -v 500000 && exec env VKRT_TEST_MEMORY_AVAILABLE_MB=100000 '" +
                                  vkrtBinary() + "' --backend cpu --threads 1 -o '" + dir + "/o.png' '" + dir +
                                  "/big-path.test'");
  const std::string& output = limited.output;
  EXPECT_EQ(limited.exitCode, 6) << output;
  // What failed and the limit it met, not a need the numbers cannot show (the 100000 MB
  // "available" are not what the image needed).
  EXPECT_NE(output.find("vkrt: error: out of memory: an allocation for " + dir + "/big-path.test failed; this process "
                        "may use at most 488 MB of address space: ulimit -v; the machine has 100000 MB available"),
            std::string::npos)
      << output;
#endif
  EXPECT_FALSE(fileExists(dir + "/o.png"));
}

namespace {

// What reportError prints for `error`, and the status it returns.
std::pair<int, std::string> reported(std::exception_ptr error, bool quiet = false) {
  std::FILE* f = std::tmpfile();
  int status = reportError(error, ErrorContext{"s.test", quiet}, f);
  std::rewind(f);
  std::string text;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  std::fclose(f);
  return {status, text};
}

}  // namespace

// Every kind of error to its one status and its message; the statuses no run can provoke
// on purpose (a bug, the device's memory) are checked here.
TEST(ExitStatus, EachKindOfErrorHasOneStatus) {
  using std::make_exception_ptr;
  EXPECT_EQ(reported(make_exception_ptr(UsageError("bad option"))),
            std::make_pair(1, std::string("vkrt: error: bad option\nsee 'vkrt --help'\n")));   // not the usage text
  auto scene = reported(make_exception_ptr(SceneError(
      {{"s.test", 3, "unknown command 'x' (line skipped)", Severity::Warning}, {"s.test", 4, "rotate axis"}})));
  EXPECT_EQ(scene.first, 2);
  EXPECT_EQ(scene.second, "s.test:3: warning: unknown command 'x' (line skipped)\ns.test:4: error: rotate axis\n");
  EXPECT_EQ(reported(make_exception_ptr(SceneError({{"s.test", 3, "w", Severity::Warning}, {"s.test", 4, "e"}})),
                     true)
                .second,
            "s.test:4: error: e\n");
  EXPECT_EQ(reported(make_exception_ptr(DeviceError("no Vulkan device"))),
            std::make_pair(3, std::string("vkrt: error: no Vulkan device\n")));
  EXPECT_EQ(reported(make_exception_ptr(IoError("cannot write"))).first, 4);
  EXPECT_EQ(reported(make_exception_ptr(OutOfMemory("a big image"))),
            std::make_pair(6, std::string("vkrt: error: out of memory: a big image\n")));
  auto badAlloc = reported(make_exception_ptr(std::bad_alloc()));
  EXPECT_EQ(badAlloc.first, 6);
  EXPECT_EQ(badAlloc.second.rfind("vkrt: error: out of memory: an allocation for s.test failed", 0), 0u)
      << badAlloc.second;
  // A refused output is a usage error without the usage text.
  auto refused = reported(make_exception_ptr(RefusedOutput("refusing to write 'a.test'")));
  EXPECT_EQ(refused, std::make_pair(1, std::string("vkrt: error: refusing to write 'a.test'\n")));
  EXPECT_EQ(reported(make_exception_ptr(InternalError("unfinished pixels"))),
            std::make_pair(70, std::string("vkrt: internal error (a bug in vkrt): unfinished pixels\n")));
  EXPECT_EQ(reported(make_exception_ptr(std::runtime_error("?"))).first, 70);
  EXPECT_EQ(reported(make_exception_ptr(42)).first, 70);
  EXPECT_EQ(reported(make_exception_ptr(Interrupted(15))).first, 143);
}

// A Vulkan call that runs out of memory, host or device, is out of memory (6), not a device
// error (3).
TEST(ExitStatus, VulkanOutOfMemoryIsOutOfMemory) {
  EXPECT_THROW(checkVk(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory()", __FILE__, __LINE__), OutOfMemory);
  EXPECT_THROW(checkVk(VK_ERROR_OUT_OF_HOST_MEMORY, "vkCreateBuffer()", __FILE__, __LINE__), OutOfMemory);
  EXPECT_THROW(checkVk(VK_ERROR_DEVICE_LOST, "vkQueueSubmit()", __FILE__, __LINE__), DeviceError);
  EXPECT_NO_THROW(checkVk(VK_SUCCESS, "vkQueueSubmit()", __FILE__, __LINE__));
}
