// The bash completion (doc/vkrt.bash-completion): each command's list of options is its table
// of options (host/cli/options.cpp), no more and no less; and, through bash-completion's own
// functions, what it offers for commands, options, option values and files. Without the
// bash-completion package the second test skips, saying so (it fails in CI).
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/option_rows.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::string kCompletion = std::string(VKRT_SOURCE_DIR) + "/doc/vkrt.bash-completion";
const std::string kBashCompletion = "/usr/share/bash-completion/bash_completion";

// The words of the shell variable `name="..."` in the completion file.
std::set<std::string> listed(const std::string& name) {
  const std::string text = readFile(kCompletion);
  const std::size_t at = text.find("local " + name + "=\"");
  if (at == std::string::npos) {
    ADD_FAILURE() << "no " << name << " in " << kCompletion;
    return {};
  }
  const std::size_t start = at + name.size() + 8, end = text.find('"', start);
  std::istringstream words(text.substr(start, end - start));
  std::set<std::string> out;
  for (std::string w; words >> w;) out.insert(w);
  return out;
}

// Every spelling of the rows of `rows` that --help or a paragraph names.
template <class Options>
std::set<std::string> documented(std::span<const OptionRow<Options>> rows, HelpSection only, bool onlyThat) {
  std::set<std::string> out;
  for (const OptionRow<Options>& row : rows) {
    if (!row.set || row.section == HelpSection::Hidden) continue;
    if (onlyThat != (row.section == only)) continue;
    std::string names(row.names);
    for (std::size_t at = 0; at < names.size();) {
      const std::size_t comma = std::min(names.find(", ", at), names.size());
      out.insert(names.substr(at, comma - at));
      at = comma + 2;
    }
  }
  return out;
}

template <class T>
std::set<T> joined(std::set<T> a, const std::set<T>& b) {
  a.insert(b.begin(), b.end());
  return a;
}

// What bash completes for the command line `line` (its last word being completed), in `dir`.
std::vector<std::string> complete(const std::string& dir, const std::string& line) {
  const std::string script = dir + "/complete.sh";
  writeFile(script,
            "source " + kBashCompletion + "\nsource " + kCompletion +
                "\nCOMP_LINE=\"$1\"; COMP_POINT=${#COMP_LINE}\nread -ra COMP_WORDS <<< \"$1\"\n"
                "[[ $1 == *' ' ]] && COMP_WORDS+=('')\nCOMP_CWORD=$((${#COMP_WORDS[@]} - 1))\n"
                "_vkrt vkrt \"${COMP_WORDS[COMP_CWORD]}\" \"${COMP_WORDS[COMP_CWORD-1]}\"\n"
                "printf '%s\\n' \"${COMPREPLY[@]}\" | sort\n");
  RunResult r = runCommand("cd '" + dir + "' && bash '" + script + "' '" + line + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::vector<std::string> out;
  std::istringstream lines(r.output);
  for (std::string l; std::getline(lines, l);)
    if (!l.empty()) out.push_back(l);
  return out;
}

bool has(const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); }

}  // namespace

TEST(Completion, EachCommandsOptionsAreItsTables) {
  const auto render = renderOptionRows();
  // The render command's rows: its own list, the comparison options' and view's.
  EXPECT_EQ(documented(render, HelpSection::Hidden, false),
            joined(joined(listed("render_options"), listed("comparison_options")), listed("view_options")));
  EXPECT_EQ(documented(render, HelpSection::Comparison, true), listed("comparison_options"));
  EXPECT_EQ(documented(render, HelpSection::View, true), listed("view_options"));
  EXPECT_EQ(documented(mergeOptionRows(), HelpSection::Hidden, false), listed("merge_options"));
  EXPECT_EQ(documented(convertOptionRows(), HelpSection::Hidden, false), listed("convert_options"));
  EXPECT_EQ(documented(gradeOptionRows(), HelpSection::Hidden, false), listed("grade_options"));
}

TEST(Completion, OffersCommandsOptionsValuesAndFiles) {
  if (!fileExists(kBashCompletion))
    VKRT_SKIP_UNLESS_CI("no bash-completion here (apt install bash-completion): the completion is not run");
  const std::string dir = freshDir("cli/completion");
  writeFile(dir + "/ball.test", "size 8 8\n");
  writeFile(dir + "/ref.png", "");
  writeFile(dir + "/notes.txt", "");
  runCommand("mkdir -p '" + dir + "/renders'");

  std::vector<std::string> c = complete(dir, "vkrt gr");
  EXPECT_EQ(c, std::vector<std::string>{"grade"});
  c = complete(dir, "vkrt ");
  for (const char* want : {"diff", "grade", "view", "ball.test", "renders"}) EXPECT_TRUE(has(c, want)) << want;
  EXPECT_FALSE(has(c, "ref.png"));
  EXPECT_FALSE(has(c, "notes.txt"));
  EXPECT_EQ(complete(dir, "vkrt --back"), std::vector<std::string>{"--backend"});
  EXPECT_EQ(complete(dir, "vkrt --backend "), (std::vector<std::string>{"cpu", "vulkan"}));
  EXPECT_EQ(complete(dir, "vkrt --estimator b"), std::vector<std::string>{"best"});
  EXPECT_EQ(complete(dir, "vkrt grade --thres"), std::vector<std::string>{"--thresholds"});
  EXPECT_EQ(complete(dir, "vkrt view --po"), std::vector<std::string>{"--port"});
  EXPECT_TRUE(complete(dir, "vkrt --po").empty()) << "--port is view's";
  EXPECT_EQ(complete(dir, "vkrt merge --allow"), std::vector<std::string>{"--allow-gaps"});
  c = complete(dir, "vkrt diff ");
  EXPECT_TRUE(has(c, "ref.png"));
  EXPECT_FALSE(has(c, "ball.test"));
  c = complete(dir, "vkrt --check ");
  EXPECT_TRUE(has(c, "ref.png"));
  EXPECT_FALSE(has(c, "notes.txt"));
  EXPECT_TRUE(complete(dir, "vkrt --spp ").empty());
}
