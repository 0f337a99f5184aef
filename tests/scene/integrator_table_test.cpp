// The integrator table (host/scene/integrator_table.h) against the parser and the docs,
// walked row by row: each settings command, in a generated scene under each integrator,
// gives one warning naming its file and line when the integrator does not use it (and then
// keeps its default), and none when it does; doc/path-tracing.md, "Commands" says the same.
#include <algorithm>
#include <sstream>

#include <gtest/gtest.h>

#include "scene/integrator_table.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::string kFile = "settings.test";
constexpr int kIntegratorLine = 3;
constexpr int kSettingLine = 4;

// A line for each settings command that sets something other than its default, valid under
// every integrator that uses it (`lightstratify on` with the default `lightsamples 1`).
struct SettingExample {
  Command command;
  const char* arguments;
};
constexpr SettingExample kExamples[] = {
    {Command::QuadLight, "0 1 0  1 0 0  0 0 1  5 5 5"},
    {Command::Spp, "4"},
    {Command::Gamma, "2.2"},
    {Command::LightSamples, "4"},
    {Command::LightStratify, "on"},
    {Command::Brdf, "ggx"},
    {Command::Roughness, "0.3"},
    {Command::NextEventEstimation, "mis"},
    {Command::RussianRoulette, "on"},
    {Command::ImportanceSampling, "cosine"},
};

std::vector<Integrator> integrators() {
  std::vector<Integrator> all;
  for (std::size_t i = 0; i < kIntegratorCount; ++i) all.push_back(integratorAt(i));
  return all;
}

// The scene: `integrator` at line 3, the setting (when there is one) at line 4, then a sphere
// that takes the current material (where `brdf` and `roughness` land).
std::string sceneText(Integrator integrator, const SettingExample* setting) {
  std::string text = "size 8 6\ncamera 0 0 5 0 0 0 0 1 0 45\nintegrator " + std::string(nameOf(integrator)) + "\n";
  if (setting) text += std::string(nameOf(setting->command)) + " " + setting->arguments + "\n";
  return text + "sphere 0 0 -2 1\n";
}

// The cells of a Markdown table's row, split at each `|` that is not written `\|`.
std::vector<std::string> tableCells(const std::string& row) {
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '|' && row[i - 1] != '\\') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return cells;
}

std::string what(Integrator integrator, const SettingExample& setting) {
  return "'" + std::string(nameOf(setting.command)) + "' under " + std::string(nameOf(integrator));
}

}  // namespace

// Every settings command of the table has its example above, and every example is one.
TEST(IntegratorTable, EverySettingHasAnExample) {
  CommandSet examples = 0;
  for (const SettingExample& e : kExamples) examples |= commandSet({e.command});
  EXPECT_EQ(examples, kIntegratorSettings);
}

TEST(IntegratorTable, AnUnusedSettingIsAWarningAtItsFileAndLine) {
  int checked = 0;
  for (Integrator integrator : integrators()) {
    for (const SettingExample& setting : kExamples) {
      if (contains(integratorRow(integrator).uses, setting.command)) continue;
      SCOPED_TRACE(what(integrator, setting));
      ++checked;
      const ParsedScene parsed = parseSceneWithWarnings(sceneText(integrator, &setting), kFile);
      ASSERT_EQ(parsed.warnings.size(), 1u);
      const Diagnostic& warning = parsed.warnings[0];
      EXPECT_FALSE(warning.isError());
      EXPECT_EQ(warning.file, kFile);
      EXPECT_EQ(warning.line, kSettingLine);
      const std::string expected = kFile + ":" + std::to_string(kSettingLine) + ": warning: '" +
                                   std::string(nameOf(setting.command)) + "' ignored: integrator " +
                                   std::string(nameOf(integrator)) + " (line " + std::to_string(kIntegratorLine) +
                                   ") does not use it";
      EXPECT_EQ(warning.format().substr(0, expected.size()), expected);
    }
  }
  EXPECT_GT(checked, 0);
}

// What is ignored leaves the scene as if the line were not there.
TEST(IntegratorTable, AnUnusedSettingKeepsItsDefault) {
  int checked = 0;
  for (Integrator integrator : integrators()) {
    const SceneDesc without = parseScene(sceneText(integrator, nullptr), kFile);
    for (const SettingExample& setting : kExamples) {
      if (contains(integratorRow(integrator).uses, setting.command)) continue;
      SCOPED_TRACE(what(integrator, setting));
      ++checked;
      const SceneDesc with = parseScene(sceneText(integrator, &setting), kFile);
      EXPECT_EQ(with.path.spp, without.path.spp);
      EXPECT_EQ(with.path.gamma, without.path.gamma);
      EXPECT_EQ(with.path.lightSamples, without.path.lightSamples);
      EXPECT_EQ(with.path.lightStratify, without.path.lightStratify);
      EXPECT_EQ(with.path.nextEvent, without.path.nextEvent);
      EXPECT_EQ(with.path.russianRoulette, without.path.russianRoulette);
      EXPECT_EQ(with.path.sampling, without.path.sampling);
      EXPECT_EQ(with.materials, without.materials);
      EXPECT_EQ(with.triangles.size(), without.triangles.size());
      EXPECT_EQ(with.quadLights.size(), without.quadLights.size());
    }
  }
  EXPECT_GT(checked, 0);
}

// Parsed with --strict: a used setting gives no warning at all.
TEST(IntegratorTable, AUsedSettingGivesNoWarning) {
  int checked = 0;
  for (Integrator integrator : integrators()) {
    for (const SettingExample& setting : kExamples) {
      if (!contains(integratorRow(integrator).uses, setting.command)) continue;
      SCOPED_TRACE(what(integrator, setting));
      ++checked;
      ParsedScene parsed;
      EXPECT_NO_THROW(parsed = parseSceneWithWarnings(sceneText(integrator, &setting), kFile, ParseOptions{true}));
      EXPECT_TRUE(parsed.warnings.empty());
    }
  }
  EXPECT_GT(checked, 0);
}

// The "used by" column of doc/path-tracing.md, "Commands" names, for each settings command,
// the integrators whose row has it ("all three": the path integrators).
TEST(IntegratorTable, TheDocumentationSaysTheSame) {
  std::istringstream doc(readFile(sourcePath("doc/path-tracing.md")));
  int rows = 0;
  for (std::string line; std::getline(doc, line);) {
    for (const SettingExample& setting : kExamples) {
      const std::string start = "| `" + std::string(nameOf(setting.command)) + "` |";
      if (line.rfind(start, 0) != 0) continue;
      ++rows;
      const std::vector<std::string> cells = tableCells(line);
      ASSERT_GE(cells.size(), 4u) << line;
      const std::string& usedBy = cells[3];
      for (Integrator integrator : integrators()) {
        const bool path = integrator != Integrator::Raytracer;
        const bool named = usedBy.find("`" + std::string(nameOf(integrator)) + "`") != std::string::npos ||
                           (path && usedBy.find("all three") != std::string::npos);
        EXPECT_EQ(named, contains(integratorRow(integrator).uses, setting.command))
            << what(integrator, setting) << ": " << usedBy;
      }
    }
  }
  EXPECT_EQ(rows, static_cast<int>(std::size(kExamples)));
}
