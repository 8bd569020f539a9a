// Scenario files (scenario.hpp): the shipped scenarios, unknown keys and bad values named with the file.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/scenario.hpp"

namespace conforma {
namespace {

const std::string kDir = std::string(CONFORMA_SOURCE_DIR) + "/scenarios/";

double ShareSum(const Scenario& s) {
  double sum = 0.0;
  for (const TrackClass& c : s.classes) sum += c.share;
  return sum;
}

TEST(Scenario, DefaultMetroAfterPaper003) {
  const Scenario s = LoadScenario(kDir + "default_metro.yaml");
  EXPECT_EQ(s.name, "default_metro");
  EXPECT_NEAR(s.vehicle.nominal_wheel_radius_m, 0.3555, 1e-12);  // 711 mm wheels
  EXPECT_NEAR(s.rail_inclination_rad, std::atan(1.0 / 20.0), 1e-15);
  EXPECT_EQ(s.rail_name, "50E4");
  EXPECT_EQ(s.wheel.kind(), ProfileKind::Wheel);
  EXPECT_EQ(s.rail.kind(), ProfileKind::Rail);
  EXPECT_NEAR(ShareSum(s), 1.0, 1e-12);
  // a largely straight line (paper 003 §7): a duty cycle on tangent track and 1 % of R 400 m (§8.11)
  ASSERT_EQ(s.classes.size(), 4u);
  double tangent = 0.0;
  for (const TrackClass& c : s.classes) tangent += c.curve_radius_m == 0.0 ? c.share : 0.0;
  EXPECT_NEAR(tangent, 0.99, 1e-12);  // percent normalised
  EXPECT_EQ(s.classes[3].curve_radius_m, 400.0);
  EXPECT_NEAR(s.classes[3].cant_m, 0.090, 1e-12);
  // traction and braking at +-1 m/s^2: T = m a r0 on every axle, equal and opposite
  EXPECT_GT(s.classes[1].axle_torque_Nm, 0.0);
  EXPECT_EQ(s.classes[2].axle_torque_Nm, -s.classes[1].axle_torque_Nm);
  EXPECT_EQ(s.classes[0].axle_torque_Nm, 0.0);
  // paper 003's figures for the compare report
  ASSERT_NE(s.published.find("conformal"), nullptr);
  ASSERT_NE(s.published.find("hertz"), nullptr);
  EXPECT_EQ(s.published.steps, 7);
  EXPECT_LT(s.published.find("conformal")->km, s.published.find("hertz")->km);
  EXPECT_NEAR(s.update.cap_m, 0.4e-3, 1e-15);
  EXPECT_TRUE(s.rail_steps.fixed);
  EXPECT_EQ(s.model, ContactModel::Conformal);
}

TEST(Scenario, MetroRailStepsUpdatesTheRail) {
  const Scenario s = LoadScenario(kDir + "metro_rail_steps.yaml");
  const Scenario base = LoadScenario(kDir + "metro_curves.yaml");
  EXPECT_EQ(s.name, "metro_rail_steps");
  EXPECT_FALSE(s.rail_steps.fixed);
  EXPECT_EQ(s.rail_steps.steps, 10);
  EXPECT_NEAR(s.rail_steps.cap_m, 0.1e-3, 1e-15);
  EXPECT_NEAR(s.rail_steps.output_spacing_m, 0.025e-3, 1e-15);
  // the same vehicle, track, profiles and line as the metro case with curves
  EXPECT_EQ(s.rail_name, base.rail_name);
  EXPECT_EQ(s.wheel_name, base.wheel_name);
  EXPECT_EQ(s.vehicle.bogie_count, base.vehicle.bogie_count);
  EXPECT_NEAR(s.rail_inclination_rad, base.rail_inclination_rad, 0.0);
  ASSERT_EQ(s.classes.size(), base.classes.size());
  for (size_t c = 0; c < s.classes.size(); ++c) {
    EXPECT_EQ(s.classes[c].name, base.classes[c].name);
    EXPECT_NEAR(s.classes[c].share, base.classes[c].share, 0.0);
  }
  EXPECT_NEAR(s.update.cap_m, base.update.cap_m, 0.0);
  EXPECT_TRUE(base.rail_steps.fixed);  // metro_curves keeps the rail fixed
  EXPECT_EQ(base.rail_steps.output_spacing_m, 0.0);
}

TEST(Scenario, AostaFromTheMeasuredClassTable) {
  const Scenario s = LoadScenario(kDir + "aosta_aln501.yaml");
  ASSERT_EQ(s.classes.size(), 18u);  // 17 curve classes + the straight remainder
  EXPECT_EQ(s.classes[0].name, "tangent");
  // curve shares of track_classes.csv sum to 67.73 %: the straight part is 32.27 %
  EXPECT_NEAR(s.classes[0].share, 0.3227, 1e-9);
  EXPECT_NEAR(ShareSum(s), 1.0, 1e-12);
  EXPECT_NEAR(s.classes[8].curve_radius_m, 200.0, 0.0);
  EXPECT_NEAR(s.classes[8].share, 0.2064, 1e-12);
  EXPECT_NEAR(s.update.total_km, 3500.0, 0.0);
  EXPECT_EQ(s.vehicle.bogie_count, 2);
}

void ExpectError(const std::string& yaml, const std::string& fragment) {
  try {
    ParseScenario(yaml, "bad.yaml");
    FAIL() << "no error for: " << yaml;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad.yaml"), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
  }
}

const char* kClasses = "track_classes: [{radius_m: 0, speed_kmh: 60, share: 1}]\n";

TEST(Scenario, UnknownKeysAndBadValuesAreNamed) {
  ExpectError(std::string("colour: red\n") + kClasses, "colour");
  ExpectError(std::string("update: {cap_mm: 0.4, stepz: 3}\n") + kClasses, "stepz");
  ExpectError(std::string("vehicle: {base: metro, wheel_base_m: 2}\n") + kClasses, "wheel_base_m");
  ExpectError("track_classes: [{radius_m: 0, speed_kmh: 60, share: 1, cant: 3}]\n", "cant");
  ExpectError(std::string("update: {cap_mm: abc}\n") + kClasses, "update.cap_mm");
  ExpectError(std::string("update: {cap_mm: -1}\n") + kClasses, "cap_mm");
  ExpectError(std::string("contact_model: fem\n") + kClasses, "fem");
  ExpectError(std::string("rail: {fixed: false, steps: 2, spacing_mm: -0.1}\n") + kClasses, "rail.spacing_mm");
  ExpectError(std::string("rail: {fixed: false, steps: 0}\n") + kClasses, "rail.steps");
  ExpectError(std::string("kinematics: {contact_model: fem}\n") + kClasses, "kinematics.contact_model");
  ExpectError("track_classes: [{radius_m: 0, share: 1}]\n", "speed_kmh");
  ExpectError("name: x\n", "no track classes");
  ExpectError(std::string("profiles: {rail: /nonexistent/rail.prr}\n") + kClasses, "rail.prr");
  ExpectError(std::string("load_tolerance: 0\n") + kClasses, "load_tolerance");
  ExpectError(std::string("load_acceptance: -0.1\n") + kClasses, "load_acceptance");
  ExpectError(std::string("load_balance: consistent\n") + kClasses, "load_balance");
  ExpectError(std::string("kp_spin_about_centre: maybe\n") + kClasses, "kp_spin_about_centre");
  ExpectError(std::string("kp_local_flexibilities: [1]\n") + kClasses, "kp_local_flexibilities");
  ExpectError(std::string("update: {overhang_cut: keep}\n") + kClasses, "update.overhang_cut");
  ExpectError(std::string("kinematics: {dynamic: {steps_per_s_max: 0}}\n") + kClasses,
              "kinematics.dynamic.steps_per_s_max");
}

// --set: the file with keys replaced (a scalar, a flow map creating a missing map), the source naming them; the same
// checks as the file's keys, and malformed overrides named.
TEST(Scenario, OverridesReplaceKeysOfTheFile) {
  const std::string file = kDir + "default_metro.yaml";
  const Scenario s = LoadScenario(file, {"kinematics.provider=dynamic", "load_tolerance=1.1e-6",
                                         "kinematics.dynamic={contact: lut, duration_s: 64, sample_interval_s: 0.32}"});
  const Scenario base = LoadScenario(file);
  EXPECT_EQ(s.kinematics.provider, KinematicsProvider::Dynamic);
  EXPECT_EQ(base.kinematics.provider, KinematicsProvider::QuasiStatic);
  EXPECT_EQ(s.load_tolerance, 1.1e-6);
  EXPECT_TRUE(s.kinematics.dynamic.lut_contact);
  EXPECT_EQ(s.kinematics.dynamic.duration_s, 64.0);
  EXPECT_EQ(s.kinematics.dynamic.sample_interval_s, 0.32);
  EXPECT_EQ(s.kinematics.dynamic.settle_s, base.kinematics.dynamic.settle_s);  // the map's other keys: defaults
  // everything else as in the file
  EXPECT_EQ(s.classes.size(), base.classes.size());
  EXPECT_EQ(s.kinematics.contact_model, base.kinematics.contact_model);
  EXPECT_EQ(s.update.cap_m, base.update.cap_m);
  EXPECT_NE(s.source.find("--set load_tolerance=1.1e-6"), std::string::npos) << s.source;
  EXPECT_EQ(LoadScenario(file, {}).source, file);
  auto expect_error = [&](const std::string& item, const std::string& named) {
    try {
      LoadScenario(file, {item});
      ADD_FAILURE() << item << ": no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
    }
  };
  expect_error("kinematics.provider", "expected KEY=VALUE");
  expect_error("=dynamic", "expected KEY=VALUE");
  expect_error("load_tolerance=", "value is empty");
  expect_error("kinematics..provider=dynamic", "empty part");
  expect_error("name.first=x", "'name' is not a map");
  expect_error("kinematics.colour=red", "colour");           // unknown key, as in the file
  expect_error("load_tolerance=-1", "load_tolerance");        // bad value, as in the file
  expect_error("kinematics.dynamic={contact: [", "not YAML");
}

TEST(Scenario, MinimalFileTakesTheDefaults) {
  const Scenario s = ParseScenario(kClasses, "mini.yaml");
  EXPECT_EQ(s.classes.size(), 1u);
  EXPECT_EQ(s.update.steps, 20);
  EXPECT_EQ(s.kinematics.provider, KinematicsProvider::QuasiStatic);
  EXPECT_NEAR(s.classes[0].friction_coefficient, 0.3, 0.0);
  EXPECT_FALSE(s.kinematics.contact_model_set);  // the curving solve uses the wear step's model
  EXPECT_NEAR(s.load_tolerance, 1e-6, 0.0);         // WheelContactOptions' default
  EXPECT_NEAR(s.load_acceptance, 0.10, 0.0);        // StepWearOptions' default
  EXPECT_EQ(s.load_balance, LoadBalance::Total);    // WheelContactOptions' default
  EXPECT_TRUE(s.update.overhang_cut_conserves_area);  // ProfileUpdateOptions' default
  EXPECT_FALSE(ParseScenario(std::string("update: {overhang_cut: wear_off}\n") + kClasses, "w.yaml")
                   .update.overhang_cut_conserves_area);
  EXPECT_EQ(ParseScenario(std::string("load_balance: total-consistent\n") + kClasses, "c.yaml").load_balance,
            LoadBalance::TotalConsistent);
  // the KP FASTSIM variants: off as in WheelContactOptions, and what ApplyScenarioContact passes on
  WheelContactOptions o;
  ApplyScenarioContact(s, &o);
  EXPECT_FALSE(o.kp_spin_about_patch_centre);
  EXPECT_FALSE(o.kp_local_flexibilities);
  EXPECT_EQ(o.load_balance, LoadBalance::Total);
  const Scenario v =
      ParseScenario(std::string("kp_spin_about_centre: true\nkp_local_flexibilities: true\nload_tolerance: 2e-6\n") +
                        kClasses,
                    "v.yaml");
  ApplyScenarioContact(v, &o);
  EXPECT_TRUE(o.kp_spin_about_patch_centre);
  EXPECT_TRUE(o.kp_local_flexibilities);
  EXPECT_NEAR(o.load_tolerance, 2e-6, 0.0);
}

TEST(Scenario, CurvingContactModelIsSeparateFromTheWearModel) {
  const Scenario s =
      ParseScenario(std::string("contact_model: conformal\nkinematics: {contact_model: hertz}\n") + kClasses, "k.yaml");
  EXPECT_EQ(s.model, ContactModel::Conformal);
  EXPECT_TRUE(s.kinematics.contact_model_set);
  EXPECT_EQ(s.kinematics.contact_model, ContactModel::Hertz);
  EXPECT_EQ(ParseScenario(std::string("contact_model: auto\n") + kClasses, "a.yaml").model, ContactModel::Auto);
}

TEST(Scenario, ClassAccelerationIsTheTorqueThatAcceleratesTheCarriedMass) {
  // T = m a r0 per axle, every axle driven alike (scenario.hpp track_classes; docs/physics-reference.md §12.3)
  const Scenario s = ParseScenario(
      "track_classes: [{radius_m: 0, speed_kmh: 60, share: 1, acceleration_m_s2: 0.8},\n"
      "                {radius_m: 0, speed_kmh: 60, share: 1, acceleration_m_s2: -1.1},\n"
      "                {radius_m: 0, speed_kmh: 60, share: 1, axle_torque_Nm: 1234.5},\n"
      "                {radius_m: 0, speed_kmh: 60, share: 1}]\n",
      "duty.yaml");
  ASSERT_EQ(s.classes.size(), 4u);
  const double m = s.vehicle.carried_mass_per_wheelset_kg(), r0 = s.vehicle.nominal_wheel_radius_m;
  EXPECT_NEAR(s.classes[0].axle_torque_Nm, m * 0.8 * r0, 1e-9 * m * r0);
  EXPECT_NEAR(s.classes[1].axle_torque_Nm, -m * 1.1 * r0, 1e-9 * m * r0);
  EXPECT_EQ(s.classes[2].axle_torque_Nm, 1234.5);
  EXPECT_EQ(s.classes[3].axle_torque_Nm, 0.0);  // free rolling unless the class says otherwise
  ExpectError("track_classes: [{radius_m: 0, speed_kmh: 60, share: 1, acceleration_m_s2: 1, axle_torque_Nm: 3}]\n",
              "not both");
  ExpectError("track_classes: [{radius_m: 0, speed_kmh: 60, share: 1, acceleration_m_s2: x}]\n", "acceleration_m_s2");
  // the providers that impose the axle speed cannot carry a drive torque: said, not ignored
  ExpectError("kinematics: {provider: centred}\ntrack_classes: [{radius_m: 0, speed_kmh: 60, share: 1, "
              "acceleration_m_s2: 1}]\n",
              "drive torque");
  ExpectError("kinematics: {free_axle_rotation: false}\ntrack_classes: [{radius_m: 0, speed_kmh: 60, share: 1, "
              "acceleration_m_s2: 1}]\n",
              "drive torque");
}

}  // namespace
}  // namespace conforma
