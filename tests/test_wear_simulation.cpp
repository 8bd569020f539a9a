// Wear loop (wear_simulation.hpp): valid profiles after several steps for every model, the cap, the same result for
// any thread count, and an exported + re-imported kinematics file giving the same wear as the direct run.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <string>

#include "conforma/kinematics_import.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {
namespace {

const std::string kDir = std::string(CONFORMA_SOURCE_DIR) + "/scenarios/";

// Default metro scenario with the kinematic curving estimate (no Ceres): fast enough for a unit test (the CLI run
// with the quasi-static provider is reported in the issue).
Scenario FastMetro() {
  Scenario s = LoadScenario(kDir + "metro_curves.yaml");
  s.kinematics.provider = KinematicsProvider::Kinematic;
  s.kinematics.tangent_phases = 2;
  return s;
}

// The kinematic estimate keeps the leading wheelset at flange contact in every curve, which concentrates the
// flange wear more than the quasi-static provider: with the default 5 mm smoothing the Hertz run reaches the
// 1000 1/m kink limit at step 9, so the long test uses 8 mm (a documented scenario parameter, update.smoothing_mm).
Scenario FastMetroSmoothed() {
  Scenario s = FastMetro();
  s.update.smoothing_cutoff_m = 8e-3;
  return s;
}

// Wheel profile is single-valued in y from the flange tip to the field side (tread and flange face).
bool SingleValuedAfterTip(const Profile& p) {
  const std::vector<Eigen::Vector2d> pts = p.sample(0.1e-3);
  size_t tip = 0;
  for (size_t i = 0; i < pts.size(); ++i)
    if (pts[i][1] > pts[tip][1]) tip = i;
  for (size_t i = tip + 1; i < pts.size(); ++i)
    if (!(pts[i][0] > pts[i - 1][0])) return false;
  return true;
}

TEST(WearSimulation, ValidProfilesAndCapForEveryModel) {
  const Scenario sc = FastMetroSmoothed();
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Conformal}) {
    WearSimulationOptions o;
    o.contact.model = m;
    o.steps = 15;
    o.total_km = 0.0;
    const WearSimulationResult r = RunWearSimulation(sc, o);
    ASSERT_EQ(r.status, WearSimulationStatus::Completed) << to_string(m) << ": " << r.message;
    ASSERT_EQ(r.steps.size(), 15u);
    double km = 0.0;
    int failed = 0, wheels = 0;  // wheels whose contact failed in the pipeline (no wear from them): reported
    for (const WearStepRecord& s : r.steps) {
      EXPECT_TRUE(s.validity.valid) << to_string(m) << " step " << s.step << ": " << s.validity.reason;
      // kink criterion stated in the scenario: |curvature| <= 1000 1/m (radius >= 1 mm)
      EXPECT_LE(s.validity.max_abs_curvature_1_m, sc.update.max_curvature_1_m) << to_string(m) << " step " << s.step;
      EXPECT_TRUE(SingleValuedAfterTip(s.wheel)) << to_string(m) << " step " << s.step;
      EXPECT_EQ(s.depth_cap_m, sc.update.cap_m);                             // no step needed a smaller cap
      EXPECT_NEAR(s.max_depth_m, sc.update.cap_m, 0.01 * sc.update.cap_m);  // largest depth = cap within 1 %
      EXPECT_GT(s.step_km, 0.0);
      // every wear patch counted under the model that solved it: this model, or Hertz for the wheels that fell
      // back to it (StepWearOptions::hertz_fallback)
      for (int k = 0; k < kContactModelCount; ++k) {
        const ContactModel counted = static_cast<ContactModel>(k);
        if (counted == m) {
          EXPECT_GT(s.patches_by_model[k], 0) << to_string(m);
        } else if (counted != ContactModel::Hertz || s.hertz_fallback_contacts == 0) {
          EXPECT_EQ(s.patches_by_model[k], 0) << to_string(m) << " counted as " << to_string(counted);
        }
      }
      km += s.step_km;
      EXPECT_NEAR(s.km, km, 1e-9 * km);
      failed += s.failed_contacts;
      wheels += s.samples + s.failed_contacts;
    }
    // wear only removes material: no point of the worn profile lies outside the initial one (depth of the initial
    // profile measured along the worn profile's normals <= resampling tolerance), and the largest depth is at
    // least one cap (Sd may grow: it is measured 10 mm above the worn taping line)
    const WheelWearDepths added = MeasureWheelWear(r.steps.back().wheel, r.initial_wheel);
    EXPECT_LE(std::max(added.tread_m, added.flange_m), 2e-6) << to_string(m);
    EXPECT_GE(std::max(r.steps.back().tread_wear_m, r.steps.back().flange_wear_m), 0.99 * sc.update.cap_m);
    RecordProperty(std::string(to_string(m)) + "_failed_wheel_contacts", std::to_string(failed) + "/" + std::to_string(wheels));
    std::printf("%s: failed wheel contacts %d of %d\n", to_string(m), failed, wheels);
    std::printf("%s: 15 steps %.0f km, Sd %.3f qR %.3f tread %.3f flange %.3f mm\n", to_string(m), r.steps.back().km,
                r.steps.back().dimensions.sd_m * 1e3, r.steps.back().dimensions.qr_m * 1e3,
                r.steps.back().tread_wear_m * 1e3, r.steps.back().flange_wear_m * 1e3);
  }
}

TEST(WearSimulation, TotalKmShortensTheLastStep) {
  const Scenario sc = FastMetroSmoothed();
  WearSimulationOptions o;
  o.contact.model = ContactModel::Hertz;
  o.steps = 10;
  o.total_km = 1500.0;
  const WearSimulationResult r = RunWearSimulation(sc, o);
  ASSERT_EQ(r.status, WearSimulationStatus::Completed) << r.message;
  ASSERT_GE(r.steps.size(), 2u);
  EXPECT_NEAR(r.steps.back().km, 1500.0, 1e-6);
  EXPECT_LT(r.steps.back().max_depth_m, sc.update.cap_m);  // the shortened step removes less than the cap
}

// update.substeps (docs/physics-reference.md §8.12): a step of cap D in 2 sub-steps is the same computation as two
// steps of cap D/2, grouped: the same profile and km bit for bit, the counters summed, and the step removes at most D.
TEST(WearSimulation, SubstepsAreFinerStepsGroupedUnderTheStepsCap) {
  Scenario grouped = FastMetroSmoothed();
  grouped.update.substeps = 2;
  Scenario fine = FastMetroSmoothed();
  fine.update.cap_m = 0.5 * grouped.update.cap_m;
  WearSimulationOptions o;
  o.contact.model = ContactModel::Hertz;
  o.total_km = 0.0;
  o.steps = 3;
  const WearSimulationResult a = RunWearSimulation(grouped, o);
  o.steps = 6;
  const WearSimulationResult b = RunWearSimulation(fine, o);
  ASSERT_EQ(a.status, WearSimulationStatus::Completed) << a.message;
  ASSERT_EQ(b.status, WearSimulationStatus::Completed) << b.message;
  ASSERT_EQ(a.steps.size(), 3u);
  ASSERT_EQ(b.steps.size(), 6u);
  for (size_t i = 0; i < a.steps.size(); ++i) {
    const WearStepRecord& s = a.steps[i];
    const WearStepRecord& f1 = b.steps[2 * i];
    const WearStepRecord& f2 = b.steps[2 * i + 1];
    EXPECT_EQ(s.km, f2.km) << "step " << s.step;
    EXPECT_NEAR(s.step_km, f1.step_km + f2.step_km, 1e-12 * s.km);
    EXPECT_EQ(s.samples, f1.samples + f2.samples);
    EXPECT_EQ(s.failed_contacts, f1.failed_contacts + f2.failed_contacts);
    EXPECT_EQ(s.depth_cap_m, f1.depth_cap_m + f2.depth_cap_m);
    ASSERT_EQ(s.wheel.sample_count(), f2.wheel.sample_count());
    for (size_t k = 0; k < s.wheel.sample_count(); ++k) EXPECT_EQ(s.wheel.sample_at(k), f2.wheel.sample_at(k));
    // the step's largest depth: at most the cap, and at least one sub-step's (equal to it where the two sub-steps'
    // deepest points lie apart)
    EXPECT_LE(s.max_depth_m, grouped.update.cap_m * (1.0 + 1e-6)) << "step " << s.step;
    EXPECT_GE(s.max_depth_m, fine.update.cap_m * (1.0 - 1e-3)) << "step " << s.step;
    EXPECT_EQ(s.tread_hollows, f2.tread_hollows);
    std::printf("step %d: %.1f km, largest depth %.3f mm\n", s.step, s.km, s.max_depth_m * 1e3);
  }
}

// Adaptive step: a run that stops at an invalid profile with a fixed cap continues past that step when the cap may be
// halved, every profile valid, and the repeated step removes exactly its (smaller) cap.
TEST(WearSimulation, InvalidProfileHalvesTheCapInsteadOfStopping) {
  Scenario sc = FastMetro();
  sc.update.smoothing_cutoff_m = 2e-3;  // little smoothing: the kink limit is reached within a few steps
  WearSimulationOptions o;
  o.contact.model = ContactModel::Hertz;
  o.steps = 12;
  o.total_km = 0.0;
  o.invalid_step_halvings = 0;
  const WearSimulationResult fixed = RunWearSimulation(sc, o);
  ASSERT_EQ(fixed.status, WearSimulationStatus::InvalidProfile) << "no invalid profile: the test needs less smoothing";
  const size_t failing_step = fixed.steps.size() + 1;
  o.invalid_step_halvings = 3;
  o.steps = static_cast<int>(failing_step);
  const WearSimulationResult adaptive = RunWearSimulation(sc, o);
  ASSERT_GE(adaptive.steps.size(), failing_step) << adaptive.message;
  for (size_t i = 0; i + 1 < failing_step; ++i)  // identical up to the failing step
    EXPECT_EQ(adaptive.steps[i].km, fixed.steps[i].km);
  const WearStepRecord& s = adaptive.steps[failing_step - 1];
  EXPECT_TRUE(s.validity.valid) << s.validity.reason;
  EXPECT_LT(s.depth_cap_m, sc.update.cap_m);
  EXPECT_NEAR(s.max_depth_m, s.depth_cap_m, 0.01 * s.depth_cap_m);
  std::printf("fixed cap stops at step %zu (%s); halved cap %.3f mm passes it\n", failing_step, fixed.message.c_str(),
              s.depth_cap_m * 1e3);
}

// Samples of a class with the same pose, velocity and loads (every wheelset on tangent track) are solved once; each
// keeps its own weight. Splitting every sample into two half-weight copies gives the same wear with the same number
// of contact solves; a copy one ulp off in yaw is solved on its own.
TEST(WearSimulation, RepeatedSamplesAreSolvedOnceAndKeepTheirOwnWeight) {
  const Scenario sc = FastMetro();
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  TrackClass tangent = sc.classes.front();
  ASSERT_EQ(tangent.curve_radius_m, 0.0);
  tangent.share = 1.0;  // the only class of the step
  const KinematicsSeries single = KinematicCurvingEstimate(sc, g, tangent);
  KinematicsSeries split;
  for (KinematicsSample s : single.samples) {
    s.weight *= 0.5;
    split.samples.push_back(s);
    split.samples.push_back(s);
  }
  StepWearOptions o;
  o.contact.model = ContactModel::Hertz;
  o.wear = sc.wear;
  std::atomic<int> calls{0};
  const WearContactFunction counted = [&calls](const WheelsetTrackGeometry& gg, Side side, const WheelsetPose& p,
                                               const WheelsetVelocity& v, const WheelContactOptions& co) {
    ++calls;
    return SolveWheelContact(gg, side, p, v, co);
  };
  const StepWear a = ComputeStepWear(g, {tangent}, {single}, o, counted);
  const int calls_single = calls.exchange(0);
  const StepWear b = ComputeStepWear(g, {tangent}, {split}, o, counted);
  EXPECT_EQ(calls.exchange(0), calls_single);
  EXPECT_EQ(b.samples, 2 * a.samples);
  const auto& da = a.wheel.wheel_depth_per_metre.depth_m;
  const auto& db = b.wheel.wheel_depth_per_metre.depth_m;
  ASSERT_EQ(da.size(), db.size());
  const double peak = a.wheel.wheel_depth_per_metre.max_depth_m();
  ASSERT_GT(peak, 0.0);
  for (size_t i = 0; i < da.size(); ++i) ASSERT_NEAR(db[i], da[i], 1e-12 * peak) << i;
  split.samples[1].pose.yaw_rad = std::nextafter(split.samples[1].pose.yaw_rad, 1.0);
  ComputeStepWear(g, {tangent}, {split}, o, counted);
  EXPECT_EQ(calls.load(), calls_single + 2);  // both wheels of the perturbed copy
}

TEST(WearSimulation, SameResultForAnyThreadCount) {
  const Scenario sc = FastMetro();
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  std::vector<KinematicsSeries> series;
  for (const TrackClass& c : sc.classes) series.push_back(KinematicCurvingEstimate(sc, g, c));
  StepWearOptions o;
  o.contact.model = ContactModel::Conformal;
  o.wear = sc.wear;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const StepWear a = ComputeStepWear(g, sc.classes, series, o, &SolveWheelContact);
  omp_set_num_threads(2);
  const StepWear b = ComputeStepWear(g, sc.classes, series, o, &SolveWheelContact);
  omp_set_num_threads(saved);
  ASSERT_EQ(a.wheel.wheel_depth_per_metre.size(), b.wheel.wheel_depth_per_metre.size());
  EXPECT_GT(a.wheel.wheel_depth_per_metre.max_depth_m(), 0.0);
  for (size_t i = 0; i < a.wheel.wheel_depth_per_metre.size(); ++i)
    ASSERT_EQ(a.wheel.wheel_depth_per_metre.depth_m[i], b.wheel.wheel_depth_per_metre.depth_m[i]) << i;
  for (int k = 0; k < 2; ++k)
    for (size_t i = 0; i < a.side[k].rail_depth_per_passage.size(); ++i)
      ASSERT_EQ(a.side[k].rail_depth_per_passage.depth_m[i], b.side[k].rail_depth_per_passage.depth_m[i]);
  // the two wheels are averaged: the wheel rate is the mean of the sides
  for (size_t i = 0; i < a.wheel.wheel_depth_per_metre.size(); i += 97)
    EXPECT_NEAR(a.wheel.wheel_depth_per_metre.depth_m[i],
                0.5 * (a.side[0].wheel_depth_per_metre.depth_m[i] + a.side[1].wheel_depth_per_metre.depth_m[i]), 1e-22);
}

TEST(WearSimulation, ExportedAndReimportedKinematicsGiveTheSameWear) {
  // quasi-static curving (hertz in the loop) on one curve and tangent track, exported to CSV and re-imported
  Scenario sc = LoadScenario(kDir + "metro_curves.yaml");
  sc.classes = {sc.classes[0], sc.classes[2]};
  sc.classes[0].share = 0.7;
  sc.classes[1].share = 0.3;
  sc.kinematics.tangent_phases = 2;
  const WearContactFunction contact = &SolveWheelContact;
  const KinematicsFunction direct = MakeScenarioKinematics(sc, ContactModel::Hertz, contact);
  const std::string dir = ::testing::TempDir();
  const KinematicsFunction via_file = [&](const WheelsetTrackGeometry& g, const TrackClass& tc, int c) {
    const std::string path = dir + "/conforma_kin_" + std::to_string(c) + ".csv";
    ExportKinematicsCsv(direct(g, tc, c), path);
    return ImportKinematicsCsv(path);
  };
  WearSimulationOptions o;
  o.contact.model = ContactModel::Hertz;
  o.steps = 2;
  o.total_km = 0.0;
  const WearSimulationResult a = RunWearSimulation(sc, o, contact, direct);
  const WearSimulationResult b = RunWearSimulation(sc, o, contact, via_file);
  ASSERT_EQ(a.status, WearSimulationStatus::Completed) << a.message;
  ASSERT_EQ(b.status, WearSimulationStatus::Completed) << b.message;
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (size_t j = 0; j < a.steps.size(); ++j) {
    EXPECT_NEAR(b.steps[j].km, a.steps[j].km, 1e-9 * a.steps[j].km);
    const WearDistribution& da = a.steps[j].wheel_depth_per_metre;
    const WearDistribution& db = b.steps[j].wheel_depth_per_metre;
    ASSERT_EQ(da.size(), db.size());
    const double scale = da.max_depth_m();
    ASSERT_GT(scale, 0.0);
    for (size_t i = 0; i < da.size(); ++i) ASSERT_NEAR(db.depth_m[i], da.depth_m[i], 1e-9 * scale) << "step " << j << " node " << i;
  }
}

}  // namespace
}  // namespace conforma
