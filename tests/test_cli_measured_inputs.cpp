// test-links: app
// Measured data the executable reads (session 26, the leftovers of session 25's fuzzing): the rig's adhesion table
// and wear plan and the measured wheel dimensions of `validate`. A value no measurement can have (an adhesion
// coefficient of 43, 7e9 rpm, a flange thickness of 0.03 mm) is an input error naming the file, line and the likely
// unit mistake; a test number given twice is refused; and a fit with more parameters than measured numbers is not
// passed off as a result (exit 4 after the report, which lists it).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using conforma::test::RunCli;

const std::string kSource = CONFORMA_SOURCE_DIR;

void ExpectInputError(const std::string& args, const std::string& named) {
  const auto r = RunCli(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
}

// Table 6 with its rows replaced: the header and the given rows.
fs::path AdhesionTable(const fs::path& dir, const std::string& name, const std::string& rows) {
  const fs::path file = dir / name;
  std::ofstream f(file);
  f << "test,reference_speed_rpm,wheel_load_kg,max_adhesion,steady_adhesion,initial_slope_N,condition\n" << rows;
  return file;
}

TEST(CliMeasuredInputs, AdhesionTableValuesBeyondAMeasurementAreNamed) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_measured", "adhesion");
  const std::string run = "rig-adhesion --no-sensitivity --variants none --out '" + (dir / "out").string() + "' --table ";
  const std::string good = "1,1000,37,0.441,0.353,8700,dry\n2,1000,37,0.220,0.212,8380,wet\n";
  ExpectInputError(run + "'" + AdhesionTable(dir, "percent.csv", good + "3,700,37,43.5,34.2,7960,dry\n").string() + "'",
                   "percent.csv:4: max_adhesion 43.5 is not a wheel-rail adhesion coefficient");
  ExpectInputError(run + "'" + AdhesionTable(dir, "rpm.csv", good + "3,7e9,37,0.435,0.342,7960,dry\n").string() + "'",
                   "reference_speed_rpm 7e9 is beyond a roller rig's");
  ExpectInputError(run + "'" + AdhesionTable(dir, "twice.csv", good + "1,700,37,0.435,0.342,7960,dry\n").string() + "'",
                   "test 1 is given twice");
  ExpectInputError(run + "'" + AdhesionTable(dir, "half.csv", good + "3.5,700,37,0.435,0.342,7960,dry\n").string() + "'",
                   "test number '3.5'");
  fs::remove_all(dir);
}

// One test per condition: 2 measured numbers for the 3 parameters of the per-condition law. The fit "converges" on
// any of its optima; the command says so and exits 4 (not converged / no result), the report listing both laws.
TEST(CliMeasuredInputs, UnderdeterminedAdhesionFitIsNotAResult) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_measured", "underdetermined");
  const fs::path table = AdhesionTable(dir, "one.csv", "1,1000,37,0.441,0.353,8700,dry\n2,1000,37,0.220,0.212,8380,wet\n");
  const auto r = RunCli("rig-adhesion --no-sensitivity --variants none --out '" + (dir / "out").string() + "' --table '" +
                        table.string() + "'");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("3 parameters for 2 measured numbers"), std::string::npos) << r.err;
  std::ifstream report(dir / "out" / "report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## Fits without a result"), std::string::npos);
  EXPECT_NE(text.find("section 2.1, dry law: 3 parameters for 2 measured numbers"), std::string::npos);
  EXPECT_NE(text.find("section 2.1, wet law"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliMeasuredInputs, RigPlanBeyondARigIsRefused) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_measured", "plan");
  std::ifstream in(kSource + "/scenarios/roller_rig_1to5.yaml");
  const std::string base((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto with = [&](const std::string& name, const std::string& from, const std::string& to) {
    std::string text = base;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    const fs::path file = dir / name;
    std::ofstream(file) << text;
    return "rig run --max-tests 1 --out '" + (dir / "out").string() + "' --scenario '" + file.string() + "'";
  };
  ExpectInputError(with("rpm.yaml", "reference_speed_rpm: 500, wheel_load_kg: 53", "reference_speed_rpm: 1.0e9, "
                                                                                     "wheel_load_kg: 53"),
                   "reference_speed_rpm 1e+09 is beyond a roller rig's");
  ExpectInputError(with("load.yaml", "wheel_load_kg: 53", "wheel_load_kg: 5.3e7"), "wheel_load_kg 5.3e+07");
  ExpectInputError(with("twice.yaml", "{test: 2,", "{test: 1,"), "test 1 is planned twice");
  fs::remove_all(dir);
}

TEST(CliMeasuredInputs, MeasuredDimensionsInAnotherUnitAreNamed) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_measured", "dimensions");
  const fs::path metres = dir / "metres.csv";
  std::ofstream(metres) << "km,QR_mm,FH_mm,FT_mm\n0,0.0108,0.028,0.0325\n1426,0.0098,0.0282,0.0315\n";
  ExpectInputError("validate --scenario '" + kSource + "/scenarios/aosta_aln501.yaml' --measured '" + metres.string() +
                       "'",
                   "metres.csv:2: column 'FT_mm' = 0.0325: implausible for Sd in mm");
  fs::remove_all(dir);
}

// rig replay writes each row's measured time as read (a replay of 1 MHz data at t ~ 1000 s kept 6 decimals before).
TEST(CliMeasuredInputs, RigReplayKeepsTheMeasuredTime) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_measured", "replay");
  const fs::path input = dir / "run.csv";
  std::ofstream(input) << "t_s,y_m,yaw_rad,omega1_rad_s,omega2_rad_s,load_left_N,load_right_N\n"
                          "1000.0000005,0,0,52.3599,49.8665,490.5,490.5\n1000.0000015,0,0,52.3599,49.8665,490.5,490.5\n";
  const auto r = RunCli("rig replay --scenario '" + kSource + "/scenarios/roller_rig_1to5.yaml' --input '" +
                        input.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::ifstream csv(dir / "out" / "rig_replay.csv");
  std::string header, first, second;
  std::getline(csv, header);
  std::getline(csv, first);
  std::getline(csv, second);
  EXPECT_EQ(first.substr(0, first.find(',')), "1000.0000005") << first;
  // the step: the time to the next row, as the difference of the two doubles
  EXPECT_NEAR(std::stod(first.substr(first.find(',') + 1)), 1e-6, 1e-12) << first;
  EXPECT_EQ(second.substr(0, second.find(',')), "1000.0000015") << second;
  fs::remove_all(dir);
}

}  // namespace
