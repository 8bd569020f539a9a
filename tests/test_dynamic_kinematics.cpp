// Kinematics provider `dynamic` (dynamic_kinematics.hpp): on a perfect steady curve the time-domain samples are the
// quasi-static curving equilibrium (the two models share the equations at constant curvature, docs/physics-reference.md
// §16.5); with a seeded irregularity the contact position spreads and the same seed gives the same samples bit for bit;
// weights sum to 1 per wheelset; bad kinematics.dynamic keys are InputErrors naming the key.
// test-links: dynamics

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "conforma/dynamic_kinematics.hpp"
#include "conforma/error.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {
namespace {

// One bogie of the metro vehicle (cost), S1002 / 50E4 1:20, Hertz + FASTSIM in the dynamics.
std::string ScenarioText(const std::string& dynamic, const std::string& radius, const std::string& extra = "") {
  return "name: dyn\n"
         "vehicle: {base: metro, bogie_count: 1}\n"
         "kinematics: {provider: dynamic, contact_model: hertz, dynamic: " + dynamic + "}\n"
         "profiles: {wheel: S1002, rail: 50E4, wheel_radius_mm: 355.5}\n"
         "contact_model: hertz\n" + extra +
         "track_classes:\n"
         "  - {name: c, radius_m: " + radius + ", cant_mm: 40, speed_kmh: 54, share: 100}\n";
}

std::map<int, double> WeightSums(const KinematicsSeries& s) {
  std::map<int, double> sum;
  for (const KinematicsSample& k : s.samples) sum[k.wheelset] += k.weight;
  return sum;
}

TEST(DynamicKinematics, PerfectCurveSamplesAreTheQuasiStaticEquilibrium) {
  const Scenario sc = ParseScenario(
      ScenarioText("{duration_s: 0.2, settle_s: 0.3, sample_interval_s: 0.05, irregularity: none}", "600"), "test");
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  const TrackClass& tc = sc.classes[0];
  const DynamicClassKinematics r = SimulateClassKinematics(sc, g, tc, ContactModel::Hertz, &SolveWheelContact);
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_TRUE(r.quasistatic_start);
  const QuasiStaticResult qs =
      SolveQuasiStaticCurving(sc.vehicle, g, tc, ScenarioQuasiStaticOptions(sc, ContactModel::Hertz));
  ASSERT_EQ(qs.status, QuasiStaticStatus::Converged);
  ASSERT_EQ(r.series.samples.size(), 2u * 5u);  // t = 0.30, 0.35, ..., 0.50 s, two wheelsets
  for (const KinematicsSample& k : r.series.samples) {
    const WheelsetQuasiStaticReport& w = qs.wheelsets[k.wheelset];
    EXPECT_NEAR(k.pose.lateral_m, w.pose.lateral_m, 0.2e-3) << "ws " << k.wheelset << " t " << k.time_s;
    EXPECT_NEAR(k.pose.yaw_rad, w.pose.yaw_rad, 0.2e-3) << "ws " << k.wheelset << " t " << k.time_s;
    EXPECT_NEAR(k.pose.vertical_m, w.pose.vertical_m, 0.05e-3);
    EXPECT_NEAR(k.velocity.yaw_rate_rad_s, tc.speed_m_s / 600.0, 1e-4);
    EXPECT_DOUBLE_EQ(k.track_curvature_per_m, 1.0 / 600.0);
    EXPECT_NEAR(k.vertical_load_N[0], w.wheel[0].vertical_load_N, 1e-6 * w.wheel[0].vertical_load_N);
    EXPECT_NEAR(k.vertical_load_N[1], w.wheel[1].vertical_load_N, 1e-6 * w.wheel[1].vertical_load_N);
  }
  for (const auto& [ws, sum] : WeightSums(r.series)) EXPECT_NEAR(sum, 1.0, 1e-12) << "ws " << ws;
}

TEST(DynamicKinematics, IrregularitySpreadsTheContactAndTheSeedReproducesIt) {
  const std::string irr = "{spectrum: ore_b176_high, seed: 7, wavelength_min_m: 3, wavelength_max_m: 70}";
  const Scenario sc = ParseScenario(
      ScenarioText("{duration_s: 0.6, settle_s: 0.2, sample_interval_s: 0.02, irregularity: " + irr + "}", "0"), "test");
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  const KinematicsFunction kin = MakeWearKinematics(sc, ContactModel::Hertz, &SolveWheelContact, nullptr);
  const KinematicsSeries a = kin(g, sc.classes[0], 0);
  const KinematicsSeries b = kin(g, sc.classes[0], 0);
  ASSERT_EQ(a.samples.size(), 2u * 31u);
  double mean = 0.0, var = 0.0;
  int n = 0;
  for (const KinematicsSample& k : a.samples)
    if (k.wheelset == 0) mean += k.pose.lateral_m, ++n;
  mean /= n;
  for (const KinematicsSample& k : a.samples)
    if (k.wheelset == 0) var += (k.pose.lateral_m - mean) * (k.pose.lateral_m - mean) / n;
  EXPECT_GT(std::sqrt(var), 1e-6) << "std dev of the leading wheelset's lateral shift relative to the track";
  std::printf("leading wheelset on tangent track, ORE B176 high 3-70 m: y mean %.4f mm, std dev %.4f mm\n", 1e3 * mean,
              1e3 * std::sqrt(var));
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (size_t i = 0; i < a.samples.size(); ++i) {
    const KinematicsSample &p = a.samples[i], &q = b.samples[i];
    EXPECT_EQ(p.pose.lateral_m, q.pose.lateral_m);
    EXPECT_EQ(p.pose.yaw_rad, q.pose.yaw_rad);
    EXPECT_EQ(p.pose.roll_rad, q.pose.roll_rad);
    EXPECT_EQ(p.velocity.lateral_velocity_m_s, q.velocity.lateral_velocity_m_s);
    EXPECT_EQ(p.velocity.yaw_rate_rad_s, q.velocity.yaw_rate_rad_s);
    EXPECT_EQ(p.velocity.axle_angular_velocity_rad_s, q.velocity.axle_angular_velocity_rad_s);
    EXPECT_EQ(p.vertical_load_N[0], q.vertical_load_N[0]);
    EXPECT_EQ(p.vertical_load_N[1], q.vertical_load_N[1]);
  }
  for (const auto& [ws, sum] : WeightSums(a)) EXPECT_NEAR(sum, 1.0, 1e-12) << "ws " << ws;
}

TEST(DynamicKinematics, FailedIntegrationFallsBackWithItsReason) {
  const Scenario sc = ParseScenario(
      ScenarioText("{duration_s: 0.2, settle_s: 0.1, sample_interval_s: 0.05, irregularity: none}", "600"), "test");
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  // a contact that never solves: the quasi-static start and the integration both fail
  const WearContactFunction broken = [](const WheelsetTrackGeometry&, Side, const WheelsetPose&, const WheelsetVelocity&,
                                        const WheelContactOptions&) { return WheelContactReport{}; };
  const DynamicClassKinematics r = SimulateClassKinematics(sc, g, sc.classes[0], ContactModel::Hertz, broken);
  EXPECT_FALSE(r.failure.empty());
  EXPECT_NE(r.status, DynamicsStatus::Completed);
  EXPECT_TRUE(r.series.samples.empty());
  auto log = std::make_shared<KinematicsFallbackLog>();
  const KinematicsFunction kin = MakeWearKinematics(sc, ContactModel::Hertz, broken, log);
  const KinematicsSeries s = kin(g, sc.classes[0], 0);
  ASSERT_EQ(log->size(), 1u);
  const KinematicsFallbackLog::Entry e = log->since(0)[0];
  EXPECT_EQ(e.replacement, "kinematic estimate");
  EXPECT_NE(e.reason.find("dynamics"), std::string::npos) << e.reason;
  const KinematicsSeries estimate = KinematicCurvingEstimate(sc, g, sc.classes[0]);
  ASSERT_EQ(s.samples.size(), estimate.samples.size());
  for (size_t i = 0; i < s.samples.size(); ++i) EXPECT_EQ(s.samples[i].pose.lateral_m, estimate.samples[i].pose.lateral_m);
}

TEST(DynamicKinematics, BadKeysAreInputErrorsNamingTheKey) {
  const std::pair<std::string, std::string> cases[] = {
      {"{duration_s: -1}", "kinematics.dynamic.duration_s"},
      {"{settle_s: -0.1}", "kinematics.dynamic.settle_s"},
      {"{sample_interval_s: 0}", "kinematics.dynamic.sample_interval_s"},
      {"{duration_s: 1, sample_interval_s: 2}", "kinematics.dynamic.sample_interval_s"},
      {"{stepper: euler}", "kinematics.dynamic.stepper"},
      {"{irregularity: bumpy}", "kinematics.dynamic.irregularity"},
      {"{irregularity: {spectrum: moon}}", "kinematics.dynamic.irregularity.spectrum"},
      {"{irregularity: {seed: -3}}", "kinematics.dynamic.irregularity.seed"},
      {"{irregularity: {wavelength_min_m: 10, wavelength_max_m: 5}}", "kinematics.dynamic.irregularity.wavelength_max_m"},
      {"{irregularity: {colour: red}}", "colour"},
      {"{durations: 3}", "durations"},
  };
  for (const auto& [yaml, key] : cases) {
    try {
      ParseScenario(ScenarioText(yaml, "600"), "test");
      ADD_FAILURE() << yaml << ": no InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << yaml << ": " << e.what();
    }
  }
  // the defaults
  const Scenario sc = ParseScenario(ScenarioText("{}", "600"), "test");
  EXPECT_EQ(sc.kinematics.provider, KinematicsProvider::Dynamic);
  EXPECT_EQ(sc.kinematics.dynamic.duration_s, 4.0);
  EXPECT_EQ(sc.kinematics.dynamic.settle_s, 1.0);
  EXPECT_EQ(sc.kinematics.dynamic.sample_interval_s, 0.02);
  EXPECT_TRUE(sc.kinematics.dynamic.irregularity);
  EXPECT_EQ(sc.kinematics.dynamic.spectrum, IrregularitySpectrum::OreB176Low);
  // the simulation layer cannot make it: an error, not a silent other provider
  EXPECT_THROW(MakeScenarioKinematics(sc, ContactModel::Hertz, &SolveWheelContact), InputError);
}

}  // namespace
}  // namespace conforma
