// Hardening: inputs at and past the limits, huge images and their memory, and
// interruptions that must leave the user's files as they were.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

namespace {

// Files vkrt left beside its output (temporary PNGs or write probes).
std::vector<std::string> leftovers(const std::string& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".vkrt-", 0) == 0) found.push_back(e.path().string());
  return found;
}

const std::string kPrecious = "the user's old image: must survive";

}  // namespace

// A hundred-megabyte line is an error at its line: reading stops a mebibyte into it (the
// most a line may hold), with or without --strict.
TEST(Limits, AHundredMegabyteLineIsAnErrorAtItsLine) {
  std::string dir = freshDir("limits/long-line");
  {
    std::ofstream f(dir + "/long.test", std::ios::binary);
    f << "size 10 10\ncamera 0 0 1 0 0 0 0 1 0 45\nvertex";
    std::string chunk;
    for (int i = 0; i < 1024; ++i) chunk += " 1.5";
    for (int i = 0; i < 100 * 1024 * 1024 / 4096; ++i) f << chunk;
    f << "\n";
  }
  RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/long.test");
  RunResult strict = runVkrt("--strict --backend cpu -o " + dir + "/o.png " + dir + "/long.test");
  fs::remove(dir + "/long.test");
  const std::string message = "long.test:3: error: the line is longer than 1048576 bytes (1 MiB)";
  EXPECT_EQ(r.exitCode, 2) << r.output.substr(0, 500);
  EXPECT_NE(r.output.find(message), std::string::npos) << r.output.substr(0, 500);
  EXPECT_FALSE(fileExists(dir + "/o.png"));
  EXPECT_EQ(strict.exitCode, 2) << strict.output.substr(0, 500);
  EXPECT_NE(strict.output.find(message), std::string::npos) << strict.output.substr(0, 500);
}

// Ten million vertices (a 200 MB file) parse and render; peak memory stays near what the
// vertices themselves need (24 bytes each in double precision).
TEST(Limits, TenMillionVerticesParseAndRender) {
  std::string dir = freshDir("limits/ten-million");
  {
    std::ofstream f(dir + "/many.test", std::ios::binary);
    f << "size 32 24\ncamera 0 0 3 0 0 0 0 1 0 45\nambient 1 1 1\n";
    std::string block;
    for (int i = 0; i < 1000; ++i) block += "vertex " + std::to_string(i % 7 - 3) + ".5 0.25 -1\n";
    for (int i = 0; i < 10000; ++i) f << block;
    f << "tri 0 1 3\n";
  }
  MeasuredRun r = runVkrtMeasuringMemory({"--backend", "cpu", "-q", "-o", dir + "/o.png", dir + "/many.test"}, dir + "/log");
  fs::remove(dir + "/many.test");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fileExists(dir + "/o.png"));
  std::printf("[ stats    ] 10M vertices: peak RSS %lld MB\n", r.peakRssKb / 1024);
  EXPECT_LT(r.peakRssKb / 1024, 1024) << "10M vertices should need well under 1 GB";
}

// A Whitted render to a file streams its rows, so it needs its bands (about 144 MB at 16384
// wide, whatever the height); a render held whole (a path integrator's running mean) needs
// 15 bytes a pixel. Either is refused when the memory available is less, before allocating.
TEST(Limits, AnImageLargerThanTheMemoryIsRefusedBeforeAllocating) {
  std::string dir = freshDir("limits/memory");
  writeFile(dir + "/big.test", "# a big one\nsize 16384 16384\ncamera 0 0 1 0 0 0 0 1 0 45\n");
  writeFile(dir + "/path.test", "# a big one\nsize 16384 16384\nintegrator pathtracer\ncamera 0 0 1 0 0 0 0 1 0 45\n");
  const std::pair<std::string, std::string> cases[] = {
      {"big.test", "/big.test:2) needs 144 MB (streamed in bands), and this machine has 100 MB available"},
      {"path.test", "/path.test:2) needs 3840 MB, and this machine has 100 MB available"},
  };
  for (const auto& [scene, message] : cases) {
    writeFile(dir + "/o.png", kPrecious);
    MeasuredRun r = runVkrtMeasuringMemory({"--backend", "cpu", "-o", dir + "/o.png", dir + "/" + scene}, dir + "/log",
                                       {"VKRT_TEST_MEMORY_AVAILABLE_MB=100"});
    EXPECT_EQ(r.exitCode, 6) << r.output;
    EXPECT_NE(r.output.find("vkrt: error: out of memory: a 16384x16384 image (" + dir + message), std::string::npos)
        << r.output;
    EXPECT_LT(r.peakRssKb / 1024, 200) << "refused, but only after allocating the image";
    EXPECT_EQ(readFile(dir + "/o.png"), kPrecious);
    EXPECT_TRUE(leftovers(dir).empty());
  }
  // With the memory a streamed render needs, it renders, however tall.
  Finished tall = waitVkrt(spawnVkrt({"--backend", "cpu", "-q", "--size", "64x16384", "-o", dir + "/tall.png",
                                      dir + "/big.test"},
                                     dir + "/log", {"VKRT_TEST_MEMORY_AVAILABLE_MB=200"}));
  EXPECT_EQ(tall.exitCode, 0) << tall.output;
}

// The peak memory the tests below hold vkrt to is vkrt's own, however large this test
// binary is: here it holds 256 MB, resident, while vkrt renders a tiny scene.
TEST(Limits, MeasuredPeakMemoryIsVkrtsOwnNotTheTestBinarys) {
  std::string dir = freshDir("peak-memory");
  writeFile(dir + "/tiny.test", "size 8 8\ncamera 0 0 4 0 0 0 0 1 0 45\nambient 0.3 0.2 0.1\nsphere 0 0 0 1\n");
  std::vector<char> ballast(256u << 20);
  for (std::size_t i = 0; i < ballast.size(); i += 4096) ballast[i] = static_cast<char>(i >> 12);
  long long residentKib = 0;   // the premise: this binary holds the ballast, resident
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) residentKib = std::stoll(line.substr(6));
  ASSERT_GE(residentKib / 1024, 256) << "the ballast is not resident";
  MeasuredRun r = runVkrtMeasuringMemory({"--backend", "cpu", "-q", "-o", dir + "/o.png", dir + "/tiny.test"},
                                      dir + "/log");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::printf("[ stats    ] tiny render beside 256 MB in the test binary: peak RSS %lld MB\n", r.peakRssKb / 1024);
  EXPECT_GT(r.peakRssKb, 0);
  EXPECT_LT(r.peakRssKb / 1024, 128) << "the test binary's memory was counted as vkrt's";
  EXPECT_NE(ballast[4096], ballast[8192]);   // the ballast stays resident until here
}

// The largest size, on both backends: the picture is right (an ambient sphere in the middle,
// black corners), and the peak memory is far below the float image (3072 MB of linear RGB):
// the renderers hand bands of rows to the PNG encoder as they finish them, so the peak is
// the bands' (CPU: about 22 MB; lavapipe: about 110 MB with the driver, an H200 117), not the
// image's.
TEST(LargeImage, Size16384RendersOnBothBackendsInBandsWellUnderAGigabyte) {
  std::string dir = freshDir("large-image");
  writeFile(dir + "/big.test", "size 16384 16384\ncamera 0 0 4 0 0 0 0 1 0 45\nambient 0.3 0.2 0.1\nsphere 0 0 0 1\n");
  const long long imageMb = 16384LL * 16384 * 3 * sizeof(float) / (1024 * 1024);
  std::vector<std::string> backends = {"cpu"};
  if (gpuContextOrSkip()) backends.push_back("vulkan");
  for (const std::string& backend : backends) {
    std::string out = dir + "/" + backend + ".png";
    MeasuredRun r = runVkrtMeasuringMemory({"--backend", backend, "-q", "-o", out, dir + "/big.test"}, dir + "/log");
    ASSERT_EQ(r.exitCode, 0) << backend << ": " << r.output;
    std::printf("[ stats    ] 16384x16384, %s: peak RSS %lld MB (float image %lld MB)\n", backend.c_str(),
                r.peakRssKb / 1024, imageMb);
    EXPECT_LE(r.peakRssKb / 1024, backend == "cpu" ? 48 : 256) << backend;
    Image img = readImage(out);
    ASSERT_EQ(img.width, 16384);
    const std::uint8_t* centre = img.pixel(8192, 8192);
    EXPECT_EQ(centre[0], 76);   // floor(0.3 * 255)
    EXPECT_EQ(centre[1], 51);
    EXPECT_EQ(centre[2], 25);
    EXPECT_EQ(img.pixel(0, 0)[0], 0);
    fs::remove(out);
  }
}

// Waits (up to a minute) until vkrt's log shows the line of its test hook
// (VKRT_TEST_WAIT_FOR_SIGNAL: interrupt.h), which it prints once it is in `stage` and waiting
// for a signal. The signal sent after that cannot come too early or too late.
::testing::AssertionResult waitingForSignal(const std::string& logPath, const std::string& stage) {
  const std::string line = "vkrt: test hook: waiting for a signal during the " + stage;
  for (int i = 0; i < 60000; ++i) {
    if (readFile(logPath).find(line) != std::string::npos) return ::testing::AssertionSuccess();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return ::testing::AssertionFailure() << "vkrt never got to the " << stage << ": " << readFile(logPath);
}

// A render stopped by SIGTERM or Ctrl-C (SIGINT) exits with 128 + the signal, says so, and
// leaves the existing output as it was and no temporary file. The signal is sent while vkrt
// waits for it in its first progress report, with most of the image still to render.
TEST(Interrupt, DuringTheRenderLeavesTheOldImageAndNoTemporaryFile) {
  std::string dir = freshDir("interrupt/render");
  std::string scene = "size 3000 3000\ncamera 0 0 4 0 0 0 0 1 0 45\ndiffuse 0.5 0.5 0.5\nsphere 0 0 0 1\n";
  for (int i = 0; i < 60; ++i) scene += "point " + std::to_string(i % 5) + " 2 3 0.02 0.02 0.02\n";
  writeFile(dir + "/slow.test", scene);
  std::vector<std::pair<std::string, int>> runs = {{"cpu", SIGTERM}};
  if (gpuContextOrSkip()) runs.emplace_back("vulkan", SIGINT);
  for (auto [backend, sig] : runs) {
    writeFile(dir + "/o.png", kPrecious);
    // A log per run: the first run's would show the second's wait before it began.
    Spawned p = spawnVkrt({"--backend", backend, "-o", dir + "/o.png", dir + "/slow.test"}, dir + "/log-" + backend,
                          {"VKRT_TEST_WAIT_FOR_SIGNAL=render"});
    EXPECT_TRUE(waitingForSignal(p.logPath, "render")) << backend;
    ::kill(p.pid, sig);
    auto t0 = std::chrono::steady_clock::now();
    Finished r = waitVkrt(p);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.exitCode, 128 + sig) << backend << ": " << r.output;
    EXPECT_NE(r.output.find("interrupted; nothing written"), std::string::npos) << r.output;
    EXPECT_TRUE(readFile(dir + "/o.png") == kPrecious) << backend << ": the old image was replaced";
    EXPECT_TRUE(leftovers(dir).empty()) << backend;
    std::printf("[ stats    ] %s stopped %.2f s after the signal\n", backend.c_str(), seconds);
  }
}

// Ctrl-C within a pixel: the CPU path integrators poll for it among a vertex's light samples,
// so a scene of a billion light samples a pixel (hours) stops at once, not after its tile.
// The signal comes a second after the start; 30 s later `timeout` would kill vkrt (status
// 137) instead of it exiting with 130. (--foreground: one SIGINT to vkrt alone; without it
// timeout sends a second one to its process group, and a second signal ends vkrt at once.)
TEST(Interrupt, CtrlCStopsACpuPathRenderWithinAPixel) {
  std::string dir = freshDir("interrupt/light-samples");
  writeFile(dir + "/many.test",
            "size 2 2\nintegrator direct\ncamera 0 1 3 0 0 0 0 1 0 45\nlightsamples 1000000000\n"
            "quadLight -0.5 2 -0.5 0 0 1 1 0 0 5 5 5\nvertex -9 0 -9\nvertex 9 0 -9\nvertex 9 0 9\n"
            "vertex -9 0 9\ndiffuse 0.5 0.5 0.5\ntri 0 2 1\ntri 0 3 2\n");
  auto t0 = std::chrono::steady_clock::now();
  RunResult r = runCommand("cd '" + dir + "' && timeout --foreground --preserve-status -s INT -k 30 1 '" + vkrtBinary() +
                           "' --backend cpu --threads 1 -o o.png many.test");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.output;
  EXPECT_NE(r.output.find("interrupted; nothing written"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/o.png"));
  EXPECT_TRUE(leftovers(dir).empty());
  std::printf("[ stats    ] stopped %.2f s after the start (the signal at 1 s)\n", seconds);
}

// Interrupted while the PNG is being written (the temporary file exists; vkrt waits for the
// signal right after creating it): the temporary file goes, the old image stays.
TEST(Interrupt, DuringTheWriteLeavesTheOldImageAndNoTemporaryFile) {
  std::string dir = freshDir("interrupt/write");
  writeFile(dir + "/small.test", "size 64 48\ncamera 0 0 4 0 0 0 0 1 0 45\nsphere 0 0 0 1\n");
  writeFile(dir + "/o.png", kPrecious);
  Spawned p = spawnVkrt({"--backend", "cpu", "-q", "-o", dir + "/o.png", dir + "/small.test"}, dir + "/log",
                        {"VKRT_TEST_WAIT_FOR_SIGNAL=write"});
  EXPECT_TRUE(waitingForSignal(p.logPath, "write"));
  bool sawTemporary = false;
  for (const std::string& f : leftovers(dir)) sawTemporary |= f.find(".png.tmp") != std::string::npos;
  EXPECT_TRUE(sawTemporary) << "no temporary file while writing";
  ::kill(p.pid, SIGINT);
  Finished r = waitVkrt(p);
  EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.output;
  EXPECT_NE(r.output.find("interrupted; nothing written"), std::string::npos) << r.output;
  EXPECT_TRUE(readFile(dir + "/o.png") == kPrecious) << "the old image was replaced";
  EXPECT_TRUE(leftovers(dir).empty());
}
