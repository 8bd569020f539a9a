// `conforma dynamics` as a user sees it: a short run writes the time-history CSV with its columns and exits 0;
// --eig prints the modes and the critical speed; a run whose contact fails (a wheelset started 80 mm off centre,
// off its rail: no rigid equilibrium) exits non-zero with the status and the failure named, never silently.
// test-links: app

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_run.hpp"

namespace conforma {
namespace {

const std::string kScenario = std::string(CONFORMA_SOURCE_DIR) + "/scenarios/default_metro.yaml";

TEST(VehicleDynamicsCli, ShortRunWritesTheHistory) {
  const std::string csv = ::testing::TempDir() + "dynamics_cli.csv";
  const test::CliRun r = test::RunCli("dynamics --scenario " + kScenario +
                                      " --bogies 1 --model hertz --speed-kmh 40 --duration 0.1 --output-interval 0.02"
                                      " --out " + csv);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("dynamics: completed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("simulated s per wall s"), std::string::npos);
  std::ifstream f(csv);
  std::string header, line;
  ASSERT_TRUE(std::getline(f, header));
  for (const char* column : {"t_s", "s_m", "ws0_y_mm", "ws1_psi_mrad", "bogie0_y_mm", "ws0R_YQ", "ws1L_Tgamma_N"})
    EXPECT_NE(header.find(column), std::string::npos) << column;
  int rows = 0;
  while (std::getline(f, line)) ++rows;
  EXPECT_EQ(rows, 6);  // t = 0, 0.02, ..., 0.1
}

TEST(VehicleDynamicsCli, IrregularityFileDrivesALinearRun) {
  const std::string irr = ::testing::TempDir() + "dynamics_irregularity.csv";
  {
    std::ofstream f(irr);
    f << "s_m,alignment_m,cross_level_rad\n";
    for (int i = -100; i <= 200; ++i) f << 0.25 * i << "," << 2e-3 * std::sin(0.1 * i) << ",0\n";
  }
  const std::string csv = ::testing::TempDir() + "dynamics_irregularity_out.csv";
  const test::CliRun r = test::RunCli("dynamics --scenario " + kScenario + " --bogies 1 --linear --speed-kmh 36" +
                                      " --duration 3 --offset-mm 0 --irregularity " + irr + " --out " + csv);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  // the wheelsets move although they start centred: the alignment drives them
  std::ifstream f(csv);
  std::string header, line;
  std::getline(f, header);
  double max_y = 0.0;
  while (std::getline(f, line)) {
    std::stringstream ss(line);
    std::string t, s, y;
    std::getline(ss, t, ',');
    std::getline(ss, s, ',');
    std::getline(ss, y, ',');
    max_y = std::max(max_y, std::fabs(std::stod(y)));
  }
  EXPECT_GT(max_y, 0.5);
  EXPECT_LT(max_y, 5.0);
  // a file that does not cover the run is an input error (exit 2)
  {
    std::ofstream g(irr);
    g << "s_m,alignment_m\n0,0\n1,0\n3,0\n";
  }
  const test::CliRun bad = test::RunCli("dynamics --scenario " + kScenario + " --bogies 1 --linear --duration 0.1" +
                                        " --irregularity " + irr);
  EXPECT_EQ(bad.exit_code, 2) << bad.out << bad.err;
  EXPECT_NE(bad.err.find("the run needs"), std::string::npos) << bad.err;
}

TEST(VehicleDynamicsCli, EigenvaluesAndCriticalSpeed) {
  const test::CliRun r = test::RunCli("dynamics --scenario " + kScenario + " --bogies 1 --eig --speed-kmh 60");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("eigenvalues at 60.0 km/h"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("critical speed"), std::string::npos) << r.out;
}

TEST(VehicleDynamicsCli, ContactFailureIsNotSilent) {
  const test::CliRun r = test::RunCli("dynamics --scenario " + kScenario +
                                      " --bogies 1 --model hertz --speed-kmh 40 --duration 0.1 --offset-mm 80");
  EXPECT_NE(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("contact_failed"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("wheelset"), std::string::npos) << r.err;
}

// --max-steps-per-s: a run over its running step budget stops with step_limit, exits non-zero and says why; a
// negative budget is an input error naming the option.
TEST(VehicleDynamicsCli, RunningStepBudgetStopsTheRunAndSaysSo) {
  const std::string base = "dynamics --scenario " + kScenario + " --bogies 1 --model hertz --speed-kmh 40 --duration 0.1";
  const test::CliRun r = test::RunCli(base + " --max-steps-per-s 10");  // 10 (t + 1 s): about 11 step attempts
  EXPECT_NE(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("dynamics: step_limit"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("step budget exceeded"), std::string::npos) << r.err;
  const test::CliRun bad = test::RunCli(base + " --max-steps-per-s -1");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--max-steps-per-s"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace conforma
