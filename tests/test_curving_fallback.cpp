// The wear loop's curving provider (MakeScenarioKinematics, wear_simulation.hpp): an accepted quasi-static solve is
// returned and remembered per class; a class whose solve is not accepted reuses its last accepted solution, or the
// kinematic estimate when it has none; every such class is counted.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <atomic>
#include <memory>

#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {
namespace {

// The contact of the standard pipeline, or no contact at all (a solve that cannot be accepted).
struct SwitchableContact {
  std::shared_ptr<bool> fail = std::make_shared<bool>(false);
  WheelContactReport operator()(const WheelsetTrackGeometry& g, Side side, const WheelsetPose& pose,
                                const WheelsetVelocity& velocity, const WheelContactOptions& options) const {
    if (*fail) return WheelContactReport{};  // status NoContact
    return SolveWheelContact(g, side, pose, velocity, options);
  }
};

void ExpectSameSeries(const KinematicsSeries& a, const KinematicsSeries& b) {
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (size_t k = 0; k < a.samples.size(); ++k) {
    EXPECT_EQ(a.samples[k].pose.lateral_m, b.samples[k].pose.lateral_m);
    EXPECT_EQ(a.samples[k].pose.yaw_rad, b.samples[k].pose.yaw_rad);
    EXPECT_EQ(a.samples[k].velocity.axle_angular_velocity_rad_s, b.samples[k].velocity.axle_angular_velocity_rad_s);
  }
}

TEST(CurvingFallback, RejectedClassReusesItsLastAcceptedSolutionOrTheEstimate) {
  const Scenario sc = LoadScenario(CONFORMA_SOURCE_DIR "/scenarios/default_metro.yaml");
  ASSERT_EQ(sc.kinematics.provider, KinematicsProvider::QuasiStatic);
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  const int r400 = 2;  // the R 400 m class
  ASSERT_EQ(sc.classes[r400].curve_radius_m, 400.0);
  SwitchableContact contact;
  auto fallbacks = std::make_shared<std::atomic<int>>(0);
  const KinematicsFunction kin = MakeScenarioKinematics(sc, sc.model, contact, fallbacks);

  // 1. a converged solve is returned as it is (the quasi-static solution itself)
  const KinematicsSeries solved = kin(g, sc.classes[r400], r400);
  EXPECT_EQ(fallbacks->load(), 0);
  const QuasiStaticResult direct =
      SolveQuasiStaticCurving(sc.vehicle, g, sc.classes[r400], ScenarioQuasiStaticOptions(sc, sc.model));
  ASSERT_EQ(direct.status, QuasiStaticStatus::Converged);
  ExpectSameSeries(solved, direct.series);

  // 2. the same class without any contact: not accepted, its last accepted solution comes back
  *contact.fail = true;
  ExpectSameSeries(kin(g, sc.classes[r400], r400), solved);
  EXPECT_EQ(fallbacks->load(), 1);

  // 3. a class never accepted falls back to the kinematic estimate (leading wheelset at flange contact)
  const int r200 = 3;
  ExpectSameSeries(kin(g, sc.classes[r200], r200), KinematicCurvingEstimate(sc, g, sc.classes[r200]));
  EXPECT_EQ(fallbacks->load(), 2);
}

}  // namespace
}  // namespace conforma
