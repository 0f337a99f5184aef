// The diagnostic log (host/scene/diagnostic_log.h): the verdict of close(), line order, the
// limit per warning kind and its summary, --strict, the error limit and onlyError().
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/diagnostic_log.h"

namespace vkrt {
namespace {

// close()'s diagnostics, whether it returned them or threw them.
std::vector<Diagnostic> closeCatching(DiagnosticLog& log, bool* threw) {
  try {
    auto d = log.close();
    *threw = false;
    return d;
  } catch (const SceneError& e) {
    *threw = true;
    return e.diagnostics();
  }
}

TEST(DiagnosticLog, AnEmptyLogClosesWithNothing) {
  DiagnosticLog log("a.test", false);
  EXPECT_FALSE(log.full());
  EXPECT_TRUE(log.close().empty());
}

TEST(DiagnosticLog, WarningsAloneAreReturnedInLineOrder) {
  DiagnosticLog log("a.test", false);
  log.warn(7, WarningKind::UnknownCommand, "seven");
  log.warn(2, WarningKind::Repeated, "two");
  log.warn(7, WarningKind::ExtraArguments, "seven again");
  log.warn(0, WarningKind::NoLights, "the file");
  const auto d = log.close();
  ASSERT_EQ(d.size(), 4u);
  const std::vector<std::pair<int, std::string>> expected = {{0, "the file"}, {2, "two"}, {7, "seven"}, {7, "seven again"}};
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_EQ(d[i].line, expected[i].first);
    EXPECT_EQ(d[i].message, expected[i].second);   // same line: the order found
    EXPECT_EQ(d[i].file, "a.test");
    EXPECT_FALSE(d[i].isError());
  }
  EXPECT_EQ(d[0].format(), "a.test: warning: the file");
  EXPECT_EQ(d[1].format(), "a.test:2: warning: two");
}

TEST(DiagnosticLog, OneErrorThrowsEveryDiagnostic) {
  DiagnosticLog log("b.test", false);
  log.warn(3, WarningKind::KeywordCase, "w");
  log.error(1, "e");
  try {
    log.close();
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    ASSERT_EQ(e.diagnostics().size(), 2u);
    EXPECT_TRUE(e.diagnostics()[0].isError());
    EXPECT_EQ(e.diagnostics()[0].line, 1);
    EXPECT_FALSE(e.diagnostics()[1].isError());
    EXPECT_STREQ(e.what(), "b.test:1: error: e\nb.test:3: warning: w");
  }
}

TEST(DiagnosticLog, PastThreeOfAKindTheRestAreSummarisedAtTheFirstLineLeftOut) {
  DiagnosticLog log("c.test", false);
  const int lines[] = {10, 11, 12, 15, 20, 31};
  for (int line : lines) log.warn(line, WarningKind::UnknownCommand, "unknown " + std::to_string(line));
  log.warn(13, WarningKind::Repeated, "repeated");   // another kind: not counted with them
  const auto d = log.close();
  ASSERT_EQ(d.size(), static_cast<std::size_t>(kMaxWarningsPerKind) + 2);
  EXPECT_EQ(d[0].message, "unknown 10");
  EXPECT_EQ(d[1].message, "unknown 11");
  EXPECT_EQ(d[2].message, "unknown 12");
  EXPECT_EQ(d[3].message, "repeated");
  EXPECT_EQ(d[4].line, 15);
  EXPECT_EQ(d[4].message, "... and 3 more of this kind (unknown commands), on lines 15 to 31");
  EXPECT_FALSE(d[4].isError());
}

TEST(DiagnosticLog, OneMoreIsSummarisedOnItsLine) {
  DiagnosticLog log("c.test", false);
  for (int line = 1; line <= kMaxWarningsPerKind + 1; ++line) log.warn(line, WarningKind::Clamped, "c");
  const auto d = log.close();
  ASSERT_EQ(d.size(), static_cast<std::size_t>(kMaxWarningsPerKind) + 1);
  EXPECT_EQ(d.back().message, "... and 1 more of this kind (values clamped), on line 4");
}

TEST(DiagnosticLog, EachKindHasItsOwnName) {
  std::set<std::string> summaries;
  for (int k = 0; k < static_cast<int>(WarningKind::Count); ++k) {
    DiagnosticLog log("d.test", false);
    for (int line = 1; line <= kMaxWarningsPerKind + 1; ++line) log.warn(line, static_cast<WarningKind>(k), "w");
    const auto d = log.close();
    ASSERT_EQ(d.size(), static_cast<std::size_t>(kMaxWarningsPerKind) + 1) << "kind " << k;
    EXPECT_EQ(d.back().message.rfind("... and 1 more of this kind (", 0), 0u) << d.back().message;
    summaries.insert(d.back().message);
  }
  EXPECT_EQ(summaries.size(), static_cast<std::size_t>(WarningKind::Count));
}

TEST(DiagnosticLog, StrictMakesEveryWarningAnError) {
  DiagnosticLog log("e.test", true);
  for (int line = 1; line <= 5; ++line) log.warn(line, WarningKind::BeforeSize, "early");
  bool threw = false;
  const auto d = closeCatching(log, &threw);
  EXPECT_TRUE(threw);
  ASSERT_EQ(d.size(), static_cast<std::size_t>(kMaxWarningsPerKind) + 1);
  for (const auto& x : d) {
    EXPECT_TRUE(x.isError()) << x.message;
    EXPECT_NE(x.message.find(" [--strict]"), std::string::npos) << x.message;
  }
  EXPECT_EQ(d[0].message, "early [--strict]");
  EXPECT_EQ(d.back().message, "... and 2 more of this kind (commands before 'size'), on lines 4 to 5 [--strict]");
}

TEST(DiagnosticLog, TakesNoMoreAfterFiftyErrors) {
  DiagnosticLog log("f.test", false);
  int line = 0;
  while (!log.full()) {
    ASSERT_LT(line, 1000) << "never full";
    ++line;
    log.error(line, "e" + std::to_string(line));
  }
  EXPECT_EQ(line, 50);
  log.error(++line, "one too many");
  bool threw = false;
  const auto d = closeCatching(log, &threw);
  EXPECT_TRUE(threw);
  ASSERT_EQ(d.size(), 51u);
  EXPECT_EQ(d[49].message, "e50");
  EXPECT_EQ(d[50].line, 50);
  EXPECT_EQ(d[50].message, "too many errors; stopping here");
}

TEST(DiagnosticLog, OnlyErrorReplacesEverythingFoundBefore) {
  DiagnosticLog log("g.test", false);
  for (int line = 1; line <= 10; ++line) log.warn(line, WarningKind::UnknownCommand, "u");
  log.error(4, "e");
  log.onlyError(12, "file is not text");
  bool threw = false;
  const auto d = closeCatching(log, &threw);
  EXPECT_TRUE(threw);
  ASSERT_EQ(d.size(), 1u);   // no summary of the warnings either
  EXPECT_EQ(d[0].line, 12);
  EXPECT_EQ(d[0].message, "file is not text");
}

TEST(DiagnosticLog, OnlyErrorEvenWhenTheLogWasFull) {
  DiagnosticLog log("h.test", false);
  for (int line = 1; !log.full(); ++line) log.error(line, "e");
  log.onlyError(70, "file is not text");
  bool threw = false;
  const auto d = closeCatching(log, &threw);
  EXPECT_TRUE(threw);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].line, 70);
}

}  // namespace
}  // namespace vkrt
