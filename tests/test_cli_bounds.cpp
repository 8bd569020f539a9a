// test-links: app
// Input the executable refuses up front, and results it does not pass off as complete (session 24's fuzzing of the
// command line): values beyond what the arithmetic or the memory can take are input errors (exit 2) naming the
// option; a damaged or foreign contact table is an error, never a crash or another geometry's numbers; a curving run
// that fell back is incomplete (exit 5).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "conforma/standard_profiles.hpp"

namespace {

namespace fs = std::filesystem;
using conforma::test::RunCli;

const std::string kScenario = std::string(CONFORMA_SOURCE_DIR) + "/scenarios/default_metro.yaml";

void ExpectInputError(const std::string& args, const std::string& named) {
  const auto r = RunCli(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << args << ": " << r.out;
}

// A wheelset pushed past flange contact onto the flange tip: the warning says so, instead of advising a z shift of
// the (correct) profile; a bad speed is an error before any table header is printed.
TEST(CliBounds, DerailedWheelsetIsNamedAndBadSpeedIsRefusedFirst) {
  const auto r = RunCli("contact --y-mm 30 --side left");
  EXPECT_NE(r.err.find("beyond flange contact"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--wheel-z-shift-mm"), std::string::npos) << r.err;
  for (const char* speed : {"0", "-2", "nan"}) {
    const auto s = RunCli(std::string("contact --speed ") + speed);
    EXPECT_EQ(s.exit_code, 2) << speed << ": " << s.err;
    EXPECT_NE(s.err.find("--speed"), std::string::npos) << s.err;
    EXPECT_EQ(s.out, "") << speed;
  }
}

// A profile in mm read as metres: named as a unit mistake, not as a too coarse profile.
TEST(CliBounds, ProfileInTheWrongUnitIsNamedAsSuch) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_bounds", "units");
  const fs::path file = dir / "wheel_mm.txt";
  {
    std::ofstream f(file);
    for (int i = 0; i <= 130; ++i) f << -70.0 + i << " " << 0.001 * (i - 70) * (i - 70) << "\n";
  }
  ExpectInputError("contact --wheel '" + file.string() + "' --wheel-units m", "wrong length unit");
  fs::remove_all(dir);
}

// A key given twice in a scenario: YAML reads the first value, so the second was silently ignored.
TEST(CliBounds, ScenarioKeyGivenTwiceIsAnInputError) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_bounds", "dup");
  const fs::path file = dir / "dup.yaml";
  std::ofstream(file) << conforma::test::Slurp(kScenario) << "\nfriction: 0.5\n";
  ExpectInputError("curving --class 0 --scenario '" + file.string() + "'", "given twice");
  fs::remove_all(dir);
}

// A creepage of 1e300 gave F_x = NaN with exit 0, 1e155 gave F_x = 0 (its square overflows).
TEST(CliBounds, HugeGivenCreepagesAreInputErrors) {
  ExpectInputError("contact --xi 1e300", "creepages.xi");
  ExpectInputError("contact --xi 1e155 --side left", "creepages.xi");
  ExpectInputError("contact --eta -1e300", "creepages.eta");
  ExpectInputError("contact --phi-per-m 1e300", "creepages.phi_per_m");
  // the bound is far beyond full slip: 1e3 still solves, saturated at mu N
  const auto r = RunCli("contact --xi 1000 --side left --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("null"), std::string::npos) << r.out;
}

// Sizes that ran out of memory or for hours: refused before computing.
TEST(CliBounds, WorkBeyondTheLimitsIsRefusedUpFront) {
  ExpectInputError("contact --grid 100000000", "fastsim_elements");
  ExpectInputError("sweep --step-mm 1e-9", "poses");
  ExpectInputError("dynamics --scenario '" + kScenario + "' --duration 0.05 --bogies 2000000000", "bogie_count");
  ExpectInputError("dynamics --scenario '" + kScenario + "' --duration 0.3 --bogies 1000", "bogie_count");
  ExpectInputError("dynamics --scenario '" + kScenario + "' --duration 0.3 --output-interval 1e-9", "output interval");
  ExpectInputError("dynamics --scenario '" + kScenario + "' --bogies -1 --duration 0.01", "--bogies");
}

// NaN and out-of-range values that silently meant something else.
TEST(CliBounds, MalformedValuesAreNotReinterpreted) {
  ExpectInputError("contact --load-N -1 --approach-mm nan", "--approach-mm");
  ExpectInputError("dynamics --scenario '" + kScenario + "' --eig --amplitude-mm 0", "--amplitude-mm");
  const fs::path out = conforma::test::FreshTempDir("conforma_bounds", "wear");
  ExpectInputError("wear --scenario '" + kScenario + "' --steps 1 --km nan --out '" + out.string() + "'", "--km");
  ExpectInputError("wear --scenario '" + kScenario + "' --steps 1 --km -5 --out '" + out.string() + "'", "--km");
  ExpectInputError("wear --scenario '" + kScenario + "' --steps -5 --out '" + out.string() + "'", "--steps");
  // a material that is no wheel or rail steel (a unit slip): 1e300 kg/m^3 gave a wear step of 1.6e296 km, exit 0
  for (const char* density : {"1e300", "2147483648", "1e-300", "7.85"})
    ExpectInputError("wear --scenario '" + kScenario + "' --steps 1 --model hertz --set material.density_kg_m3=" +
                         density + " --out '" + out.string() + "'",
                     "density_kg_m3 = ");
  ExpectInputError("contact --G-GPa 1e-6", "shear_modulus_Pa = ");
  fs::remove_all(out);
  // the message names the pose, not a 300-digit number
  const auto r = RunCli("contact --y-mm 1e300");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_LT(r.err.size(), 400u) << r.err;
}

// A friction coefficient no wheel-rail contact has (1e-300 ran a wear step of ~1e300 km without a word) is named on
// stderr, as `contact` and `dynamics` do; a plausible one is not.
TEST(CliBounds, ImplausibleFrictionInAScenarioWarns) {
  const fs::path out = conforma::test::FreshTempDir("conforma_bounds", "friction");
  const std::string wear = "wear --scenario '" + kScenario + "' --steps 1 --model hertz --out '" + out.string() + "'";
  const auto low = RunCli(wear + " --set friction=0.01");
  EXPECT_EQ(low.exit_code, 0) << low.err;
  EXPECT_NE(low.err.find("warning: track class cruise: friction 0.01 is outside the plausible range"),
            std::string::npos)
      << low.err;
  const auto plausible = RunCli(wear + " --set friction=0.4");
  EXPECT_EQ(plausible.exit_code, 0) << plausible.err;
  EXPECT_EQ(plausible.err.find("friction"), std::string::npos) << plausible.err;
  fs::remove_all(out);
}

// The tangent class's kinematic oscillation of 100 mm leaves the rails: the class falls back and its samples lose
// contact; that is an incomplete result (exit 5), shown in the output, 0 with --allow-partial.
TEST(CliBounds, CurvingThatFellBackIsIncomplete) {
  const std::string args =
      "curving --scenario '" + kScenario + "' --class 0 --set kinematics.tangent_amplitude_mm=100";
  const auto r = RunCli(args);
  EXPECT_EQ(r.exit_code, 5) << r.out << r.err;
  EXPECT_NE(r.out.find("fell back"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("fell back"), std::string::npos) << r.err;
  EXPECT_EQ(RunCli("--allow-partial " + args).exit_code, 0);
  EXPECT_EQ(RunCli("curving --scenario '" + kScenario + "' --class 0").exit_code, 0);
}

// A table names the geometry it was built for: evaluated with another wheel it is refused, not read as that wheel's.
// Damaged bytes anywhere in the file give an error or the undamaged answer, never a crash (the file format has
// checksums on its object headers and data: a one-byte change in a dataset header segfaulted inside libhdf5 before).
TEST(CliBounds, ContactTableOfAnotherGeometryOrDamagedIsAnError) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_bounds", "lut");
  const std::string table = (dir / "t.h5").string();
  ASSERT_EQ(RunCli("lut build --out '" + table + "' --y-mm -2:2:1 --yaw-mrad -1,1 --load-kN 40,60 --threads 1").exit_code,
            0);
  const std::string query = " --load-N 50000 --y-mm 0.5 --yaw-mrad 0.3";
  const auto same = RunCli("lut eval '" + table + "'" + query);
  ASSERT_EQ(same.exit_code, 0) << same.err;
  // without --load-N: the middle of the table's load axis (the shared 10 kN default lies outside it), said so, and
  // the same answer as --load-N 50000 given
  const auto middle = RunCli("lut eval '" + table + "' --y-mm 0.5 --yaw-mrad 0.3");
  ASSERT_EQ(middle.exit_code, 0) << middle.err;
  EXPECT_NE(middle.out.find("load 50 kN (the middle of the table's load axis"), std::string::npos) << middle.out;
  EXPECT_EQ(middle.out.substr(middle.out.find('\n')), same.out.substr(same.out.find('\n')));
  const auto other = RunCli("lut eval '" + table + "'" + query + " --wheel '" +
                            conforma::test::SharedData("profiles/contact/testbank/profiles/Car7358_0001r.whl") + "'");
  EXPECT_EQ(other.exit_code, 2) << other.out << other.err;
  EXPECT_NE(other.err.find("built for another geometry"), std::string::npos) << other.err;

  std::ifstream in(table, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 1000u);
  const std::string damaged = (dir / "damaged.h5").string();
  int errors = 0, runs = 0;
  for (size_t at = 0; at < bytes.size(); at += bytes.size() / 60 + 1, ++runs) {
    std::vector<char> copy = bytes;
    copy[at] = static_cast<char>(copy[at] ^ 0x5a);
    std::ofstream(damaged, std::ios::binary).write(copy.data(), static_cast<std::streamsize>(copy.size()));
    const auto r = RunCli("lut eval '" + damaged + "'" + query);
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 2) << "byte " << at << ": exit " << r.exit_code << "\n" << r.err;
    if (r.exit_code == 0) {  // (the first line names the file)
      EXPECT_EQ(r.out.substr(r.out.find('\n')), same.out.substr(same.out.find('\n')))
          << "byte " << at << " changed the answer without an error";
    }
    if (r.exit_code == 2) {  // the error names the file and what of it could not be read
      EXPECT_NE(r.err.find(damaged + ": contact LUT file: "), std::string::npos) << "byte " << at << ": " << r.err;
    }
    errors += r.exit_code == 2;
  }
  // (14 of the 61 bytes changed are read and found; the others lie where nothing is read: padding, free space)
  EXPECT_GT(errors, 0) << "of " << runs << " damaged bytes none was found";
  fs::remove_all(dir);
}

// --- session 25: the fuzzing's remaining findings ----------------------------------------------------------------

// S1002 points y z [mm] (taping line at y = 0), y from -65 to 60 mm by 0.5 mm (the flange back's vertical end left out).
std::vector<std::pair<double, double>> S1002Points() {
  std::vector<std::pair<double, double>> p;
  for (int i = 0; i <= 250; ++i) p.emplace_back(-65.0 + 0.5 * i, conforma::S1002Height_mm(-65.0 + 0.5 * i));
  return p;
}

void WriteColumns(const fs::path& file, bool swap = false, bool decimal_comma = false) {
  std::ofstream f(file);
  for (const auto& [y, z] : S1002Points()) {
    char line[80];
    std::snprintf(line, sizeof line, "%.6f %.6f", swap ? z : y, swap ? y : z);
    std::string text = line;
    if (decimal_comma)
      for (char& c : text) c = c == '.' ? ',' : c;
    f << text << "\n";
  }
}

// Profile files that were read as something else: each is named for what is wrong with it.
TEST(CliBounds, ProfileFileMistakesAreNamed) {
  const fs::path dir = conforma::test::FreshTempDir("conforma_bounds", "profiles");
  const fs::path good = dir / "s1002.txt", comma = dir / "comma.txt", swapped = dir / "swapped.txt",
                 metres = dir / "metres.txt", miniprof = dir / "taping_origin.whl", xy_nan = dir / "xy_nan.whl";
  WriteColumns(good);
  WriteColumns(comma, false, true);
  WriteColumns(swapped, true);
  {
    std::ofstream m(metres), w(miniprof), x(xy_nan);
    w << "Filename=t\nXYPoints=251\nColumnDef=X,Y\n\n";
    x << "Filename=t\nXYPoints=nan\nColumnDef=X,Y\n\n";
    for (const auto& [y, z] : S1002Points()) {
      m << y * 1e-3 << " " << z * 1e-3 << "\n";  // metres, read as mm
      w << y << " " << z << "\n";                // the taping line at X = 0 instead of the flange back
      x << y + 70.0 << " " << z << "\n";
    }
  }
  ASSERT_EQ(RunCli("contact --side left --wheel '" + good.string() + "'").exit_code, 0);  // the same points, as columns
  ExpectInputError("contact --wheel '" + comma.string() + "'", "decimal commas");
  ExpectInputError("contact --wheel '" + swapped.string() + "'", "columns swapped");
  ExpectInputError("contact --wheel '" + metres.string() + "'", "wrong length unit");
  ExpectInputError("contact --wheel '" + miniprof.string() + "'", "flange back at X = 0");
  ExpectInputError("contact --wheel '" + xy_nan.string() + "'", "XYPoints=nan");
  ExpectInputError("contact --rail '" + good.string() + "'", "wheel profile");  // a wheel given as the rail
  ExpectInputError("contact --wheel '" + dir.string() + "'", "is a directory");
  fs::remove_all(dir);
}

// Poses, radii and names beyond a wheelset on track, which solved with exit 0 before.
TEST(CliBounds, PoseAndTrackBeyondARailwayAreRefused) {
  ExpectInputError("contact --yaw-mrad 1e9", "--yaw-mrad");
  ExpectInputError("contact --r0-mm 1e-9", "--r0-mm");
  ExpectInputError("contact --load-N 0", "--load-N 0");
  ExpectInputError("contact --load-N -1 --approach-mm 1e6", "--approach-mm");
  ExpectInputError("sweep --models hertz,,kp", "empty name");
  ExpectInputError("lut build --out x.h5 --y-mm -2:2:1 --yaw-mrad -300,1 --load-kN 40,60", "yaw_rad");
  const std::string curving = "curving --class 0 --scenario '" + kScenario + "' --set ";
  ExpectInputError(curving + "profiles.wheel_radius_mm=355500", "wheel_radius_mm");
  // a copy of the scenario with one value of a track class changed
  const fs::path dir = conforma::test::FreshTempDir("conforma_bounds", "classes");
  const std::string text = conforma::test::Slurp(kScenario);
  auto with = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    const fs::path file = dir / "changed.yaml";
    std::ofstream(file) << text.substr(0, at) << to << text.substr(at + from.size());
    return "curving --class 0 --scenario '" + file.string() + "'";
  };
  ExpectInputError(with("speed_kmh: 70", "speed_kmh: 1e6"), "speed_kmh = 1e+06");
  ExpectInputError(with("cant_mm: 90", "cant_mm: 5000"), "cant_mm = 5000");
  ExpectInputError(with("acceleration_m_s2: 1.0", "acceleration_m_s2: 100"), "adhesion");
  fs::remove_all(dir);
  ExpectInputError(curving + "kinematics.tangent_amplitude_mm=1e6", "tangent_amplitude_mm");
  ExpectInputError(curving + "wear_law=archard", "built-in law is 'usfd'");
  // each rail step runs the whole wheel sequence again: a typo of 1e9 rail steps ran for ever
  ExpectInputError("curving --class 0 --scenario '" + std::string(CONFORMA_SOURCE_DIR) +
                       "/scenarios/metro_rail_steps.yaml' --set rail.steps=1000000000",
                   "rail.steps = 1000000000: at most 1000");
}

// A sweep past the flange onto no rail: every pose is a row naming it, and the run is incomplete (exit 5); the CSV
// had the header only.
TEST(CliBounds, SweepPosesWithoutContactAreRowsAndIncomplete) {
  const auto r = RunCli("sweep --from-mm 1e5 --to-mm 2e5 --step-mm 1e5 --models hertz --csv");
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_NE(r.out.find("hertz,100000,0,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no_rigid_contact"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("no rigid contact"), std::string::npos) << r.err;
}

// A wheelset started 50 mm off centre climbs its flange: the run completes, and the summary says that Y/Q passed the
// flange-climbing limit (it said "completed" with Y/Q 3.1 and nothing else).
TEST(CliBounds, DynamicsNamesAFlangeClimbingYOverQ) {
  const auto r = RunCli("dynamics --scenario '" + kScenario + "' --model hertz --duration 0.02 --offset-mm 50 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("flange-climbing limits"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("derailment risk"), std::string::npos) << r.err;
  const auto centred = RunCli("dynamics --scenario '" + kScenario + "' --model hertz --duration 0.02 --quiet");
  EXPECT_EQ(centred.exit_code, 0) << centred.err;
  EXPECT_EQ(centred.err.find("derailment risk"), std::string::npos) << centred.err;
}

// The other commands (session 25's second fuzzing): sizes that crashed, hung or ran away, and option mistakes that
// were silently the defaults, are input errors up front; a malformed command line is exit 2 like any input error
// (CLI11's own codes 104-114 before).
TEST(CliBounds, OtherCommandsRefuseRunawayInput) {
  ExpectInputError("contact --bogus", "--bogus");
  ExpectInputError("contact --y-mm abc", "--y-mm");
  EXPECT_EQ(RunCli("contact --help").exit_code, 0);
  ExpectInputError("stress --cases 2 --threads 100000 --determinism-cases 0", "--threads");  // segfaulted
  ExpectInputError("stress --cases 2000000000 --determinism-cases 0", "--cases");           // std::bad_alloc
  const std::string rig = "rig run --scenario '" + std::string(CONFORMA_SOURCE_DIR) + "/scenarios/roller_rig_1to5.yaml'";
  const fs::path out = conforma::test::FreshTempDir("conforma_bounds", "rig");
  ExpectInputError(rig + " --out '" + out.string() + "' --step-s 1e-9", "samples");  // hung
  ExpectInputError(rig + " --out '" + out.string() + "' --step-s nan", "--step-s");  // the scenario's step before
  ExpectInputError(rig + " --out /proc/conforma_forbidden", "--out");                // internal error before
  fs::remove_all(out);
  ExpectInputError("track irregularity --length-m 2.5e5", "length_m");  // quadratic in the length: hung
  ExpectInputError("curving --class 0 --scenario '" + kScenario + "' --set kinematics.tangent_phases=100000000",
                   "tangent_phases");
  ExpectInputError("bench --creepage-scale 1e300 --models hertz --families mbench --no-plot", "--creepage-scale");
  ExpectInputError("threshold --load-N 1e12", "--load-N");
  // lists that computed nothing with exit 0, or ran an entry twice; sizes that failed row by row
  ExpectInputError("threshold --sets ''", "--sets");
  ExpectInputError("threshold --sets new,new", "given twice");
  ExpectInputError("threshold --kp-strips 100000000", "--kp-strips");
  ExpectInputError("mbench --models ''", "--models");
  ExpectInputError("curving --scenario '" + kScenario + "' --class -5", "--class");
}

}  // namespace
