// Validation against measured wheels (measured_validation.hpp): the MD061 file as shipped, clear errors for malformed
// files, interpolation between wear steps, the profile normal distance on an exactly offset curve, and an end-to-end
// run whose "measured" data are the simulation's own output (zero error), through the library and the CLI.
// test-links: app  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "conforma/error.hpp"
#include "conforma/validation/measured_validation.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/scenario.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {
namespace {

namespace fs = std::filesystem;

const std::string kMd061 = std::string(CONFORMA_SHARED_DATA) + "/measured/aosta_minuetto/md061_fleet_average.csv";

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("conforma_validate_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string path(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }

 private:
  fs::path path_;
};

// Message of the InputError thrown by f ("" if none).
template <class F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MeasuredDimensions, ReadsTheMd061FleetAverage) {
  const MeasuredDimensions m = ReadMeasuredDimensions(kMd061);
  ASSERT_EQ(m.points.size(), 4u);
  EXPECT_TRUE(m.has[0] && m.has[1] && m.has[2]);
  // file: km,QR_mm,FH_mm,FT_mm with FT = Sd, FH = Sh, QR = qR
  const double km[4] = {0, 1426, 2001, 2575};
  const double qr[4] = {10.8, 9.8, 9.1, 8.6}, fh[4] = {28.0, 28.2, 28.1, 28.0}, ft[4] = {32.5, 31.5, 30.8, 30.2};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(m.points[i].km, km[i]);
    EXPECT_NEAR(*m.points[i].value_m[static_cast<int>(ReferenceDimension::Sd)], ft[i] * 1e-3, 1e-15);
    EXPECT_NEAR(*m.points[i].value_m[static_cast<int>(ReferenceDimension::Sh)], fh[i] * 1e-3, 1e-15);
    EXPECT_NEAR(*m.points[i].value_m[static_cast<int>(ReferenceDimension::qR)], qr[i] * 1e-3, 1e-15);
  }
  EXPECT_EQ(m.points[0].line, 4);  // two comment lines and the header come first
  EXPECT_TRUE(m.ignored_columns.empty());
}

TEST(MeasuredDimensions, AlternativeNamesAndPartialColumns) {
  const MeasuredDimensions m =
      ParseMeasuredDimensions("# c\n\nKM, sd_mm ,wheel\n0,32.5,1r\n100,32.1,1r\n", "alt.csv");
  ASSERT_EQ(m.points.size(), 2u);
  EXPECT_TRUE(m.has[0]);
  EXPECT_FALSE(m.has[1] || m.has[2]);
  EXPECT_FALSE(m.points[1].value_m[1].has_value());
  EXPECT_NEAR(*m.points[1].value_m[0], 32.1e-3, 1e-15);
  ASSERT_EQ(m.ignored_columns.size(), 1u);
  EXPECT_EQ(m.ignored_columns[0], "wheel");
}

TEST(MeasuredDimensions, MalformedFilesNameFileAndLine) {
  TempDir tmp;
  struct Case {
    const char* text;
    const char* expect;  // substring of the message after "<file>:<line>: "
    int line;
  };
  const Case cases[] = {
      {"# x\ndistance,QR_mm,FH_mm\n0,10,28\n", "missing column 'km'", 2},
      {"km,wheel\n0,1\n", "no dimension column", 1},
      {"km,QR_mm,FH_mm,FT_mm\n0,10.8,28.0,32.5\n1426,9.8,28.2\n", "missing column", 3},
      {"km,QR_mm,FH_mm,FT_mm\n0,10.8,28.0,32.5\n1426,nan,28.2,31.5\n", "'nan' is not finite", 3},
      {"km,QR_mm,FH_mm,FT_mm\n0,10.8,28.0,32.5\n1426,9.8,abc,31.5\n", "'abc' is not a number", 3},
      {"km,QR_mm,FH_mm,FT_mm\n0,10.8,28.0,32.5\n1426,9.8,28.2,31.5\n1426,9.1,28.1,30.8\n", "increase strictly", 4},
      {"km,QR_mm,FH_mm,FT_mm\n0,10.8,28.0,32.5\n\n# c\n900,9.8,28.2,31.5\n500,9.1,28.1,30.8\n", "increase strictly", 6},
      {"km,QR_mm,FH_mm,FT_mm\n0,10.8,,32.5\n", "missing value in column 'FH_mm'", 2},
      {"km,QR_mm,FH_mm,FT_mm\n-5,10.8,28,32.5\n", "km must be >= 0", 2},
      {"km,QR_mm,FT_mm,sd_mm\n0,10.8,28,32.5\n", "two columns for Sd", 1},
      {"km,QR_mm\n", "no data rows", 1},
  };
  for (const Case& c : cases) {
    const std::string f = tmp.write("bad.csv", c.text);
    const std::string msg = ErrorOf([&] { ReadMeasuredDimensions(f); });
    EXPECT_NE(msg.find(f + ":" + std::to_string(c.line) + ": "), std::string::npos) << c.text << " -> " << msg;
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.text << " -> " << msg;
  }
  const std::string missing = ErrorOf([&] { ReadMeasuredDimensions(tmp.path("absent.csv")); });
  EXPECT_NE(missing.find("absent.csv"), std::string::npos) << missing;
}

// A series with Sd, Sh, qR linear in km at uneven step lengths (as the cap makes them).
SimulatedDimensionSeries LinearSeries() {
  SimulatedDimensionSeries s;
  const double km[] = {0.0, 310.5, 702.25, 1100.0, 1733.0};
  for (int i = 0; i < 5; ++i) {
    WheelDimensions d;
    d.sd_m = 32.5e-3 - 1.1e-6 * km[i];
    d.sh_m = 28.0e-3 + 0.2e-6 * km[i];
    d.qr_m = 10.8e-3 - 0.9e-6 * km[i];
    s.step.push_back(i);
    s.km.push_back(km[i]);
    s.dimensions.push_back(d);
  }
  return s;
}

TEST(DimensionInterpolation, ExactOnALinearSeriesAndBracketsReported) {
  const SimulatedDimensionSeries s = LinearSeries();
  for (double km : {0.0, 1.0, 155.0, 310.5, 500.0, 1099.9, 1500.0, 1733.0}) {
    const InterpolatedDimension sd = InterpolateDimension(s, ReferenceDimension::Sd, km);
    const InterpolatedDimension sh = InterpolateDimension(s, ReferenceDimension::Sh, km);
    const InterpolatedDimension qr = InterpolateDimension(s, ReferenceDimension::qR, km);
    ASSERT_EQ(sd.bracket.status, InterpolationStatus::Interpolated) << km;
    EXPECT_NEAR(sd.value_m, 32.5e-3 - 1.1e-6 * km, 1e-15) << km;
    EXPECT_NEAR(sh.value_m, 28.0e-3 + 0.2e-6 * km, 1e-15) << km;
    EXPECT_NEAR(qr.value_m, 10.8e-3 - 0.9e-6 * km, 1e-15) << km;
    EXPECT_LE(s.km[sd.bracket.before], km);
    EXPECT_GE(s.km[sd.bracket.after], km);
  }
  const StepBracket b = BracketKm(s.km, 500.0);
  EXPECT_EQ(b.before, 1u);
  EXPECT_EQ(b.after, 2u);
  EXPECT_NEAR(b.weight, (500.0 - 310.5) / (702.25 - 310.5), 1e-15);
  EXPECT_EQ(BracketKm(s.km, 1733.1).status, InterpolationStatus::BeyondSimulation);
  EXPECT_THROW(BracketKm(s.km, -1.0), InputError);
  EXPECT_THROW(BracketKm(s.km, std::nan("")), InputError);
}

TEST(DimensionComparison, ErrorsRmsAndPointsBeyondTheSimulation) {
  const SimulatedDimensionSeries s = LinearSeries();
  // measured = simulated + known offsets: Sd +0.1 and -0.3 mm (RMS sqrt(0.05) mm), Sh exact; a point beyond
  const MeasuredDimensions m = ParseMeasuredDimensions(
      "km,FT_mm,FH_mm\n"
      "100," + std::to_string(32.5 - 1.1e-3 * 100 - 0.1) + "," + std::to_string(28.0 + 0.2e-3 * 100) + "\n" +
      "1000," + std::to_string(32.5 - 1.1e-3 * 1000 + 0.3) + "," + std::to_string(28.0 + 0.2e-3 * 1000) + "\n" +
      "2000,30,28.4\n",
      "offsets.csv");
  const DimensionComparison c = CompareDimensions(s, m);
  ASSERT_EQ(c.points.size(), 6u);
  const DimensionErrorSummary& sd = c.summary[0];
  EXPECT_EQ(sd.points, 2);
  EXPECT_EQ(sd.beyond_simulation, 1);
  EXPECT_NEAR(sd.rms_error_m, std::sqrt((0.1 * 0.1 + 0.3 * 0.3) / 2) * 1e-3, 1e-9);
  EXPECT_NEAR(sd.max_abs_error_m, 0.3e-3, 1e-9);
  EXPECT_NEAR(sd.mean_error_m, (0.1 - 0.3) / 2 * 1e-3, 1e-9);
  EXPECT_NEAR(c.points[0].error_m, 0.1e-3, 1e-9);  // simulated - measured
  EXPECT_NEAR(c.summary[1].rms_error_m, 0.0, 1e-9);
  EXPECT_EQ(c.summary[2].points, 0);
  EXPECT_EQ(c.points[4].bracket.status, InterpolationStatus::BeyondSimulation);
}

// S1002 displaced by `offset` along its own outward normal (an exact parallel curve: every point of the original
// is `offset` from it, measured along the common normal, where the radius of curvature exceeds the offset).
Profile OffsetProfile(const Profile& p, double offset) {
  std::vector<Eigen::Vector2d> pts;
  const int n = static_cast<int>(std::ceil(p.length() / 0.05e-3));
  for (int i = 0; i <= n; ++i) {
    const double s = p.length() * i / n;
    pts.push_back(p.position(s) + offset * p.normal(s));
  }
  ProfileFitOptions fit;
  fit.function_of_y = false;
  fit.sample_spacing_m = 0.05e-3;
  return Profile::FromPoints(pts, p.kind(), fit, "offset");
}

TEST(ProfileDistance, NormalOffsetOfAProfileGivesTheOffset) {
  const Profile s1002 = MakeS1002();
  const Profile outside = OffsetProfile(s1002, 0.1e-3);
  ProfileDistanceOptions o;
  o.lateral_range_m = std::array<double, 2>{-40e-3, 50e-3};  // flange face, root and tread
  const ProfileDistanceResult r = MeasureProfileDistance(s1002, outside, Profile(), o);
  ASSERT_EQ(r.status, ProfileDistanceStatus::Measured);
  EXPECT_GT(r.points, 500);
  EXPECT_EQ(r.outside_measurement, 0);
  EXPECT_NEAR(r.rms_m, 0.1e-3, 1e-9);  // 1e-6 mm
  EXPECT_NEAR(r.max_m, 0.1e-3, 1e-9);
  EXPECT_NEAR(r.mean_signed_m, 0.1e-3, 1e-9);  // measured outside: the "simulation" wore 0.1 mm more
  EXPECT_NEAR(r.zone_y_min_m, -40e-3, 0.2e-3);
  EXPECT_NEAR(r.zone_y_max_m, 50e-3, 0.2e-3);
  // the other way round: measured inside the simulated surface
  const ProfileDistanceResult inside = MeasureProfileDistance(outside, s1002, Profile(), o);
  EXPECT_NEAR(inside.rms_m, 0.1e-3, 1e-9);
  EXPECT_NEAR(inside.mean_signed_m, -0.1e-3, 1e-9);
}

TEST(ProfileDistance, WornZoneFollowsTheWearDepthAndAlignment) {
  // "simulated" = S1002 with a 0.3 mm deep cosine hollow on the tread between y = 0 and 20 mm; measured = S1002.
  const Profile s1002 = MakeS1002();
  std::vector<Eigen::Vector2d> pts;
  const int n = static_cast<int>(std::ceil(s1002.length() / 0.05e-3));
  for (int i = 0; i <= n; ++i) {
    const double s = s1002.length() * i / n;
    const Eigen::Vector2d q = s1002.position(s);
    const double depth = (q[0] > 0.0 && q[0] < 20e-3) ? 0.15e-3 * (1.0 - std::cos(2 * M_PI * q[0] / 20e-3)) : 0.0;
    pts.push_back(q - depth * s1002.normal(s));
  }
  ProfileFitOptions fit;
  fit.function_of_y = false;
  fit.sample_spacing_m = 0.05e-3;
  const Profile worn = Profile::FromPoints(pts, ProfileKind::Wheel, fit, "hollow");
  const ProfileDistanceResult r = MeasureProfileDistance(worn, s1002, s1002);
  ASSERT_EQ(r.status, ProfileDistanceStatus::Measured);
  // zone: depth > 0.01 mm <=> 1 - cos(2 pi y / 20) > 1/15
  const double y0 = 20e-3 / (2 * M_PI) * std::acos(1.0 - 1.0 / 15.0);
  EXPECT_NEAR(r.zone_y_min_m, y0, 0.15e-3);
  EXPECT_NEAR(r.zone_y_max_m, 20e-3 - y0, 0.15e-3);
  EXPECT_NEAR(r.max_m, 0.3e-3, 2e-6);  // the bottom of the hollow (tread nearly flat: depth ~ distance)
  EXPECT_NEAR(r.y_at_max_m, 10e-3, 0.3e-3);
  EXPECT_GT(r.mean_signed_m, 0.0);  // the measured S1002 lies outside the hollow: the "simulation" wore more
  // Taping-line alignment: the measured profile shifted by +1 mm in z is brought back to the simulated height at
  // y = 0 (no wear there), so the distances are unchanged.
  std::vector<Eigen::Vector2d> up = s1002.samples();
  for (Eigen::Vector2d& p : up) p[1] += 1e-3;
  const Profile lifted = Profile::FromPoints(up, ProfileKind::Wheel, fit, "lifted");
  ProfileDistanceOptions o;
  o.align_taping_line = true;
  const ProfileDistanceResult a = MeasureProfileDistance(worn, lifted, s1002, o);
  EXPECT_NEAR(a.alignment_shift_m, -1e-3, 1e-9);
  EXPECT_NEAR(a.rms_m, r.rms_m, 1e-8);
  EXPECT_NEAR(a.max_m, r.max_m, 1e-8);
  // nothing worn: empty zone, a status, not an error
  const ProfileDistanceResult none = MeasureProfileDistance(s1002, s1002, s1002);
  EXPECT_EQ(none.status, ProfileDistanceStatus::EmptyZone);
  EXPECT_EQ(none.points, 0);
}

// ---------------------------------------------------------------- end to end
const std::string kMetro = std::string(CONFORMA_SOURCE_DIR) + "/scenarios/metro_curves.yaml";

// The default metro scenario on the kinematic curving estimate (no Ceres) with 2 tangent phases: a few seconds per
// step, as in test_wear_simulation.
std::string TinyScenarioYaml() {
  std::ifstream in(kMetro);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string y = ss.str();
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"provider: quasistatic", "provider: kinematic"},
                                 {"tangent_phases: 4", "tangent_phases: 2"}}) {
    const size_t p = y.find(from);
    if (p == std::string::npos) ADD_FAILURE() << kMetro << " has no '" << from << "'";
    else y.replace(p, from.size(), to);
  }
  return y;
}

std::string MeasuredFromSteps(const WearSimulationResult& r) {
  std::ostringstream m;
  m << "# written from the simulation's own steps\nkm,FT_mm,FH_mm,QR_mm\n" << std::setprecision(17);
  m << 0 << "," << r.initial_dimensions.sd_m * 1e3 << "," << r.initial_dimensions.sh_m * 1e3 << ","
    << r.initial_dimensions.qr_m * 1e3 << "\n";
  for (const WearStepRecord& s : r.steps)
    m << s.km << "," << s.dimensions.sd_m * 1e3 << "," << s.dimensions.sh_m * 1e3 << "," << s.dimensions.qr_m * 1e3
      << "\n";
  return m.str();
}

// Two Hertz wear steps of a scenario (no distance limit): the runs the end-to-end tests compare with themselves.
WearSimulationResult TwoHertzSteps(const Scenario& sc) {
  WearSimulationOptions o;
  o.contact.model = ContactModel::Hertz;
  o.steps = 2;
  o.total_km = 0.0;
  return RunWearSimulation(sc, o);
}

TEST(ValidateEndToEnd, OwnStepOutputAsMeasuredGivesZeroError) {
  TempDir tmp;
  const WearSimulationResult r = TwoHertzSteps(ParseScenario(TinyScenarioYaml(), kMetro, CONFORMA_SOURCE_DIR "/scenarios"));
  ASSERT_EQ(r.steps.size(), 2u) << r.message;

  // (a) dimensions: the file holds the step values at the step km -> zero error at every point
  const MeasuredDimensions m = ReadMeasuredDimensions(tmp.write("own.csv", MeasuredFromSteps(r)));
  const DimensionComparison c = CompareDimensions(DimensionSeriesOf(r), m);
  ASSERT_EQ(c.points.size(), 9u);
  for (const DimensionComparisonPoint& p : c.points) {
    EXPECT_EQ(p.bracket.status, InterpolationStatus::Interpolated);
    EXPECT_NEAR(p.error_m, 0.0, 1e-12) << p.km << " " << to_string(p.dimension);
  }
  for (const DimensionErrorSummary& s : c.summary) {
    EXPECT_EQ(s.points, 3);
    EXPECT_LT(s.rms_error_m, 1e-12);
  }
  // the wear changed the dimensions, so a zero error is not trivial
  EXPECT_GT(std::abs(r.steps.back().dimensions.qr_m - r.initial_dimensions.qr_m) +
                std::abs(r.steps.back().dimensions.sd_m - r.initial_dimensions.sd_m),
            1e-6);

  // (b) profile: step 1 written as a Simpack file and read back as the "measured" profile at the step's km
  const std::string prw = tmp.path("step1.prw");
  SaveProfileSimpack(r.steps[0].wheel, prw);
  const Profile measured = LoadProfile(prw);
  const SimulatedProfile at1 = SimulatedProfileAt(r, r.steps[0].km);
  EXPECT_EQ(at1.step_before, 1);
  EXPECT_EQ(at1.step_after, 1);
  const ProfileDistanceResult d = MeasureProfileDistance(at1.profile, measured, r.initial_wheel);
  ASSERT_EQ(d.status, ProfileDistanceStatus::Measured);
  EXPECT_GT(d.points, 50);  // the worn zone (> 0.01 mm) of a 0.4 mm step
  EXPECT_LT(d.max_m, 1e-7);
  EXPECT_LT(d.rms_m, 1e-7);

  // halfway between the steps, the blended profile lies halfway: its distance to step 1 is half of step 2's
  const double km_mid = 0.5 * (r.steps[0].km + r.steps[1].km);
  const SimulatedProfile mid = SimulatedProfileAt(r, km_mid);
  EXPECT_EQ(mid.step_before, 1);
  EXPECT_EQ(mid.step_after, 2);
  EXPECT_NEAR(mid.bracket.weight, 0.5, 1e-12);
  ProfileDistanceOptions zone;
  zone.lateral_range_m = std::array<double, 2>{-45e-3, 50e-3};
  const ProfileDistanceResult full = MeasureProfileDistance(r.steps[0].wheel, r.steps[1].wheel, Profile(), zone);
  const ProfileDistanceResult half = MeasureProfileDistance(r.steps[0].wheel, mid.profile, Profile(), zone);
  EXPECT_GT(full.max_m, 0.2e-3);
  EXPECT_NEAR(half.max_m, 0.5 * full.max_m, 0.02 * full.max_m);
  EXPECT_NEAR(half.mean_signed_m, 0.5 * full.mean_signed_m, 0.02 * std::abs(full.mean_signed_m));
  const SimulatedProfile nearest = SimulatedProfileAt(r, km_mid * 0.999, ProfileInterpolation::Nearest);
  EXPECT_EQ(nearest.step_before, 1);
  EXPECT_EQ(SimulatedProfileAt(r, r.steps[1].km * 1.01).bracket.status, InterpolationStatus::BeyondSimulation);
}

// The command itself on the tiny scenario with its own step output as the measured file: files written and zero
// error in validate.json.
TEST(ValidateEndToEnd, CommandLineSmoke) {
  TempDir tmp;
  const std::string yaml = tmp.write("tiny.yaml", TinyScenarioYaml());
  const WearSimulationResult r = TwoHertzSteps(LoadScenario(yaml));
  ASSERT_EQ(r.steps.size(), 2u) << r.message;
  const std::string measured = tmp.write("own.csv", MeasuredFromSteps(r));
  const std::string prw = tmp.path("step2.prw");
  SaveProfileSimpack(r.steps[1].wheel, prw);
  std::ostringstream at;
  at << std::setprecision(17) << r.steps[1].km;
  const std::string out = tmp.path("out");
  const std::string cmd = std::string(CONFORMA_CLI) + " validate --scenario '" + yaml + "' --measured '" + measured +
                          "' --measured-profile '" + prw + "@" + at.str() + "' --models hertz --steps 2 --out '" + out +
                          "' > '" + tmp.path("log.txt") + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  for (const char* f : {"validate.csv", "validate.json", "report.md", "validate_profiles.csv", "hertz/steps.csv"})
    EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
  nlohmann::json j;
  std::ifstream(out + "/validate.json") >> j;
  const auto& h = j["models"]["hertz"];
  for (const char* dim : {"Sd", "Sh", "qR"}) {
    EXPECT_EQ(h["dimensions"][dim]["points"].get<int>(), 3) << dim;
    EXPECT_LT(h["dimensions"][dim]["rms_error_mm"].get<double>(), 1e-9) << dim;
  }
  EXPECT_EQ(h["profiles"][0]["status"].get<std::string>(), "measured");
  EXPECT_LT(h["profiles"][0]["max_mm"].get<double>(), 1e-4);
  std::ifstream csv(out + "/validate.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("model,km,dimension,simulated_mm,measured_mm,error_mm", 0), 0u) << header;
}

}  // namespace
}  // namespace conforma
