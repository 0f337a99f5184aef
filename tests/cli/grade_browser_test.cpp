// The grading report in a real browser (headless Chromium, Debian's `chromium`): every file a
// page names is there, the pages load with no console message, the script sorts and shows
// the comparison slider, the screenshot shows the thumbnails, and without JavaScript the
// same table is there to read. Skipped (saying so) where Chromium is not installed, except
// in CI, where it fails.
#include <filesystem>

#include <gtest/gtest.h>

#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace fs = std::filesystem;

namespace {

constexpr const char* kNoChromium =
    "no chromium here (apt install chromium): the grading report is not opened in a browser";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::optional<std::string> chromium() {
  for (const char* name : {"chromium", "chromium-browser"}) {
    RunResult r = runCommand(std::string("command -v ") + name);
    if (r.exitCode == 0 && !r.output.empty()) return r.output.substr(0, r.output.find('\n'));
  }
  return std::nullopt;
}

struct Browser {
  std::string binary, profile;
  // Opens `url` headless and returns what it prints: the DOM after its scripts ran (stdout)
  // and the browser's log (stderr, where the page's console messages appear as ":CONSOLE").
  RunResult open(const std::string& url, const std::string& options, std::string* dom) const {
    const std::string out = profile + ".dom";
    RunResult r = runCommand("'" + binary + "' --headless=new --no-sandbox --disable-gpu --no-first-run --user-data-dir='" +
                             profile + "' --enable-logging=stderr --v=0 " + options + " '" + url + "' > '" + out + "'");
    if (dom) *dom = readFile(out);
    return r;
  }
};

// The console lines of a browser's log.
std::string consoleLines(const std::string& log) {
  std::string lines;
  std::size_t at = 0;
  while (at < log.size()) {
    std::size_t end = log.find('\n', at);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(at, end - at);
    if (contains(line, ":CONSOLE")) lines += line + "\n";
    at = end + 1;
  }
  return lines;
}

Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) im.pixel(x, y)[0] = r, im.pixel(x, y)[1] = g, im.pixel(x, y)[2] = b;
  return im;
}

// Three students against two references: s1 and s3 pass both, s2 fails one and lacks the
// other. The submitted images are orange, which nothing else on the page is.
std::string makeReport(const std::string& dir) {
  for (const char* f : {"refs", "subs/s1", "subs/s2", "subs/s3"}) fs::create_directories(dir + "/" + f);
  const Image orange = solid(64, 48, 255, 128, 0), teal = solid(64, 48, 0, 128, 128);
  writePngAtomic(orange, dir + "/refs/warm.png");
  writePngAtomic(teal, dir + "/refs/cool.png");
  for (const char* s : {"s1", "s3"}) {
    writePngAtomic(orange, dir + "/subs/" + s + "/warm.png");
    writePngAtomic(teal, dir + "/subs/" + s + "/cool.png");
  }
  Image wrong = orange;
  for (int x = 10; x < 30; ++x) wrong.pixel(x, 20)[2] = 255;
  writePngAtomic(wrong, dir + "/subs/s2/warm.png");
  RunResult r = runVkrt("grade -q " + dir + "/refs " + dir + "/subs -o " + dir + "/report");
  EXPECT_EQ(r.exitCode, 5) << r.output;
  return dir + "/report";
}

// Every src= and href= of `page` that names a file (not data:, an address or a #fragment):
// the path it names, relative to the page.
std::vector<std::string> namedFiles(const std::string& page) {
  std::vector<std::string> files;
  const std::string text = readFile(page);
  for (const std::string attribute : {"src=\"", "href=\""})
    for (std::size_t at = text.find(attribute); at != std::string::npos; at = text.find(attribute, at + 1)) {
      const std::size_t start = at + attribute.size(), end = text.find('"', start);
      const std::string target = text.substr(start, end - start);
      if (target.empty() || target.find_first_of(":#") != std::string::npos) continue;
      files.push_back((fs::path(page).parent_path() / target).lexically_normal().string());
    }
  return files;
}

// What a screenshot shows: the orange of the submitted images, the page's light background
// and its dark text.
struct Pixels {
  long long all = 0, orange = 0, light = 0, dark = 0;
};
Pixels countPixels(const std::string& shot) {
  Image image = readImage(shot);
  Pixels n;
  n.all = static_cast<long long>(image.width) * image.height;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      n.orange += p[0] > 240 && p[1] > 110 && p[1] < 146 && p[2] < 20;
      n.light += p[0] > 240 && p[1] > 240 && p[2] > 240;
      n.dark += p[0] < 60 && p[1] < 60 && p[2] < 60;
    }
  std::printf("[ stats    ] %s %dx%d: %lld orange, %lld light, %lld dark pixels\n", shot.c_str(), image.width,
              image.height, n.orange, n.light, n.dark);
  return n;
}

std::optional<Browser> browserOrSkip(const std::string& dir) {
  std::optional<std::string> binary = chromium();
  if (!binary) return std::nullopt;
  return Browser{*binary, dir + "/profile"};
}

}  // namespace

TEST(GradeReportBrowser, LoadsSortsAndShowsItsImages) {
  std::string dir = freshDir("grade/browser");
  std::optional<Browser> browser = browserOrSkip(dir);
  if (!browser) VKRT_SKIP_UNLESS_CI(kNoChromium);
  const std::string report = makeReport(dir);

  // Every file a page names is in the folder: it is self-contained.
  std::vector<std::string> pages{report + "/index.html"};
  for (const auto& e : fs::directory_iterator(report + "/pages")) pages.push_back(e.path().string());
  EXPECT_EQ(pages.size(), 6u);   // the overview and five comparisons (s2's cool is missing)
  for (const std::string& page : pages)
    for (const std::string& file : namedFiles(page)) EXPECT_TRUE(fs::is_regular_file(file)) << page << " names " << file;

  // The overview: no console message; the script ran (the headings sortable); sorted by the
  // address, descending and ascending, by the "passed" column.
  std::string dom;
  RunResult r = browser->open("file://" + report + "/index.html", "--dump-dom", &dom);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(consoleLines(r.output), "");
  EXPECT_TRUE(contains(dom, "<th class=\"sortable\"")) << dom;
  EXPECT_LT(dom.find(">s1<"), dom.find(">s2<"));
  browser->open("file://" + report + "/index.html#sort=1", "--dump-dom", &dom);
  EXPECT_LT(dom.find(">s2<"), dom.find(">s1<")) << "s2 passed fewest: first going up";
  EXPECT_TRUE(contains(dom, "sorted-up")) << dom;
  browser->open("file://" + report + "/index.html#sort=1-down", "--dump-dom", &dom);
  EXPECT_GT(dom.find(">s2<"), dom.find(">s3<")) << "s2 last going down";

  // A comparison page: no console message, the slider shown, the failing pixels boxed.
  r = browser->open("file://" + report + "/pages/s0002-c002.html", "--dump-dom", &dom);
  EXPECT_EQ(consoleLines(r.output), "");
  EXPECT_TRUE(contains(dom, "<section class=\"compare\">")) << dom;
  EXPECT_TRUE(contains(dom, "class=\"region\"")) << dom;

  // The screenshot is not blank: the orange thumbnails are drawn (three, 96x72 each).
  const std::string shot = dir + "/overview.png";
  r = browser->open("file://" + report + "/index.html", "--window-size=1000,700 --screenshot='" + shot + "'", nullptr);
  ASSERT_TRUE(fileExists(shot)) << r.output;
  const Pixels px = countPixels(shot);
  EXPECT_GE(px.orange, 3 * 96 * 72 * 9 / 10) << shot;
  EXPECT_GT(px.light + px.dark, px.all / 4) << shot << ": no page behind the thumbnails";
  EXPECT_GT(px.dark, 500) << shot << ": no text";
}

// Without its script (grade.js emptied in a copy of the report: headless Chromium with
// scripts off neither dumps nor draws a page), the overview shows its table with every
// thumbnail, and a comparison page its images side by side (the one-frame slider, which needs
// the script, stays hidden: one orange image less than with it).
TEST(GradeReportBrowser, ReadableWithoutJavaScript) {
  std::string dir = freshDir("grade/browser-nojs");
  std::optional<Browser> browser = browserOrSkip(dir);
  if (!browser) VKRT_SKIP_UNLESS_CI(kNoChromium);
  const std::string report = makeReport(dir), bare = dir + "/bare";
  fs::copy(report, bare, fs::copy_options::recursive);
  writeFile(bare + "/grade.js", "");
  auto shoot = [&](const std::string& folder, const std::string& page, const std::string& shot) {
    RunResult r = browser->open("file://" + folder + "/" + page, "--window-size=1000,700 --screenshot='" + shot + "'", nullptr);
    EXPECT_EQ(consoleLines(r.output), "");
    EXPECT_TRUE(fileExists(shot)) << r.output;
    return countPixels(shot);
  };
  std::string dom;
  browser->open("file://" + bare + "/index.html", "--dump-dom", &dom);
  EXPECT_FALSE(contains(dom, "<th class=\"sortable\"")) << "the script did not run";
  for (const char* part : {">s1<", ">s2<", ">s3<", ">pass<", ">fail<", ">missing<", ">2/2<", ">0/2<"})
    EXPECT_TRUE(contains(dom, part)) << part;
  const Pixels overview = shoot(bare, "index.html", dir + "/overview.png");
  EXPECT_GE(overview.orange, 3 * 96 * 72 * 9 / 10);
  EXPECT_GT(overview.dark, 500) << "no text";
  // s2's warm page: reference and submission (orange, 64x48 each, shown as they are).
  const Pixels still = shoot(bare, "pages/s0002-c002.html", dir + "/page.png");
  EXPECT_GE(still.orange, 2 * 64 * 48 * 3 / 4);   // less the magenta boxes around the failing row
  EXPECT_GT(shoot(report, "pages/s0002-c002.html", dir + "/page-js.png").orange, still.orange + 64 * 48 / 2)
      << "with the script: the slider's frame too";
}
