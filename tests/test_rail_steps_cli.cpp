// test-links: app
// `conforma wear` with rail steps (rail_step_output.hpp): a small run of the shipped rail-step scenario writes
// rail_steps.csv (one row per rail step, the area identity per side, validity) and rail_steps.md; a fixed rail
// writes none of them; the plots of every rail step; the plotting interpreter is checked before computing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using conforma::test::RunCli;

fs::path TempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("conforma_rail_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string Slurp(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void Replace(std::string* text, const std::string& from, const std::string& to) {
  const size_t at = text->find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text->replace(at, from.size(), to);
}

// scenarios/metro_rail_steps.yaml with the kinematic curving estimate (no Ceres), `rail_steps` rail steps of two
// wheel steps each (a run of seconds).
fs::path SmallScenario(const fs::path& dir, bool fixed) {
  std::string y = Slurp(fs::path(CONFORMA_SOURCE_DIR) / "scenarios" / "metro_rail_steps.yaml");
  Replace(&y, "provider: quasistatic", "provider: kinematic");
  Replace(&y, "tangent_phases: 4", "tangent_phases: 2");
  Replace(&y, "total_km: 6000", "total_km: 0");
  Replace(&y, "steps: 10              # upper bound", "steps: 2              # upper bound");
  Replace(&y, "steps: 10              # rail steps", "steps: 2              # rail steps");
  if (fixed) Replace(&y, "fixed: false", "fixed: true");
  const fs::path f = dir / "small.yaml";
  std::ofstream(f) << y;
  return f;
}

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
  return out;
}

TEST(RailStepsCli, WearWritesTheRailStepTableWithTheAreaIdentity) {
  const fs::path dir = TempDir("steps");
  const fs::path out = dir / "out";
  const auto r = RunCli("wear --scenario '" + SmallScenario(dir, false).string() + "' --model hertz --no-plot --out '" +
                        out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("rail step  2:"), std::string::npos) << r.out;
  std::ifstream csv(out / "rail_steps.csv");
  std::string line;
  std::vector<std::string> header;
  int rows = 0;
  while (std::getline(csv, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = Split(line);
    if (header.empty()) {
      header = cells;
      continue;
    }
    ASSERT_EQ(cells.size(), header.size()) << line;
    ++rows;
    auto value = [&](const std::string& column) {
      for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == column) return cells[i];
      ADD_FAILURE() << "no column " << column;
      return std::string();
    };
    EXPECT_EQ(value("new_rail"), std::to_string(rows));
    EXPECT_EQ(value("wheels_valid"), "1");
    for (const std::string side : {"left", "right"}) {
      EXPECT_EQ(value(side + "_status"), "updated");
      EXPECT_EQ(value(side + "_valid"), "1");
      EXPECT_GT(std::stod(value(side + "_removed_area_mm2")), 0.0);
      EXPECT_LT(std::stod(value(side + "_area_residual")), 1e-9) << side << " rail step " << rows;
      EXPECT_EQ(value(side + "_virtual_rails"), "2");
    }
  }
  EXPECT_EQ(rows, 2);
  EXPECT_TRUE(fs::exists(out / "rail_step_001_depth.csv"));
  EXPECT_TRUE(fs::exists(out / "rail_step_002_depth.csv"));
  EXPECT_TRUE(fs::exists(out / "rail_cumulative_depth.csv"));
  EXPECT_TRUE(fs::exists(out / "rail_left_002.prr"));
  const std::string md = Slurp(out / "rail_steps.md");
  EXPECT_NE(md.find("Identity holds in every rail step; every wheel and rail profile valid"), std::string::npos) << md;
  EXPECT_NE(md.find("plots not produced: --no-plot"), std::string::npos) << md;
  fs::remove_all(dir);
}

TEST(RailStepsCli, PlotsOfEveryRailStep) {
  const char* python = "/usr/bin/python3";
  if (std::system((std::string(python) + " -c 'import matplotlib, numpy' >/dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "no python3 with matplotlib and numpy";
  const fs::path dir = TempDir("plots");
  const fs::path out = dir / "out";
  const auto r = RunCli("wear --scenario '" + SmallScenario(dir, false).string() + "' --model hertz --python " +
                        python + " --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  for (const char* png : {"rail_step_001.png", "rail_step_002.png", "rail_evolution.png"}) {
    EXPECT_TRUE(fs::exists(out / png)) << png;
    EXPECT_GT(fs::file_size(out / png), 10000u) << png;
  }
  const std::string md = Slurp(out / "rail_steps.md");
  EXPECT_NE(md.find("![rail step 2](rail_step_002.png)"), std::string::npos) << md;
  EXPECT_NE(md.find("![rail evolution](rail_evolution.png)"), std::string::npos) << md;
  fs::remove_all(dir);
}

TEST(RailStepsCli, FixedRailWritesNoRailStepFiles) {
  const fs::path dir = TempDir("fixed");
  const fs::path out = dir / "out";
  // a fixed rail needs no plotting python: a bad --python is not even looked at
  const auto r = RunCli("wear --scenario '" + SmallScenario(dir, true).string() + "' --model hertz --steps 1 " +
                        "--python /nonexistent --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(out / "steps.csv"));
  EXPECT_FALSE(fs::exists(out / "rail_steps.csv"));
  EXPECT_FALSE(fs::exists(out / "rail_steps.md"));
  EXPECT_EQ(r.out.find("rail steps"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(RailStepsCli, PlotPythonCheckedBeforeComputing) {
  const fs::path dir = TempDir("python");
  const auto r = RunCli("wear --scenario '" + SmallScenario(dir, false).string() + "' --python /nonexistent --out '" +
                        (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--python"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "steps.csv"));
  fs::remove_all(dir);
}

}  // namespace
