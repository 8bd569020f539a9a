// `conforma dynamics` as a user sees it: a short run writes the time-history CSV with its columns and exits 0;
// --eig prints the modes and the critical speed; a run whose contact fails (a wheelset started 80 mm off centre,
// off its rail: no rigid equilibrium) exits non-zero with the status and the failure named, never silently.
// test-links: app

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace conforma
