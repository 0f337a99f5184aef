// Each command's table of options (host/cli/options.cpp) against what documents it: every
// option of a table is in `vkrt --help` and among the man page's options (doc/vkrt.1), the man
// page lists no option that no table has, --help's option lines name only the tables'
// options, and the hidden rows (for the benchmark and tests) are in neither.
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/option_rows.h"
#include "cli/options.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::regex kOption("(^|[^A-Za-z0-9-])(--?[a-z][a-z-]*)");

// Every option named in `text` ("-o", "--output").
std::set<std::string> optionsIn(const std::string& text) {
  std::set<std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), kOption), end; it != end; ++it) out.insert((*it)[2]);
  return out;
}

// The man page with "\-" read as "-" and its changes of font ("\fR") left out.
std::string manPage() {
  std::string text = readFile(sourcePath("doc/vkrt.1"));
  for (std::size_t at = text.find("\\-"); at != std::string::npos; at = text.find("\\-", at)) text.erase(at, 1);
  for (std::size_t at = text.find("\\f"); at != std::string::npos; at = text.find("\\f", at)) text.erase(at, 3);
  return text;
}

// The options of the man page's lists: those the line after each ".TP" names.
std::set<std::string> manPageOptions(const std::string& page) {
  std::set<std::string> out;
  for (std::size_t at = page.find("\n.TP\n"); at != std::string::npos; at = page.find("\n.TP\n", at + 1)) {
    const std::size_t begin = at + 5, end = page.find('\n', begin);
    for (const std::string& o : optionsIn(page.substr(begin, end - begin))) out.insert(o);
  }
  return out;
}

// The options of --help's option lines: in each line that starts "  -", up to its text.
std::set<std::string> helpLineOptions(const std::string& help) {
  std::set<std::string> out;
  for (std::size_t at = help.find("\n  -"); at != std::string::npos; at = help.find("\n  -", at + 1)) {
    const std::size_t end = help.find('\n', at + 1);
    std::string line = help.substr(at + 1, end - at - 1);
    line = line.substr(0, std::min(line.find("   "), line.size()));   // the head, before its text
    for (const std::string& o : optionsIn(line)) out.insert(o);
  }
  return out;
}

template <class Options>
void collectHidden(std::span<const OptionRow<Options>> rows, std::vector<std::string>& out) {
  for (const OptionRow<Options>& row : rows)
    if (row.section == HelpSection::Hidden) out.emplace_back(row.names);
}

}  // namespace

TEST(OptionTable, HelpManPageAndTablesNameTheSameOptions) {
  const std::vector<std::string> documented = documentedOptions();
  const std::set<std::string> tables(documented.begin(), documented.end());
  ASSERT_GT(tables.size(), 35u);
  const std::set<std::string> help = optionsIn(usageText()), page = manPageOptions(manPage());
  for (const std::string& o : tables) {
    EXPECT_TRUE(help.count(o)) << o << ": in a table of options, not in --help";
    EXPECT_TRUE(page.count(o)) << o << ": in a table of options, not among the options of doc/vkrt.1";
  }
  for (const std::string& o : page) EXPECT_TRUE(tables.count(o)) << o << ": in doc/vkrt.1, in no table of options";
  for (const std::string& o : helpLineOptions(usageText()))
    EXPECT_TRUE(tables.count(o)) << o << ": an option line of --help, in no table of options";
}

TEST(OptionTable, HiddenRowsAreNotDocumented) {
  std::vector<std::string> hidden;
  collectHidden(renderOptionRows(), hidden);
  collectHidden(mergeOptionRows(), hidden);
  collectHidden(convertOptionRows(), hidden);
  collectHidden(gradeOptionRows(), hidden);
  ASSERT_FALSE(hidden.empty());
  const std::set<std::string> help = optionsIn(usageText()), page = optionsIn(manPage());
  for (const std::string& o : hidden) {
    EXPECT_FALSE(help.count(o)) << o << ": a hidden option, in --help";
    EXPECT_FALSE(page.count(o)) << o << ": a hidden option, in doc/vkrt.1";
  }
}

// A row's spellings each parse to its setter: -o and --output, -q and --quiet, and
// --name=value as --name value.
TEST(OptionTable, EverySpellingOfARowParses) {
  auto render = [](const std::vector<std::string>& args) { return std::get<RenderOptions>(parseOptions(args)); };
  EXPECT_EQ(render({"-o", "a.png", "s.test"}).request.output, "a.png");
  EXPECT_EQ(render({"--output", "a.png", "s.test"}).request.output, "a.png");
  EXPECT_EQ(render({"--output=a.png", "s.test"}).request.output, "a.png");
  EXPECT_TRUE(render({"-q", "s.test"}).quiet);
  EXPECT_TRUE(render({"--quiet", "s.test"}).quiet);
  EXPECT_EQ(render({"--spp=7", "s.test"}).request.spp, 7u);
  EXPECT_EQ(render({"--", "-s.test"}).request.scenePath, "-s.test");
  MergeOptions merge = std::get<MergeOptions>(parseOptions({"merge", "--output=m.png", "--allow-gaps", "t.png"}));
  EXPECT_EQ(merge.output, "m.png");
  EXPECT_TRUE(merge.allowGaps);
  EXPECT_EQ(merge.tiles, std::vector<std::string>{"t.png"});
  GradeOptions grade = std::get<GradeOptions>(parseOptions({"grade", "r", "s", "--output=o", "--max-bias=2"}));
  EXPECT_EQ(grade.output, "o");
  EXPECT_EQ(grade.references, "r");
  DiffOptions diff = std::get<DiffOptions>(parseOptions({"diff", "--max-diff", "3", "a.png", "b.png"}));
  EXPECT_EQ(diff.comparison.thresholds.maxDiff, 3);
  EXPECT_EQ(diff.b, "b.png");
}
