// `conforma contact` outputs as a user sees them: plausibility warnings on stderr and in the JSON, the table's
// column names, the friction laws of --friction-law (and their errors), and the --fields export (CSV, NPY read back
// with numpy, folder checked before solving).
// test-links: app

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "conforma/wheel_contact_fields.hpp"

namespace {

using conforma::test::RunCli;
namespace fs = std::filesystem;

const std::string kTestbank = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/testbank/profiles/";

fs::path FreshFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("conforma_fields_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  return dir;
}

std::vector<std::string> WarningsOf(const nlohmann::json& wheel) {
  return wheel.at("warnings").get<std::vector<std::string>>();
}

// Issue 13 item 10: a wheel profile whose z origin is 35 mm off the taping line with the default --r0-mm 460
// (xi = -0.077, full slip) was solved without a word.
TEST(ContactCliOutputs, NominalRadiusWarningInJsonAndOnStderr) {
  const std::string args = "contact --wheel " + kTestbank + "worn_high_mileage.prw --rail 50E4";
  const auto json_run = RunCli(args + " --json");
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  const nlohmann::json j = nlohmann::json::parse(json_run.out);
  ASSERT_EQ(j["wheels"].size(), 2u);
  for (const nlohmann::json& w : j["wheels"]) {
    const std::vector<std::string> warnings = WarningsOf(w);
    ASSERT_EQ(warnings.size(), 1u) << w.dump(1);
    EXPECT_EQ(warnings[0].rfind("nominal_radius:", 0), 0u) << warnings[0];
    EXPECT_NE(warnings[0].find("495.3 mm is +35.3 mm from the nominal radius r0 = 460.0 mm"), std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[0].find("xi = -0.07"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("Shift the wheel profile's z by -35.3 mm"), std::string::npos) << warnings[0];
  }
  EXPECT_NE(json_run.err.find("warning: left wheel: nominal_radius:"), std::string::npos) << json_run.err;
  const auto text = RunCli(args);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.err.find("warning: right wheel: nominal_radius:"), std::string::npos) << text.err;
  EXPECT_NE(text.err.find("z origin is not at the taping line"), std::string::npos) << text.err;
  // --r0-mm does not remove it: the rolling radius is r0 + z_wheel, the offset is the profile's
  const auto other_r0 = RunCli(args + " --r0-mm 425 --json");
  ASSERT_EQ(other_r0.exit_code, 0) << other_r0.err;
  const nlohmann::json other_r0_json = nlohmann::json::parse(other_r0.out);
  ASSERT_EQ(other_r0_json.at("wheels").size(), 2u) << other_r0.out;
  for (const nlohmann::json& w : other_r0_json.at("wheels"))
    EXPECT_NE(WarningsOf(w).at(0).find("+35.3 mm from the nominal radius r0 = 425.0 mm"), std::string::npos);
  // the shift the warning names removes it, and with it the spurious full slip (issue 13 item 10)
  const auto shifted = RunCli(args + " --wheel-z-shift-mm -35.3 --json");
  ASSERT_EQ(shifted.exit_code, 0) << shifted.err;
  const nlohmann::json shifted_json = nlohmann::json::parse(shifted.out);
  ASSERT_EQ(shifted_json.at("wheels").size(), 2u) << shifted.out;
  for (const nlohmann::json& w : shifted_json.at("wheels")) {
    EXPECT_TRUE(WarningsOf(w).empty()) << w.dump(1);
    for (const nlohmann::json& p : w["patches"]) EXPECT_LT(std::fabs(p["xi"].get<double>()), 2e-3) << p.dump(1);
  }
  // a new wheel on the tread: no warning
  const auto s1002 = RunCli("contact --rail 50E4 --json");
  ASSERT_EQ(s1002.exit_code, 0) << s1002.err;
  const nlohmann::json s1002_json = nlohmann::json::parse(s1002.out);
  ASSERT_EQ(s1002_json.at("wheels").size(), 2u) << s1002.out;
  for (const nlohmann::json& w : s1002_json.at("wheels")) EXPECT_TRUE(WarningsOf(w).empty());
  EXPECT_EQ(s1002.err.find("warning"), std::string::npos) << s1002.err;
}

// Issue 13 item 11: mu = 5 was accepted without a warning.
TEST(ContactCliOutputs, FrictionOutsideRangeWarns) {
  const auto run = RunCli("contact --mu 5 --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json run_json = nlohmann::json::parse(run.out);
  ASSERT_EQ(run_json.at("wheels").size(), 2u) << run.out;
  for (const nlohmann::json& w : run_json.at("wheels")) {
    ASSERT_EQ(WarningsOf(w).size(), 1u) << w.dump(1);
    EXPECT_NE(WarningsOf(w)[0].find("friction_coefficient: the friction coefficient mu = 5 is outside"),
              std::string::npos);
  }
  EXPECT_NE(run.err.find("warning: left wheel: friction_coefficient"), std::string::npos) << run.err;
  const auto plain = RunCli("contact --mu 0.4");
  EXPECT_EQ(plain.err.find("warning"), std::string::npos) << plain.err;
}

// Issue 13 item 11: the table's `patch` column was the conformal flag.
TEST(ContactCliOutputs, TableColumnsSayWhatTheyAre) {
  const auto run = RunCli("contact --model kpec --y-mm 3");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::istringstream lines(run.out);
  std::string title, header, legend, row;
  std::getline(lines, title);
  std::getline(lines, header);
  std::getline(lines, legend);
  std::getline(lines, row);
  std::istringstream h(header), r(row);
  std::vector<std::string> columns, cells;
  for (std::string c; h >> c;) columns.push_back(c);
  for (std::string c; r >> c;) cells.push_back(c);
  ASSERT_GE(columns.size(), 3u) << header;
  EXPECT_EQ(columns[0], "wheel");
  EXPECT_EQ(columns[1], "model");
  EXPECT_EQ(columns[2], "conformal");
  EXPECT_EQ(header.find("patch"), std::string::npos) << header;
  ASSERT_EQ(cells.size(), columns.size()) << row;  // every row cell under its column, the flag spelled out
  EXPECT_EQ(cells[0], "left");
  EXPECT_EQ(cells[1], "kpec");
  EXPECT_TRUE(cells[2] == "yes" || cells[2] == "no") << row;
  EXPECT_NE(legend.find("conformal: alpha_c above the conformity threshold"), std::string::npos) << legend;
}

double FirstPatch(const std::string& json, const char* key) {
  return nlohmann::json::parse(json)["wheels"][0]["patches"][0][key].get<double>();
}

TEST(ContactCliOutputs, FrictionLawsFromTheCommandLine) {
  const std::string base = "contact --model kpec --side left --xi 0.02 --json";  // full slip
  const auto constant = RunCli(base + " --mu 0.3");
  ASSERT_EQ(constant.exit_code, 0) << constant.err;
  const double fn = FirstPatch(constant.out, "fn_N");
  EXPECT_NEAR(std::fabs(FirstPatch(constant.out, "fx_N")), 0.3 * fn, 0.02 * fn);
  const auto falling = RunCli(base + " --friction-law piecewise-linear --mu 0.3 --mu-dynamic 0.15 --critical-slip 0.001");
  ASSERT_EQ(falling.exit_code, 0) << falling.err;
  EXPECT_NEAR(std::fabs(FirstPatch(falling.out, "fx_N")), 0.15 * fn, 0.03 * fn);
  const auto paper_name = RunCli(base + " --friction-law f1b --mu 0.3 --mu-dynamic 0.15 --critical-slip 0.001");
  ASSERT_EQ(paper_name.exit_code, 0) << paper_name.err;
  EXPECT_EQ(FirstPatch(paper_name.out, "fx_N"), FirstPatch(falling.out, "fx_N"));
  for (const char* law : {"exponential --mu-ratio 0.5 --slip-decay 200",
                          "static-dynamic --slip-decay 200 --mu-dynamic 0.15 --slip-rise 50"}) {
    const auto run = RunCli(base + " --mu 0.3 --friction-law " + law);
    ASSERT_EQ(run.exit_code, 0) << law << "\n" << run.err;
    EXPECT_LT(std::fabs(FirstPatch(run.out, "fx_N")), 0.28 * fn) << law;
  }
  struct Bad {
    const char* args;
    const char* message;
  };
  for (const Bad& b : {Bad{"--friction-law foo", "option --friction-law: unknown law 'foo'"},
                       Bad{"--friction-law exponential --mu-ratio 0.5 --slip-decay 1 --mu-dynamic 0.1",
                           "option --mu-dynamic is not a parameter of --friction-law exponential"},
                       Bad{"--mu-dynamic 0.1", "option --mu-dynamic is not a parameter of --friction-law constant"},
                       Bad{"--friction-law piecewise-linear --mu-dynamic 0.1",
                           "--friction-law piecewise-linear needs --critical-slip"},
                       Bad{"--friction-law piecewise-linear --mu-dynamic 0.1 --critical-slip 0", "--critical-slip"},
                       Bad{"--friction-law exponential --mu-ratio 1.5 --slip-decay 1", "--mu-ratio must be in [0, 1]"},
                       Bad{"--friction-law static-dynamic --slip-decay -1 --mu-dynamic 0.1 --slip-rise 1",
                           "--slip-decay"}}) {
    const auto run = RunCli(std::string("contact ") + b.args);
    EXPECT_EQ(run.exit_code, 2) << b.args << "\n" << run.err;
    EXPECT_NE(run.err.find(b.message), std::string::npos) << b.args << "\n" << run.err;
  }
  // every command with the contact options has them
  for (const char* command : {"sweep"}) {
    const auto help = RunCli(std::string(command) + " --help");
    EXPECT_NE(help.out.find("--friction-law"), std::string::npos) << command;
  }
}

std::vector<std::vector<std::string>> ReadCsv(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(ContactCliOutputs, FieldsAsCsvPerWheelAndPatch) {
  const fs::path dir = FreshFolder("csv");
  const auto run = RunCli("contact --model kpec --y-mm 3 --json --fields " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  std::vector<std::string> columns;
  conforma::VisitCellFields(conforma::ContactCell{}, [&columns](const char* name, const auto&) { columns.push_back(name); });
  ASSERT_EQ(j["fields_files"].size(), j["wheels"][0]["patches"].size() + j["wheels"][1]["patches"].size());
  for (const nlohmann::json& w : j["wheels"]) {
    for (size_t p = 0; p < w["patches"].size(); ++p) {
      const nlohmann::json& patch = w["patches"][p];
      const fs::path file = dir / (w["side"].get<std::string>() + "_patch" + std::to_string(p) + ".csv");
      ASSERT_TRUE(fs::exists(file)) << file;
      const auto rows = ReadCsv(file);
      ASSERT_GT(rows.size(), 10u);
      EXPECT_EQ(rows[0], columns);  // the header names every column with its unit
      const auto col = [&columns](const char* name) {
        return static_cast<size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
      };
      double load = 0.0, power = 0.0, slip_area = 0.0;
      for (size_t r = 1; r < rows.size(); ++r) {
        ASSERT_EQ(rows[r].size(), columns.size());
        const double area = std::stod(rows[r][col("area_m2")]);
        load += std::stod(rows[r][col("pressure_Pa")]) * area;
        power += std::stod(rows[r][col("wear_index_Pa")]) * area * 2.0;  // V = --speed, default 2 m/s
        if (std::stod(rows[r][col("in_slip")]) == 1.0) slip_area += area;
      }
      // the field integrals equal the JSON's totals
      EXPECT_NEAR(power, patch["frictional_power_W"].get<double>(), 1e-9 * power);
      EXPECT_GT(power, 0.0);
      EXPECT_NEAR(slip_area, patch["slip_area_m2"].get<double>(), 1e-12 + 1e-9 * slip_area);
      EXPECT_NEAR(load, patch["fn_N"].get<double>(), 0.05 * patch["fn_N"].get<double>());
    }
  }
  fs::remove_all(dir);
}

TEST(ContactCliOutputs, FieldsAsNpyReadBackWithNumpy) {
  if (std::system("/usr/bin/python3 -c 'import numpy' 2>/dev/null") != 0) GTEST_SKIP() << "no numpy";
  const fs::path csv = FreshFolder("npy_csv"), npy = FreshFolder("npy");
  const std::string args = "contact --model conformal --y-mm 5 --side left --fields ";
  ASSERT_EQ(RunCli(args + csv.string()).exit_code, 0);
  const auto run = RunCli(args + npy.string() + " --fields-format npy");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path file = npy / "left_patch0.npy";
  ASSERT_TRUE(fs::exists(file));
  // numpy reads the header and the data; print the column names, the row count and every value
  const fs::path dump = npy / "dump.txt";
  const std::string script = "import numpy as np; a = np.load('" + file.string() +
                             "'); f = open('" + dump.string() +
                             "', 'w'); f.write(','.join(a.dtype.names) + '\\n'); f.write(str(a.shape[0]) + '\\n'); "
                             "[f.write(','.join(repr(float(v)) for v in row) + '\\n') for row in a.tolist()]";
  ASSERT_EQ(std::system(("/usr/bin/python3 -c \"" + script + "\"").c_str()), 0) << script;
  const auto from_numpy = ReadCsv(dump);
  const auto from_csv = ReadCsv(csv / "left_patch0.csv");
  ASSERT_EQ(from_numpy.size(), from_csv.size() + 1);
  EXPECT_EQ(from_numpy[0], from_csv[0]);  // the same column names
  EXPECT_EQ(std::stoul(from_numpy[1][0]), from_csv.size() - 1);
  for (size_t r = 1; r < from_csv.size(); ++r)
    for (size_t c = 0; c < from_csv[r].size(); ++c)
      ASSERT_EQ(std::stod(from_numpy[r + 1][c]), std::stod(from_csv[r][c])) << r << " " << c;
  fs::remove_all(csv);
  fs::remove_all(npy);
}

TEST(ContactCliOutputs, FieldsFolderCheckedBeforeSolving) {
  const fs::path blocker = FreshFolder("file");
  { std::ofstream(blocker.string()) << "a file, not a folder"; }
  for (const std::string& folder : {std::string("/proc/conforma_fields"), blocker.string(),
                                   (blocker / "sub").string()}) {
    const auto run = RunCli("contact --model conformal --fields " + folder);
    EXPECT_EQ(run.exit_code, 2) << folder << "\n" << run.err;
    EXPECT_NE(run.err.find("option --fields: cannot"), std::string::npos) << run.err;
    EXPECT_EQ(run.out.find("wheel"), std::string::npos) << "solved before the check:\n" << run.out;
  }
  const auto bad_format = RunCli("contact --fields /tmp --fields-format xls");
  EXPECT_NE(bad_format.exit_code, 0);
  fs::remove(blocker);
}

}  // namespace
