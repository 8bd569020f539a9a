// test-links: app
// Honest exit codes and statuses of the executable (issue 13, items 1, 2, 6, 7, 8, 11): a non-converged or partial
// result is visible in the output and exits 4 / 5 (0 with --allow-partial); a user mistake is an input error (2)
// naming the option, found before computing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
using conforma::test::Slurp;

const std::string kLostContacts = std::string(CONFORMA_SOURCE_DIR) + "/tests/data/lost_contacts/lost_contacts.yaml";

// A fresh temporary folder per test.
fs::path TempDir(const std::string& name) { return conforma::test::FreshTempDir("conforma_status", name); }

// The lost-contacts scenario with one line replaced (S1002 wheel: a fresh profile).
fs::path ScenarioVariant(const fs::path& dir, const std::string& from, const std::string& to) {
  std::string text = Slurp(kLostContacts);
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const std::string wheel = "wheel: worn_conformal_step6.prw";
  text.replace(text.find(wheel), wheel.size(), "wheel: S1002");
  const fs::path f = dir / "scenario.yaml";
  std::ofstream(f) << text;
  return f;
}

// Item 1: the load control of the right wheel cannot carry the load: S1002 pressed against the 60E1 flange at a
// contact angle of 62 deg with full lateral slip down the flange at mu = 0.6 (mu tan(delta) = 1.12 > 1): the creep
// force pulls the wheel down more than the pressure lifts it, so no push-down carries the load (Nadal's limit
// passed; docs/physics-reference.md §3.6.1). Physical, so independent of a model's weak spots.
TEST(CliStatus, ContactNotConvergedIsShownAndExits4) {
  const std::string args =
      "contact --model conformal --wheel S1002 --rail 60E1 --side right --y-mm -7 --load-N 60000 --mu 0.6 --xi 0 "
      "--eta 0.05 --phi-per-m 0";
  const auto r = RunCli(args);
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  EXPECT_NE(r.out.find("right wheel: status not_converged"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("of the prescribed 60.0 kN"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("did not converge"), std::string::npos) << r.err;
  const auto j = RunCli(args + " --json");
  EXPECT_EQ(j.exit_code, 4);
  EXPECT_NE(j.out.find("not_converged"), std::string::npos);
  EXPECT_EQ(RunCli("--allow-partial " + args).exit_code, 0);
}

// Item 1 in `sweep` (kinematic creepages): a non-converged wheel in a one-point sweep is shown in the text and CSV
// and exits 4: conformal on a worn wheel at 163.1 kN, y = 3.8 mm (98.8 % of the load after 86 evaluations; the former
// cases converge since issue 15's KP fixes: y = 9.25 mm since the lobe fixes, 8.9 mm since KPEC's wells, §3.3).
TEST(CliStatus, SweepNotConvergedIsShownAndExits4) {
  const std::string args = "sweep --models conformal --side right --wheel '" +
                           conforma::test::SharedData("profiles/contact/testbank/profiles/Car7358_0001r.whl") +
                           "' --rail 50E4 --from-mm 3.8 --to-mm 3.8 --yaw-per-y " + std::to_string(-11.248 / 9.25) +
                           " --load-N 163143.77 --mu 0.254";
  const auto r = RunCli(args);
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  EXPECT_NE(r.out.find("right wheel: status not_converged"), std::string::npos) << r.out;
  const auto c = RunCli(args + " --csv");
  EXPECT_EQ(c.exit_code, 4) << c.err;
  EXPECT_NE(c.out.find(",wheel_status\n"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find(",not_converged\n"), std::string::npos) << c.out;
  EXPECT_EQ(RunCli(args + " --allow-partial").exit_code, 0);
}

// Item 2: a wear run whose wear distribution lost contacts says so (stdout, steps.csv) and exits 5.
TEST(CliStatus, WearWithLostContactsIsPartial) {
  const fs::path out = TempDir("wear_lost");
  const auto r = RunCli("wear --scenario '" + kLostContacts + "' --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 5) << r.out << r.err;
  // steps.csv: failed_contacts of step 1. How many of the 16 miss a 1e-16 tolerance is round-off luck (4 before
  // session 16's round-off changes, 6 after); what is asserted is that some fail and every output gives the same count.
  std::ifstream steps(out / "steps.csv");
  std::string header, row0, row1;
  std::getline(steps, header);
  std::getline(steps, row0);
  std::getline(steps, row1);
  std::vector<std::string> names, cells;
  for (std::stringstream h(header); h.good();) names.emplace_back(), std::getline(h, names.back(), ',');
  for (std::stringstream c(row1); c.good();) cells.emplace_back(), std::getline(c, cells.back(), ',');
  const auto col = std::find(names.begin(), names.end(), "failed_contacts") - names.begin();
  ASSERT_LT(static_cast<size_t>(col), cells.size());
  const int failed = std::stoi(cells[col]);
  EXPECT_GE(failed, 1);
  EXPECT_LE(failed, 16);
  const std::string n = std::to_string(failed);
  EXPECT_NE(r.out.find("WARNING: [conformal] step 1: " + n + " of 16 wheel contacts FAILED"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find(n + " wheel contact(s) failed"), std::string::npos) << r.err;
  // item 11: the wear rate column is in mm per km, and its header says so
  const std::string wear = Slurp(out / "wear_step_001.csv");
  EXPECT_EQ(wear.find("m per m travelled"), std::string::npos);
  EXPECT_NE(wear.find("mm of depth per km travelled"), std::string::npos);
  EXPECT_EQ(RunCli("--allow-partial wear --scenario '" + kLostContacts + "' --out '" + out.string() + "'").exit_code, 0);
  fs::remove_all(out);
}

TEST(CliStatus, CompareReportShowsLostContacts) {
  const fs::path out = TempDir("compare_lost");
  const auto r = RunCli("compare --scenario '" + kLostContacts + "' --models conformal --steps 1 --no-plot --out '" +
                        out.string() + "'");
  EXPECT_EQ(r.exit_code, 5) << r.out << r.err;
  const std::string md = Slurp(out / "report.md");
  // the count of the wear run above (round-off luck against the 1e-16 tolerance), the same in the report and stdout
  const std::string marker = "WARNING: [conformal] step 1: ";
  const size_t at = r.out.find(marker);
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string n = r.out.substr(at + marker.size(), r.out.find(' ', at + marker.size()) - at - marker.size());
  EXPECT_GE(std::stoi(n), 1);
  EXPECT_NE(md.find("**WARNING: conformal step 1: " + n + " of 16 wheel contacts failed"), std::string::npos) << md;
  EXPECT_NE(md.find("completed, contacts lost"), std::string::npos) << md;
  fs::remove_all(out);
}

// Item 6: a run that stopped with an invalid profile (0 steps) is not a success.
TEST(CliStatus, InvalidProfileRunIsPartial) {
  const fs::path dir = TempDir("cap50");
  const fs::path sc = ScenarioVariant(dir, "cap_mm: 0.4", "cap_mm: 50");
  const auto r = RunCli("wear --scenario '" + sc.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 5) << r.out << r.err;
  EXPECT_NE(r.err.find("invalid_profile"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(CliStatus, ComparePythonCheckedBeforeComputing) {
  const fs::path out = TempDir("compare_python");
  const auto r = RunCli("compare --scenario '" + kLostContacts + "' --python /nonexistent --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--python"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "hertz")) << "computed before checking the interpreter";
  fs::remove_all(out);
}

TEST(CliStatus, BenchUnknownFamilyIsInputError) {
  const fs::path out = TempDir("bench_family");
  const auto r = RunCli("bench --families foo --no-plot --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--families"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("mbench"), std::string::npos) << r.err;  // the known families are listed
  fs::remove_all(out);
}

// Issue 14: the bench's exact reference is visible per case (status, iterations) and per row (reference_status).
TEST(CliStatus, BenchShowsItsExactReference) {
  const fs::path out = TempDir("bench_reference");
  const auto r = RunCli("bench --families flange_root --models hertz,conformal --no-plot --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string refs = Slurp(out / "bench_reference.csv");
  EXPECT_EQ(refs.rfind("case,family,status,", 0), 0u) << refs;
  EXPECT_NE(refs.find("flange_root_p0,flange_root,converged,"), std::string::npos) << refs;
  EXPECT_NE(refs.find("flange_root_p1,flange_root,converged,"), std::string::npos) << refs;
  const std::string rows = Slurp(out / "bench.csv");
  EXPECT_NE(rows.find(",reference_status\n"), std::string::npos);
  EXPECT_NE(rows.find(",converged\n"), std::string::npos);
  const std::string creep = Slurp(out / "bench_creep_errors.md");
  EXPECT_NE(creep.find("| hertz | flange_root |"), std::string::npos) << creep;
  EXPECT_NE(creep.find("| conformal | flange_root |"), std::string::npos) << creep;
  fs::remove_all(out);
}

TEST(CliStatus, SweepAndStressRejectEmptyInput) {
  auto models = RunCli("sweep --models ''");
  EXPECT_EQ(models.exit_code, 2) << models.out;
  EXPECT_NE(models.err.find("--models"), std::string::npos) << models.err;
  auto nan = RunCli("sweep --from-mm nan");
  EXPECT_EQ(nan.exit_code, 2) << nan.out;
  EXPECT_NE(nan.err.find("--from-mm"), std::string::npos) << nan.err;
  auto stress = RunCli("stress --cases 0");
  EXPECT_EQ(stress.exit_code, 2) << stress.out;
  EXPECT_NE(stress.err.find("--cases"), std::string::npos) << stress.err;
  EXPECT_EQ(stress.out.find("PASSED"), std::string::npos);
}

// Item 7: an output folder that cannot be created is an input error before computing.
TEST(CliStatus, UnwritableOutputFolderIsInputError) {
  for (const std::string& cmd : {std::string("bench --no-plot"), std::string("wear --scenario '") + kLostContacts + "'",
                                std::string("compare --no-plot --scenario '") + kLostContacts + "'"}) {
    const auto r = RunCli(cmd + " --out /proc/conforma_x");
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find("--out"), std::string::npos) << cmd << ": " << r.err;
  }
}

TEST(CliStatus, SmoothingLongerThanProfileIsInputError) {
  const fs::path dir = TempDir("smoothing");
  const fs::path sc = ScenarioVariant(dir, "smoothing_mm: 7.0", "smoothing_mm: 10000");
  const auto r = RunCli("wear --scenario '" + sc.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("smoothing_mm"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

// Item 8: the normal-only reference model cannot drive a wear run.
TEST(CliStatus, ReferenceModelRejectedByWearCommands) {
  const fs::path out = TempDir("reference");
  for (const std::string& cmd : {std::string("wear --model reference"), std::string("compare --models hertz,reference"),
                                std::string("validate --models reference --measured x.csv"),
                                std::string("curving --model reference")}) {
    const auto r = RunCli(cmd + " --scenario '" + kLostContacts + "'" +
                          (cmd.rfind("curving", 0) == 0 ? "" : " --out '" + out.string() + "'"));
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find("reference"), std::string::npos) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("conformal"), std::string::npos) << cmd << ": " << r.err;  // the usable models
  }
  for (const char* cmd : {"wear", "compare", "validate", "curving"}) {
    const auto help = RunCli(std::string(cmd) + " --help");
    EXPECT_EQ(help.out.find("reference"), std::string::npos) << cmd << " --help lists reference";
  }
  fs::remove_all(out);
}

// Item 11: an RMS over the km-0 point alone is not a result.
TEST(CliStatus, ValidateWithOnlyTheInitialPointIsPartial) {
  const fs::path dir = TempDir("validate_short");
  std::ofstream(dir / "measured.csv") << "km,QR_mm,FH_mm,FT_mm\n0,10.5,28.0,32.5\n100000,8.0,29.5,29.0\n";
  const auto r = RunCli("validate --scenario '" + kLostContacts + "' --models hertz --steps 1 --no-plot --measured '" +
                        (dir / "measured.csv").string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 5) << r.out << r.err;
  EXPECT_EQ(r.out.find("over 1 points"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("NO RESULT"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

}  // namespace

namespace {

// Item 11: model_difference.png plots the normal distance the report uses, not the z difference: on a 45 degree
// face two profiles 0.1 mm apart in z are 0.1 cos(45 deg) = 0.0707 mm apart along the normal.
TEST(CliStatus, CompareDifferencePlotUsesTheNormalDistance) {
  const char* python = "/usr/bin/python3";
  if (std::system((std::string(python) + " -c 'import matplotlib, numpy' >/dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "no python3 with matplotlib and numpy";
  const fs::path dir = TempDir("normal_distance");
  const std::string script =
      "import sys; sys.path.insert(0, '" + std::string(CONFORMA_SOURCE_DIR) + "/scripts')\n"
      "import numpy as np, plot_compare as pc\n"
      "y = list(np.linspace(0.0, 10.0, 101))\n"
      "first, second = (y, [v for v in y]), (y, [v - 0.1 for v in y])\n"
      "ys, d = pc.normal_distance(first, second)\n"
      "inner = d[(ys > 2) & (ys < 8)]\n"
      "print('%.6f %.6f' % (inner.min(), inner.max()))\n";
  std::ofstream(dir / "check.py") << script;
  const std::string cmd = std::string(python) + " '" + (dir / "check.py").string() + "' > '" + (dir / "out").string() +
                          "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << Slurp(dir / "out");
  std::istringstream in(Slurp(dir / "out"));
  double lo = 0.0, hi = 0.0;
  in >> lo >> hi;
  EXPECT_NEAR(std::abs(lo), 0.1 / std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(std::abs(hi), 0.1 / std::sqrt(2.0), 1e-4);
  fs::remove_all(dir);
}

}  // namespace
