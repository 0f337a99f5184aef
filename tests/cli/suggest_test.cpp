// "Did you mean ...?" after a typo: the edit-distance helper (host/util/suggest.h), and each place
// that uses it: a subcommand, an option, a scene command; an image given as a scene; usage
// errors in two lines, the usage text only for --help.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli/image_argument.h"
#include "cli/options.h"
#include "util/errors.h"
#include "image/image_file.h"
#include "image/pfm.h"
#include "scene/parse.h"
#include "util/suggest.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

namespace {

const std::string kScene =
    "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\ndiffuse 0.5 0 0\n";

constexpr std::string_view kNames[] = {"diff", "merge", "sphere", "backend", "maxdepth", "spp", "seed"};

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string lastLine(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  return t.substr(t.rfind('\n') + 1);
}

std::size_t lineCount(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

TEST(Suggest, EditDistanceCountsEditsIgnoringCase) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("sphere", "sphere"), 0u);
  EXPECT_EQ(editDistance("SPHERE", "sphere"), 0u);   // case is no edit
  EXPECT_EQ(editDistance("sphre", "sphere"), 1u);    // a deletion
  EXPECT_EQ(editDistance("spherex", "sphere"), 1u);  // an insertion
  EXPECT_EQ(editDistance("sphare", "sphere"), 1u);   // a substitution
  EXPECT_EQ(editDistance("mrege", "merge"), 1u);     // two adjacent letters swapped: one edit
  EXPECT_EQ(editDistance("bakcend", "backend"), 1u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("ca", "abc"), 3u);          // optimal string alignment: no edit of a swapped pair
  EXPECT_EQ(editDistance("abc", "ca"), editDistance("ca", "abc"));
}

// The optimal-string-alignment distance by its recursive definition (no table), for short
// words: an oracle written apart from editDistance's rows.
std::size_t osaDistance(std::string_view a, std::string_view b) {
  if (a.empty()) return b.size();
  if (b.empty()) return a.size();
  auto low = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const std::size_t i = a.size(), j = b.size();
  std::size_t d = std::min({osaDistance(a.substr(0, i - 1), b) + 1, osaDistance(a, b.substr(0, j - 1)) + 1,
                            osaDistance(a.substr(0, i - 1), b.substr(0, j - 1)) + (low(a[i - 1]) == low(b[j - 1]) ? 0 : 1)});
  if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1]))
    d = std::min(d, osaDistance(a.substr(0, i - 2), b.substr(0, j - 2)) + 1);
  return d;
}

// Every pair of words of up to 3 letters from a 3-letter alphabet (case mixed in), empty words
// included: the table's rows agree with the recursion, in both orders.
TEST(Suggest, EditDistanceAgreesWithTheRecursiveDefinition) {
  std::vector<std::string> words = {""};
  for (std::size_t n = 0; words.size() < 40; ++n)
    for (char c : {'a', 'B', 'c'}) words.push_back(words[n] + c);
  std::size_t pairs = 0;
  for (const std::string& a : words)
    for (const std::string& b : words) {
      ASSERT_EQ(editDistance(a, b), osaDistance(a, b)) << "'" << a << "' and '" << b << "'";
      ++pairs;
    }
  EXPECT_EQ(pairs, 40u * 40u);
}

TEST(Suggest, ClosestMatchOnlyWhenNearForTheWordsLength) {
  EXPECT_EQ(closestMatch("dif", kNames), "diff");
  EXPECT_EQ(closestMatch("DIFF", kNames), "diff");
  EXPECT_EQ(closestMatch("mrege", kNames), "merge");
  EXPECT_EQ(closestMatch("sphre", kNames), "sphere");
  EXPECT_EQ(closestMatch("bxckxxd", kNames), std::nullopt);   // 3 edits from backend
  EXPECT_EQ(closestMatch("bakcedn", kNames), "backend");      // 2 edits, 7 letters
  EXPECT_EQ(closestMatch("dfx", kNames), std::nullopt);       // 2 edits from diff, 3 letters: 1 at most
  EXPECT_EQ(closestMatch("sp", kNames), "spp");
  EXPECT_EQ(closestMatch("s", kNames), std::nullopt);         // one letter: only itself in another case
  EXPECT_EQ(closestMatch("", kNames), std::nullopt);
  EXPECT_EQ(closestMatch("refraction", kNames), std::nullopt);
  // Of two equally near, the first; a nearer one wins wherever it is.
  constexpr std::string_view tie[] = {"seed", "send", "sees"};
  EXPECT_EQ(closestMatch("seod", tie), "seed");
  constexpr std::string_view nearer[] = {"seeds", "seed"};
  EXPECT_EQ(closestMatch("seed", nearer), "seed");
  // Of two equally near, the one the word begins: a name cut short, wherever it stands.
  constexpr std::string_view cut[] = {"max-bias", "max-bias-z"}, cutBackwards[] = {"max-bias-z", "max-bias"};
  EXPECT_EQ(closestMatch("max-bias-", cut), "max-bias-z");
  EXPECT_EQ(closestMatch("max-bias-", cutBackwards), "max-bias-z");
  EXPECT_EQ(closestMatch("max-bias", cut), "max-bias");
  // A long token is refused by its length, without a full comparison.
  EXPECT_EQ(closestMatch(std::string(500000, 'q'), kNames), std::nullopt);
  EXPECT_EQ(didYouMean("bakcend", kNames, "--"), "; did you mean '--backend'?");
  EXPECT_EQ(didYouMean("zzzzzz", kNames), "");
}

TEST(Suggest, ImagesAreKnownByTheirBytesOrElseTheirNames) {
  std::string dir = freshDir("suggest/image-kind");
  writeImageAtomic(gradient(4, 3), dir + "/a.png");
  writeImageAtomic(gradient(4, 3), dir + "/a.ppm");
  RadianceImage pfm(4, 3);
  writePfmAtomic(pfm, dir + "/a.pfm");
  // A PNG, whatever its name (vkrt writes no output named .test: written, then renamed).
  writeImageAtomic(gradient(4, 3), dir + "/png-named.png");
  fs::rename(dir + "/png-named.png", dir + "/png-named.test");
  writeFile(dir + "/scene.png", kScene);                      // text: a scene, whatever its name
  writeFile(dir + "/p3.test", "P3\n1 1\n255\n0 0 0\n");
  EXPECT_EQ(imageKind(dir + "/a.png"), "PNG");
  EXPECT_EQ(imageKind(dir + "/a.ppm"), "PPM");
  EXPECT_EQ(imageKind(dir + "/a.pfm"), "PFM");
  EXPECT_EQ(imageKind(dir + "/png-named.test"), "PNG");
  EXPECT_EQ(imageKind(dir + "/p3.test"), "PPM");
  EXPECT_EQ(imageKind(dir + "/scene.png"), std::nullopt);
  EXPECT_EQ(imageKind(dir + "/missing.PNG"), "PNG");   // nothing to read: the name says
  EXPECT_EQ(imageKind(dir + "/missing.pfm"), "PFM");
  EXPECT_EQ(imageKind(dir + "/missing.test"), std::nullopt);
  EXPECT_EQ(imageKind(dir), std::nullopt);   // a directory: the scene reader says what is wrong
}

// `vkrt dif a.png b.png` read the PNGs as scene files ("file is not text", exit 4) and
// `vkrt mrege -o x.png a.pfm` said "-o x.png names one file, for 2 scenes".
TEST(Suggest, MistypedSubcommandIsAUsageErrorWithTheCommand) {
  RunResult dif = runVkrt("dif a.png b.png");
  EXPECT_EQ(dif.exitCode, 1) << dif.output;
  EXPECT_EQ(dif.output, "vkrt: error: unknown command 'dif'; did you mean 'diff'?\nsee 'vkrt --help'\n");
  RunResult mrege = runVkrt("mrege -o x.png a.pfm");
  EXPECT_EQ(mrege.exitCode, 1) << mrege.output;
  EXPECT_TRUE(contains(mrege.output, "vkrt: error: unknown command 'mrege'; did you mean 'merge'?\n")) << mrege.output;
  RunResult upper = runVkrt("DIFF a.png b.png");
  EXPECT_TRUE(contains(upper.output, "unknown command 'DIFF'; did you mean 'diff'?")) << upper.output;
  // A file of that name is a scene, read as one.
  std::string dir = freshDir("suggest/subcommand-file");
  writeFile(dir + "/dif", kScene + "sphere 0 0 0 1\n");
  RunResult file = runCommand("cd " + dir + " && " + vkrtBinary() + " --backend cpu -q -o o.png dif");
  EXPECT_EQ(file.exitCode, 0) << file.output;
  EXPECT_TRUE(fileExists(dir + "/o.png"));
  // A name far from every subcommand is a scene that is not there (I/O error), as before.
  RunResult far = runVkrt("render-me.test");
  EXPECT_EQ(far.exitCode, 4) << far.output;
}

TEST(Suggest, UnknownOptionNamesTheNearestLongOption) {
  for (const char* args : {"--bakcend cpu x.test", "--bakcend=cpu x.test", "-backend cpu x.test", "--BACKEND cpu x.test"}) {
    RunResult r = runVkrt(args);
    EXPECT_EQ(r.exitCode, 1) << args;
    EXPECT_TRUE(contains(r.output, "; did you mean '--backend'?\nsee 'vkrt --help'\n")) << args << "\n" << r.output;
  }
  RunResult spp = runVkrt("--sp 4 x.test");
  EXPECT_TRUE(contains(spp.output, "unknown option '--sp'; did you mean '--spp'?")) << spp.output;
  RunResult far = runVkrt("--frobnicate x.test");
  EXPECT_EQ(far.output, "vkrt: error: unknown option '--frobnicate'\nsee 'vkrt --help'\n");
  RunResult diff = runVkrt("diff --max-dif 3 a.png b.png");
  EXPECT_TRUE(contains(diff.output, "unknown option '--max-dif'; did you mean '--max-diff'?")) << diff.output;
  RunResult merge = runVkrt("merge --alow-gaps -o m.png t.png");
  EXPECT_EQ(merge.exitCode, 1) << merge.output;
  EXPECT_TRUE(contains(merge.output, "unknown merge option '--alow-gaps' (merge takes -o OUT.png, --allow-gaps, --strict, -q); "
                                     "did you mean '--allow-gaps'?"))
      << merge.output;
}

// Every long option of --help is suggested for itself with its last letter missing: the
// list of names the suggestions come from keeps up with the options.
TEST(Suggest, EveryLongOptionOfHelpIsSuggested) {
  const std::string help = usageText();
  std::set<std::string> options;
  for (std::size_t at = help.find("--"); at != std::string::npos; at = help.find("--", at + 2)) {
    std::size_t end = at + 2;
    while (end < help.size() && ((help[end] >= 'a' && help[end] <= 'z') || help[end] == '-')) ++end;
    if (end > at + 2) options.insert(help.substr(at, end - at));
  }
  ASSERT_GT(options.size(), 25u);
  for (const std::string& option : options) {
    const std::string typo = option.substr(0, option.size() - 1);
    const bool gradeOnly = option == "--max-bias" || option == "--max-variance" || option == "--max-bias-z" ||
                           option == "--thresholds" || option == "--gradescope" || option == "--points" ||
                           option == "--one-student" || option.rfind("--limit-", 0) == 0;
    std::vector<std::string> args = option == "--allow-gaps" ? std::vector<std::string>{"merge", typo}
                                    : gradeOnly              ? std::vector<std::string>{"grade", typo}
                                                             : std::vector<std::string>{typo, "x.test"};
    try {
      parseOptions(args);
      ADD_FAILURE() << typo << ": no error";
    } catch (const UsageError& e) {
      EXPECT_TRUE(contains(e.what(), "did you mean '" + option + "'?")) << e.what();
    }
  }
}

// A typo as near a shape's command as another command's is suggested as the one the format
// lists first: `spare` is 2 from both `sphere` and `scale`.
TEST(Suggest, ShapeCommandsKeepTheFormatsOrderInSuggestions) {
  ParsedScene p = parseSceneWithWarnings(kScene + "spare 0 0 0 1\n", "s.test");
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0].format(), "s.test:5: warning: unknown command 'spare' (line skipped); did you mean 'sphere'?");
}

// `sphre 0 0 0 1` is skipped with a warning (the picture renders without the sphere): the
// warning, at its line, names the command meant.
TEST(Suggest, UnknownSceneCommandWarningNamesTheNearestCommand) {
  ParsedScene p = parseSceneWithWarnings(kScene + "sphre 0 0 0 1\nrefraction 1.5\nPopTransfrom\n", "s.test");
  ASSERT_EQ(p.warnings.size(), 3u);
  EXPECT_EQ(p.warnings[0].format(), "s.test:5: warning: unknown command 'sphre' (line skipped); did you mean 'sphere'?");
  EXPECT_EQ(p.warnings[1].format(), "s.test:6: warning: unknown command 'refraction' (line skipped)");
  EXPECT_EQ(p.warnings[2].format(),
            "s.test:7: warning: unknown command 'PopTransfrom' (line skipped); did you mean 'popTransform'?");
  EXPECT_TRUE(p.scene.spheres.empty());
  std::string dir = freshDir("suggest/keyword");
  writeFile(dir + "/s.test", kScene + "sphre 0 0 0 1\n");
  RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 0) << r.output;   // still a warning
  EXPECT_TRUE(contains(r.output, dir + "/s.test:5: warning: unknown command 'sphre' (line skipped); did you mean 'sphere'?"))
      << r.output;
  EXPECT_TRUE(fileExists(dir + "/o.png"));
}

// An image where a scene is expected is said to be one, in one line (exit 1, nothing
// written), whatever its name; a text scene is read whatever its name.
TEST(Suggest, ImageGivenAsASceneIsAUsageError) {
  std::string dir = freshDir("suggest/image-scene");
  writeImageAtomic(gradient(4, 3), dir + "/a.png");
  writeImageAtomic(gradient(4, 3), dir + "/b.ppm");
  writePfmAtomic(RadianceImage(4, 3), dir + "/c.pfm");
  writeImageAtomic(gradient(4, 3), dir + "/png-named.png");
  fs::rename(dir + "/png-named.png", dir + "/png-named.test");
  const std::string tail = " image, not a scene file (to compare images: vkrt diff A B; to merge tiles: "
                           "vkrt merge -o OUT TILE ...)\nsee 'vkrt --help'\n";
  for (auto [file, kind] : {std::pair{"a.png", "PNG"}, std::pair{"b.ppm", "PPM"}, std::pair{"c.pfm", "PFM"},
                            std::pair{"png-named.test", "PNG"}, std::pair{"missing.png", "PNG"}}) {
    RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/" + file);
    EXPECT_EQ(r.exitCode, 1) << file << "\n" << r.output;
    EXPECT_EQ(r.output, "vkrt: error: " + dir + "/" + file + " is a " + kind + tail) << file;
  }
  // Two images and -o FILE: the images are what is wrong, not the count.
  RunResult two = runVkrt("-o " + dir + "/o.png " + dir + "/a.png " + dir + "/c.pfm");
  EXPECT_TRUE(contains(two.output, dir + "/a.png is a PNG image, not a scene file")) << two.output;
  EXPECT_FALSE(fileExists(dir + "/o.png"));
  writeFile(dir + "/scene.png", kScene + "sphere 0 0 0 1\n");
  RunResult text = runVkrt("--backend cpu -q -o " + dir + "/o.png " + dir + "/scene.png");
  EXPECT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(fileExists(dir + "/o.png"));
}

// Every usage error is its line and where the usage is; --help alone prints the usage.
TEST(Suggest, UsageErrorsAreOneLineAndAPointerToHelp) {
  for (const char* args : {"", "--bogus x.test", "--threads 0 x.test", "-o", "-o x.png a.test b.test",
                           "diff a.png", "merge -o m.png"}) {
    RunResult r = runVkrt(args);
    EXPECT_EQ(r.exitCode, 1) << args;
    EXPECT_EQ(r.output.rfind("vkrt: error: ", 0), 0u) << args << "\n" << r.output;
    EXPECT_EQ(lineCount(r.output), 2u) << args << "\n" << r.output;
    EXPECT_EQ(lastLine(r.output), "see 'vkrt --help'") << args;
    EXPECT_FALSE(contains(r.output, "usage: vkrt")) << args;
  }
  RunResult help = runVkrt("--help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_EQ(help.output, usageText());
}
