// The tokenizer (host/scene/tokenizer.h): words split at blanks, comments, line numbers, the
// byte-order mark, the words a line keeps, and where a byte that is not text stops it.
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "scene/tokenizer.h"

namespace vkrt {
namespace {

struct Read {
  int number;
  std::vector<std::string> words;
  int count;
};

// Every line of `text` that holds words, until End or NotText; the final status in *status.
std::vector<Read> readAll(std::string_view text, Tokenizer::Status* status = nullptr, Tokenizer* out = nullptr) {
  Tokenizer local(text);
  Tokenizer& t = out ? *out : local;
  std::vector<Read> lines;
  TokenLine line;
  Tokenizer::Status s;
  while ((s = t.next(line)) == Tokenizer::Status::Line) {
    Read r{line.number, {}, line.count};
    for (int i = 0; i < std::min(line.count, TokenLine::kMaxWords); ++i) r.words.emplace_back(line.words[i]);
    lines.push_back(r);
  }
  if (status) *status = s;
  return lines;
}

using Words = std::vector<std::string>;

TEST(Tokenizer, SplitsAtEveryKindOfBlank) {
  const auto lines = readAll("  size\t640 \v480\f\r\n");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].number, 1);
  EXPECT_EQ(lines[0].count, 3);
  EXPECT_EQ(lines[0].words, (Words{"size", "640", "480"}));
}

TEST(Tokenizer, CommentsRunToTheEndOfTheLine) {
  const auto lines = readAll("# a whole line\nsphere 0 0 0 1 # the rest # and more\nfoo#bar baz\n");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].number, 2);
  EXPECT_EQ(lines[0].words, (Words{"sphere", "0", "0", "0", "1"}));
  // `#` ends a word without a blank before it.
  EXPECT_EQ(lines[1].number, 3);
  EXPECT_EQ(lines[1].words, (Words{"foo"}));
}

TEST(Tokenizer, EmptyLinesAreCountedButNotGiven) {
  Tokenizer t("\n\n   \n\t# c\nmaxdepth 3\n\n\nfoo");
  const auto lines = readAll("", nullptr, &t);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].number, 5);
  EXPECT_EQ(lines[1].number, 8);
  EXPECT_EQ(lines[1].words, (Words{"foo"}));
  EXPECT_EQ(t.lineNumber(), 8);
}

TEST(Tokenizer, LineNumberAtTheEndIsTheNumberOfLines) {
  for (const auto& [text, n] : std::vector<std::pair<std::string, int>>{
           {"", 0}, {"a", 1}, {"a\n", 1}, {"a\nb", 2}, {"\n\n\n", 3}, {"a\n\n", 2}}) {
    Tokenizer t(text);
    EXPECT_EQ(t.lineNumber(), 0);
    Tokenizer::Status s;
    readAll("", &s, &t);
    EXPECT_EQ(s, Tokenizer::Status::End) << text;
    EXPECT_EQ(t.lineNumber(), n) << "text '" << text << "'";
  }
}

TEST(Tokenizer, SkipsAByteOrderMarkOnlyAtTheStart) {
  auto lines = readAll("\xEF\xBB\xBFsize 1 1\n");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].words, (Words{"size", "1", "1"}));
  // Elsewhere its bytes are an ordinary word's (bytes >= 0x80 are text).
  lines = readAll("size 1 1\n\xEF\xBB\xBFmaxdepth 2\n");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1].words[0], "\xEF\xBB\xBFmaxdepth");
  // Part of a mark is not skipped.
  lines = readAll("\xEF\xBBsize");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].words[0], "\xEF\xBBsize");
}

TEST(Tokenizer, KeepsTheFirstWordsAndCountsThemAll) {
  std::string text = "vertex";
  const int args = 40;
  for (int i = 0; i < args; ++i) text += " " + std::to_string(i);
  const auto lines = readAll(text);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].count, args + 1);
  ASSERT_EQ(lines[0].words.size(), static_cast<std::size_t>(TokenLine::kMaxWords));
  EXPECT_GE(TokenLine::kMaxWords, kMaxArgs + 1);   // a command and quadLight's 12 arguments
  EXPECT_EQ(lines[0].words[0], "vertex");
  for (int i = 1; i < TokenLine::kMaxWords; ++i) EXPECT_EQ(lines[0].words[i], std::to_string(i - 1));
}

TEST(Tokenizer, WordsViewTheText) {
  const std::string text = "camera 0 0 5";
  Tokenizer t(text);
  TokenLine line;
  ASSERT_EQ(t.next(line), Tokenizer::Status::Line);
  EXPECT_EQ(line.command(), "camera");
  EXPECT_EQ(line.command().data(), text.data());
  EXPECT_EQ(line.words[3].data(), text.data() + 11);
}

TEST(Tokenizer, StopsAtAControlByteAndSaysWhere) {
  Tokenizer t("size 1 1\nab\x01 cd\nmaxdepth 2\n");
  TokenLine line;
  ASSERT_EQ(t.next(line), Tokenizer::Status::Line);
  ASSERT_EQ(t.next(line), Tokenizer::Status::NotText);
  EXPECT_EQ(t.lineNumber(), 2);
  EXPECT_EQ(t.notTextMessage(), "file is not text (byte 0x01 in column 3); expected a CSE167 scene file");
}

TEST(Tokenizer, EveryByteHasTheClassTheFormatGivesIt) {
  for (int c = 0; c < 256; ++c) {
    const char ch = static_cast<char>(c);
    const bool blank = c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
    const bool binary = !blank && (c < 0x20 || c == 0x7F) && c != '\n';
    if (c == '\n') continue;   // lines are split before bytes are classed
    EXPECT_EQ(isTextByte(ch), !binary) << "byte " << c;
    if (blank) {
      EXPECT_EQ(byteClass(ch), kBlank) << "byte " << c;
    }
    // A byte that is text and no blank or '#' is part of a word: it makes one on its own.
    if (!binary && !blank && c != '#') {
      const auto lines = readAll(std::string("x") + ch + "y z");
      ASSERT_EQ(lines.size(), 1u) << "byte " << c;
      EXPECT_EQ(lines[0].count, 2) << "byte " << c;
    }
  }
}

TEST(Tokenizer, NulAndDelAreNotTextEvenInAComment) {
  using namespace std::string_literals;
  for (const std::string& s : {"# comment \x7F here"s, "size 1 1 # \0"s, "size 1 1 # \0\nmaxdepth 2"s}) {
    Tokenizer t(s);
    TokenLine line;
    EXPECT_EQ(t.next(line), Tokenizer::Status::NotText) << s;
    EXPECT_EQ(t.lineNumber(), 1);
  }
  Tokenizer t(std::string_view("\0", 1));
  TokenLine line;
  ASSERT_EQ(t.next(line), Tokenizer::Status::NotText);
  EXPECT_EQ(t.notTextMessage(), "file is not text (byte 0x00 in column 1); expected a CSE167 scene file");
}

TEST(Tokenizer, EqualIgnoringCaseFoldsOnlyAsciiLetters) {
  EXPECT_TRUE(equalIgnoringCase("maxDepth", "MAXDEPTH"));
  EXPECT_TRUE(equalIgnoringCase("MIS", "mis"));
  EXPECT_TRUE(equalIgnoringCase("", ""));
  EXPECT_FALSE(equalIgnoringCase("mis", "mi"));
  EXPECT_FALSE(equalIgnoringCase("ab", "ac"));
  // '@' and '`' sit next to 'A' and 'a', '[' and '{' next to 'Z' and 'z': none is a letter.
  EXPECT_FALSE(equalIgnoringCase("@", "`"));
  EXPECT_FALSE(equalIgnoringCase("[", "{"));
  // Bytes beyond ASCII are compared as they are.
  EXPECT_FALSE(equalIgnoringCase("\xC3\xA9", "\xC3\x89"));
}

}  // namespace
}  // namespace vkrt
