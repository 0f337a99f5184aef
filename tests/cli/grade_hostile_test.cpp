// `vkrt grade` against submissions made to fool it or to bring it down: links of every kind,
// special files, ten thousand files, a file of 2 GB, image bombs in every format vkrt reads,
// names with control characters, scene files that are special, huge, deep, or write
// elsewhere. Each fails its own scene with a reason, the rest is graded, the run stays within
// bounded time and memory, and nothing outside the report is written.
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <zlib.h>

#define STB_IMAGE_WRITE_STATIC   // (this test's own JPEG writer: vkrt reads JPEG, never writes it)
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "image/image_file.h"
#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Image solid(int w, int h, std::uint8_t v) {
  Image im(w, h);
  std::fill(im.rgb.begin(), im.rgb.end(), v);
  return im;
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string chunk(const std::string& type, const std::string& data) {
  std::string c(4, '\0');
  const std::uint32_t n = static_cast<std::uint32_t>(data.size());
  for (int i = 0; i < 4; ++i) c[i] = static_cast<char>(n >> (24 - 8 * i));
  c += type + data;
  const std::uint32_t crc = static_cast<std::uint32_t>(
      ::crc32(::crc32(0, reinterpret_cast<const Bytef*>(type.data()), 4), reinterpret_cast<const Bytef*>(data.data()),
              static_cast<uInt>(data.size())));
  for (int i = 0; i < 4; ++i) c += static_cast<char>(crc >> (24 - 8 * i));
  return c;
}

// A PNG of `width` x `height` RGB pixels whose compressed data inflates to `inflated` zero
// bytes: its pixels' share (a real bomb: 8000x8000 black pixels, 192 MB, in about 200 KB), or
// far more than they take (a small header with 256 MB of zeros behind it).
std::string pngOf(int width, int height, std::uint64_t inflated) {
  std::string ihdr(13, '\0');
  for (int i = 0; i < 4; ++i) {
    ihdr[i] = static_cast<char>(static_cast<std::uint32_t>(width) >> (24 - 8 * i));
    ihdr[4 + i] = static_cast<char>(static_cast<std::uint32_t>(height) >> (24 - 8 * i));
  }
  ihdr[8] = 8, ihdr[9] = 2;   // 8 bits, RGB
  z_stream z{};
  deflateInit(&z, 1);
  const std::string zeros(1 << 16, '\0');
  std::string idat, out(1 << 16, '\0');
  for (std::uint64_t left = inflated;;) {
    const std::size_t take = static_cast<std::size_t>(std::min<std::uint64_t>(left, zeros.size()));
    left -= take;
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(zeros.data()));
    z.avail_in = static_cast<uInt>(take);
    const int flush = left > 0 ? Z_NO_FLUSH : Z_FINISH;
    do {
      z.next_out = reinterpret_cast<Bytef*>(out.data());
      z.avail_out = static_cast<uInt>(out.size());
      deflate(&z, flush);
      idat.append(out.data(), out.size() - z.avail_out);
    } while (z.avail_out == 0);
    if (left == 0) break;
  }
  deflateEnd(&z);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", idat) + chunk("IEND", "");
}

// A JPEG whose frame header (SOF0) says `side` x `side`, its few bytes of data a 16x16 image's.
std::string jpegBomb(const std::string& dir, int side) {
  const Image small = solid(16, 16, 128);
  const std::string path = dir + "/small.jpg";
  EXPECT_NE(stbi_write_jpg(path.c_str(), 16, 16, 3, small.rgb.data(), 90), 0);
  std::string bytes = readFile(path);
  fs::remove(path);
  const std::size_t sof = bytes.find("\xFF\xC0");
  EXPECT_NE(sof, std::string::npos);
  for (std::size_t at : {sof + 5, sof + 7}) {
    bytes[at] = static_cast<char>(side >> 8);
    bytes[at + 1] = static_cast<char>(side & 255);
  }
  return bytes;
}

// An EXR of 4x4 written by vkrt, its data window made `side` x `side`.
std::string exrBomb(const std::string& dir, int side) {
  const std::string path = dir + "/small.exr";
  writeImageAtomic(RadianceImage(4, 4), path, 1.0);
  std::string bytes = readFile(path);
  fs::remove(path);
  const std::string name = std::string("dataWindow\0box2i\0", 17);
  const std::size_t at = bytes.find(name);
  EXPECT_NE(at, std::string::npos);
  const std::int32_t box[4] = {0, 0, side - 1, side - 1};
  std::memcpy(&bytes[at + name.size() + 4], box, sizeof box);   // after the attribute's size
  return bytes;
}

std::size_t escapes(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\x1b')); }

}  // namespace

// A class of submissions, each hostile in its own way but for the first and the last two,
// graded in one run: every hostile one fails its scene with its reason, the good ones pass, in
// bounded time and memory (no bomb's pixels decoded, no walk of '/'), the terminal free of
// the control characters a name held, and nothing written outside the report.
TEST(GradeHostile, EverySubmissionFailsOnlyItsOwnSceneWithAReason) {
  const std::string dir = freshDir("grade/hostile");
  const std::string refs = dir + "/refs", cls = dir + "/class", elsewhere = dir + "/elsewhere";
  for (const std::string& f : {refs, cls, elsewhere}) fs::create_directories(f);
  const Image a = solid(8, 6, 90);
  writePngAtomic(a, refs + "/a.png");
  writePngAtomic(a, elsewhere + "/a.png");
  auto student = [&](const std::string& name) {
    fs::create_directories(cls + "/" + name);
    return cls + "/" + name;
  };
  writePngAtomic(a, student("good") + "/a.png");
  fs::create_symlink("/etc/passwd", student("to-passwd") + "/a.png");
  fs::create_symlink("a.png", student("loop") + "/a.png");   // a link to itself
  fs::create_symlink(elsewhere, student("folder-out") + "/hw");
  fs::create_symlink("/", student("folder-root") + "/root");
  fs::create_symlink("/dev/zero", student("device") + "/a.png");
  const std::string many = student("many");
  for (int i = 0; i < 10000; ++i) writeBytes(many + "/x" + std::to_string(i) + ".png", "");
  writePngAtomic(a, many + "/a.png");
  {   // 2 GB that take no disk: a sparse file
    const std::string huge = student("huge") + "/a.png";
    writeBytes(huge, "");
    fs::resize_file(huge, std::uint64_t{2} << 30);
  }
  writeBytes(student("bomb-png") + "/a.png", pngOf(8000, 8000, 8000ull * (1 + 3 * 8000)));
  writeBytes(student("bomb-idat") + "/a.png", pngOf(8, 6, std::uint64_t{256} << 20));
  writeBytes(student("bomb-ppm") + "/a.ppm", "P6\n60000 60000\n255\n" + std::string(100, '\0'));
  writeBytes(student("bomb-pfm") + "/a.pfm", "PF\n60000 60000\n-1.0\n" + std::string(100, '\0'));
  writeBytes(student("bomb-exr") + "/a.exr", exrBomb(dir, 60000));
  writeBytes(student("bomb-jpg") + "/a.jpg", jpegBomb(dir, 60000));
  writePngAtomic(a, student("\x1b]0;pwned\x07\x1b[2J..evil") + "/a.png");   // a name that would steer the terminal
  const std::string before = readFile(refs + "/a.png");

  const auto t0 = std::chrono::steady_clock::now();
  MeasuredRun run = runVkrtMeasuringMemory({"grade", refs, cls, "-o", dir + "/report"}, dir + "/log");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(run.exitCode, 5) << run.output;
  EXPECT_LT(seconds, 60.0) << "bounded time: no walk of '/', no bomb decoded";
  EXPECT_LT(run.peakRssKb, 150 * 1024) << "bounded memory: the PNG bomb alone is 192 MB of pixels";
  EXPECT_EQ(escapes(run.output), 0u) << "no raw escape on the terminal";
  const std::string json = readFile(dir + "/report/summary.json");
  auto result = [&](const std::string& name) {
    const std::size_t at = json.find("{\"name\": \"" + name + "\"");
    return at == std::string::npos ? std::string() : json.substr(at, json.find("\n  {\"name\"", at + 1) - at);
  };
  const std::pair<const char*, const char*> expected[] = {
      {"good", "\"status\": \"pass\""},
      {"to-passwd", "is a link to a file outside the submission ('/etc/passwd')"},
      {"loop", "where it leads cannot be told"},
      {"folder-out", "hw: a link to a folder outside the submission ('" },
      {"folder-root", "root: a link to a folder outside the submission ('/'); not searched"},
      {"device", "is a link to a file outside the submission ('/dev/zero')"},
      {"many", "and 9995 more images of no scene; not graded"},
      {"huge", "is 2048 MB, longer than an image of the reference's size can be (64 MB); not read"},
      {"bomb-png", "the image is 8000x8000, the reference 8x6"},
      {"bomb-idat", "its compressed data inflates past the 1370 bytes its 8x6 pixels take (a decompression bomb)"},
      {"bomb-ppm", "60000"},
      {"bomb-pfm", "60000"},
      {"bomb-exr", "cannot read image"},   // its line offsets, read for 60000 rows, end early
      {"bomb-jpg", "the image is 60000x60000, the reference 8x6"},
  };
  for (const auto& [name, said] : expected) {
    const std::string r = result(name);
    EXPECT_TRUE(contains(r, said)) << name << ": " << said << "\n" << r;
    if (std::string(name) != "good" && std::string(name) != "many") {
      EXPECT_FALSE(contains(r, "\"status\": \"pass\"")) << name << "\n" << r;
    }
  }
  EXPECT_TRUE(contains(result("many"), "\"status\": \"pass\"")) << result("many");
  EXPECT_TRUE(contains(json, "..evil\", \"folder\": ")) << "the name kept as it is in the JSON";
  EXPECT_TRUE(contains(run.output, "\\x1B]0;pwned\\x07\\x1B[2J..evil")) << run.output;
  EXPECT_LT(fs::file_size(dir + "/report/index.html"), 2u << 20) << "ten thousand files noted in a few lines";
  EXPECT_EQ(readFile(refs + "/a.png"), before);
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.path().filename() != "log";
  EXPECT_EQ(entries, 4u) << "refs, class, elsewhere and the report: nothing else written";
}

// A FIFO named as an image, which a read would wait on for ever: its scene fails at once, and
// the student's other image is graded.
TEST(GradeHostile, AFifoNamedAsAnImageDoesNotHoldTheRun) {
  const std::string dir = freshDir("grade/hostile-fifo");
  for (const char* f : {"refs", "class/fifo"}) fs::create_directories(dir + "/" + f);
  writePngAtomic(solid(8, 6, 90), dir + "/refs/a.png");
  writePngAtomic(solid(8, 6, 90), dir + "/refs/b.png");
  writePngAtomic(solid(8, 6, 90), dir + "/class/fifo/b.png");
  ASSERT_EQ(::mkfifo((dir + "/class/fifo/a.png").c_str(), 0644), 0);
  Finished f = waitVkrtWithin(spawnVkrt({"grade", dir + "/refs", dir + "/class", "-o", dir + "/report"}, dir + "/log"), 30);
  EXPECT_EQ(f.exitCode, 4) << "not killed after 30 s: " << f.output;
  EXPECT_TRUE(contains(f.output, "vkrt: fifo: a: '" + dir + "/class/fifo/a.png' is a FIFO, not a regular file; not read"))
      << f.output;
  EXPECT_TRUE(contains(f.output, "vkrt: fifo                 1/2 pass; unreadable: a")) << f.output;
}

// Scene files handed in (rendered by the grader): a FIFO that would block the run, a sparse
// file of 2 GB, a hundred thousand nested transforms, a scene whose output names the reference
// and a file elsewhere, and a name with control characters. Each fails or renders on its own,
// within a minute, and nothing but the report is written.
TEST(GradeHostile, SceneFilesThatAreSpecialHugeDeepOrWriteElsewhere) {
  const std::string dir = freshDir("grade/hostile-scenes");
  const std::string refs = dir + "/refs", sub = dir + "/student";
  for (const std::string& f : {refs, sub}) fs::create_directories(f);
  const std::string ball = "size 8 6\ncamera 0 0 5 0 0 0 0 1 0 45\nambient 0.2 0.4 0.6\nsphere 0 0 0 1\n";
  writeFile(sub + "/good.test", ball);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + refs + "/good.png " + sub + "/good.test").exitCode, 0);
  for (const char* scene : {"fifo", "huge", "deep", "writer", "esc\x1b[2J"})
    fs::copy_file(refs + "/good.png", refs + "/" + scene + ".png");
  ASSERT_EQ(::mkfifo((sub + "/fifo.test").c_str(), 0644), 0);
  writeBytes(sub + "/huge.test", "");
  fs::resize_file(sub + "/huge.test", std::uint64_t{2} << 30);
  std::string deep = ball;
  for (int i = 0; i < 100000; ++i) deep += "pushTransform\n";
  deep += "sphere 0 0 0 1\n";
  for (int i = 0; i < 100000; ++i) deep += "popTransform\n";
  writeFile(sub + "/deep.test", deep);
  writeFile(sub + "/writer.test", ball + "output " + refs + "/good.png\n");
  const std::string esc = sub + "/esc\x1b[2J.test";
  writeFile(esc, ball + "output " + dir + "/elsewhere.png\n");
  const std::string before = readFile(refs + "/good.png");

  Spawned p = spawnVkrt({"grade", "--backend", "cpu", refs, sub + "/good.test", sub + "/fifo.test", sub + "/huge.test",
                         sub + "/deep.test", sub + "/writer.test", esc, "-o", dir + "/report"},
                        dir + "/log");
  Finished f = waitVkrtWithin(p, 60);
  EXPECT_NE(f.exitCode, 137) << "the run must not wait on the FIFO: " << f.output;
  EXPECT_EQ(f.exitCode, 4) << f.output;
  EXPECT_EQ(escapes(f.output), 0u) << f.output;
  const std::string json = readFile(dir + "/report/summary.json");
  EXPECT_TRUE(contains(json, "fifo.test' is a FIFO, not a regular file; not read")) << json;
  EXPECT_TRUE(contains(json, "huge.test' is 2048 MB, longer than a scene file handed in can be (32 MB); not read")) << json;
  for (const char* scene : {"good", "deep", "writer", "esc\\u001b[2J"})
    EXPECT_TRUE(contains(json, std::string("{\"scene\": \"") + scene + "\", \"status\": \"pass\"")) << scene << "\n" << json;
  EXPECT_EQ(readFile(refs + "/good.png"), before);
  EXPECT_FALSE(fs::exists(dir + "/elsewhere.png"));
}

// How an image is judged is the teacher's to say: a scene file beside the reference decides
// whether the scene is path-traced (judged by its noise) and its gamma, whatever the
// student's scene file of that name declares.
TEST(GradeHostile, AStudentsSceneFileDoesNotChooseHowItIsJudged) {
  const std::string dir = freshDir("grade/hostile-judging");
  const std::string refs = dir + "/refs", sub = dir + "/student";
  for (const std::string& f : {refs, sub}) fs::create_directories(f);
  const std::string whitted = "size 8 6\ncamera 0 0 5 0 0 0 0 1 0 45\nambient 0.2 0.4 0.6\nsphere 0 0 0 1\n";
  writeFile(refs + "/ball.test", whitted);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + refs + "/ball.png " + refs + "/ball.test").exitCode, 0);
  writeFile(sub + "/ball.test", whitted + "integrator pathtracer\nspp 4\ngamma 2.2\n");
  RunResult r = runVkrt("grade --backend cpu " + refs + " " + sub + "/ball.test -o " + dir + "/report");
  const std::string json = readFile(dir + "/report/summary.json");
  EXPECT_TRUE(contains(json, "\"thresholds\": \"any difference fails\"")) << r.output << json;
  EXPECT_FALSE(contains(json, "max-bias-z")) << json;
}
