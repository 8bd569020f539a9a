// Rail steps of the wear loop (paper 003 §6 and Fig. 11; rail_step_summary.hpp): the rail's removed area is the
// weighted mean of the virtual rails' areas, every wheel and rail profile stays valid, each rail step restarts the
// wheel sequence from the scenario's wheel.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "conforma/rail_step_summary.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {
namespace {

const std::string kDir = std::string(CONFORMA_SOURCE_DIR) + "/scenarios/";

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

// The rail-step scenario with the kinematic curving estimate (no Ceres) and 3 rail steps of 2 wheel steps each:
// a small run (hertz) for a unit test; the full 10-step run is reported in docs/physics-reference.md §8.8.
Scenario SmallRailStepRun() {
  Scenario s = LoadScenario(kDir + "metro_rail_steps.yaml");
  s.kinematics.provider = KinematicsProvider::Kinematic;
  s.kinematics.tangent_phases = 2;
  s.rail_steps.steps = 3;
  s.update.steps = 2;
  s.update.total_km = 0.0;
  return s;
}

WearSimulationResult RunSmall() {
  WearSimulationOptions o;
  o.contact.model = ContactModel::Hertz;
  return RunWearSimulation(SmallRailStepRun(), o);
}

TEST(RailSteps, RailAreaIsTheMeanOfTheVirtualRailAreasAndEveryProfileIsValid) {
  const WearSimulationResult r = RunSmall();
  ASSERT_EQ(r.status, WearSimulationStatus::Completed) << r.message;
  ASSERT_EQ(r.steps.size(), 6u);
  ASSERT_EQ(r.rails.size(), 3u);
  for (const WearStepRecord& s : r.steps) EXPECT_TRUE(s.validity.valid) << s.rail_step << "/" << s.step << ": " << s.validity.reason;
  const std::vector<RailStepSummary> sum = SummariseRailSteps(r);
  ASSERT_EQ(sum.size(), 3u);
  double worst = 0.0;
  for (const RailStepSummary& k : sum) {
    EXPECT_EQ(k.wheel_steps, 2);
    EXPECT_TRUE(k.wheels_valid);
    for (int side = 0; side < 2; ++side) {
      const RailSideStepSummary& o = k.side[side];
      EXPECT_EQ(o.status, ProfileUpdateStatus::Updated) << "rail step " << k.rail_step << " side " << side;
      EXPECT_TRUE(o.valid);
      ASSERT_EQ(o.virtual_removed.size(), 2u);  // one virtual rail per wheel profile of the sequence
      // rail material was removed, by the rail cap (mean smoothed depth = cap; measured on the refitted profile)
      EXPECT_GT(o.removed.area_m2, 0.0);
      const double cap = SmallRailStepRun().rail_steps.cap_m;
      EXPECT_NEAR(o.removed.max_depth_m, cap, 0.02 * cap) << "rail step " << k.rail_step << " side " << side;
      // the identity: removed area of r_{k+1} = weighted mean of the virtual rails' removed areas, both measured
      // on the profiles along the normals of r_k
      EXPECT_LT(o.area_residual, 1e-9) << "rail step " << k.rail_step << " side " << side << ": " << o.removed.area_m2
                                       << " vs " << o.virtual_mean_area_m2;
      worst = std::max(worst, o.area_residual);
      // the virtual rails differ (the wheel changes along the sequence), so the identity is not trivial
      EXPECT_NE(o.virtual_removed[0].area_m2, o.virtual_removed[1].area_m2);
    }
  }
  RecordProperty("worst_area_residual", sci(worst));
}

// Paper 003 §6: "for each rail profile, the wheel wear evolution (from the initial unworn profile to the final
// worn profile) is simulated": the first wheel step of every rail step starts from the scenario's wheel w_0, so its
// depth against w_0 is one step's cap, not the cap of the whole previous sequence.
TEST(RailSteps, EveryRailStepRestartsTheWheelFromTheScenarioWheel) {
  const WearSimulationResult r = RunSmall();
  ASSERT_EQ(r.status, WearSimulationStatus::Completed) << r.message;
  const double cap = SmallRailStepRun().update.cap_m;
  int restarts = 0;
  for (size_t i = 0; i < r.steps.size(); ++i) {
    const WearStepRecord& s = r.steps[i];
    if (s.step != 1) continue;
    const RemovedAlongNormals d = MeasureRemovedAlongNormals(r.initial_wheel, s.wheel);
    EXPECT_LT(d.max_depth_m, 1.05 * cap) << "rail step " << s.rail_step;
    EXPECT_GT(d.max_depth_m, 0.9 * cap) << "rail step " << s.rail_step;
    if (i == 0) continue;
    // r.steps[i - 1] is the last wheel step of the previous rail step: a wheel that went on from that profile
    // would have removed more than it; a wheel restarted from w_0 removed about one step's worth (of two)
    ASSERT_EQ(r.steps[i - 1].rail_step, s.rail_step - 1);
    const RemovedAlongNormals before = MeasureRemovedAlongNormals(r.initial_wheel, r.steps[i - 1].wheel);
    EXPECT_LT(d.area_m2, 0.75 * before.area_m2) << "rail step " << s.rail_step;
    ++restarts;
  }
  EXPECT_EQ(restarts, 2);
}

}  // namespace
}  // namespace conforma
