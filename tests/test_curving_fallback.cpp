// The wear loop's curving provider (MakeScenarioKinematics, wear_simulation.hpp): an accepted quasi-static solve is
// returned and remembered per class; a class whose solve is not accepted reuses its last accepted solution, or the
// kinematic estimate when it has none; every such class is recorded with its reason.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <memory>

#include "conforma/kinematics_quasistatic.hpp"
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
  const Scenario sc = LoadScenario(CONFORMA_SOURCE_DIR "/scenarios/metro_curves.yaml");
  ASSERT_EQ(sc.kinematics.provider, KinematicsProvider::QuasiStatic);
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  const int r400 = 2;  // the R 400 m class
  ASSERT_EQ(sc.classes[r400].curve_radius_m, 400.0);
  SwitchableContact contact;
  auto fallbacks = std::make_shared<KinematicsFallbackLog>();
  const KinematicsFunction kin = MakeScenarioKinematics(sc, sc.model, contact, fallbacks);

  // 1. a converged solve is returned as it is (the quasi-static solution itself)
  const KinematicsSeries solved = kin(g, sc.classes[r400], r400);
  EXPECT_EQ(fallbacks->size(), 0u);
  const QuasiStaticResult direct =
      SolveQuasiStaticCurving(sc.vehicle, g, sc.classes[r400], ScenarioQuasiStaticOptions(sc, sc.model));
  ASSERT_EQ(direct.status, QuasiStaticStatus::Converged);
  ExpectSameSeries(solved, direct.series);

  // 2. the same class without any contact: not accepted, its last accepted solution comes back
  *contact.fail = true;
  ExpectSameSeries(kin(g, sc.classes[r400], r400), solved);
  ASSERT_EQ(fallbacks->size(), 1u);
  // ... and the reason is recorded (no silent fallback)
  const KinematicsFallbackLog::Entry e = fallbacks->since(0)[0];
  EXPECT_EQ(e.class_index, r400);
  EXPECT_EQ(e.replacement, "previous solution");
  EXPECT_NE(e.reason.find("without contact"), std::string::npos) << e.reason;

  // 3. a class never accepted falls back to the kinematic estimate (leading wheelset at flange contact)
  const int r200 = 3;
  ExpectSameSeries(kin(g, sc.classes[r200], r200), KinematicCurvingEstimate(sc, g, sc.classes[r200]));
  ASSERT_EQ(fallbacks->size(), 2u);
  EXPECT_EQ(fallbacks->since(1)[0].replacement, "kinematic estimate");
}

// Issue 15 (total-force load control): on the metro case with curves (metro_curves.yaml), new profiles, every class of the conformal
// run is accepted (no kinematics fallback). The R 200 m class guards the flange-climbing check: its leading
// wheelset's equilibrium (right wheel at the flange root, ~46 deg) lies 0.006 mm from a jump of the conformal
// wheel forces (the merged patch's reference point switching from the flange root to the tread: Y drops by
// ~17 kN towards the flange); the former central difference over 0.02 mm spanned the jump, called the state
// "climbing" and rejected the equilibrium, and the class fell back to the kinematic estimate.
TEST(CurvingFallback, MetroCurvesConformalClassesAreAcceptedOnTheNewProfiles) {
  const Scenario sc = LoadScenario(CONFORMA_SOURCE_DIR "/scenarios/metro_curves.yaml");
  const WheelsetTrackGeometry g(sc.MakeTrackSetup());
  auto fallbacks = std::make_shared<KinematicsFallbackLog>();
  const KinematicsFunction kin = MakeScenarioKinematics(sc, ContactModel::Conformal, &SolveWheelContact, fallbacks);
  for (size_t c = 0; c < sc.classes.size(); ++c) kin(g, sc.classes[c], static_cast<int>(c));
  for (const KinematicsFallbackLog::Entry& e : fallbacks->since(0)) ADD_FAILURE() << KinematicsFallbackLog::describe(e);

  const int r200 = 3;
  ASSERT_EQ(sc.classes[r200].curve_radius_m, 200.0);
  const QuasiStaticResult r = SolveQuasiStaticCurving(sc.vehicle, g, sc.classes[r200],
                                                      ScenarioQuasiStaticOptions(sc, ContactModel::Conformal));
  ASSERT_EQ(r.status, QuasiStaticStatus::Converged) << QuasiStaticRejection(r);
  for (const BogieQuasiStaticReport& b : r.bogies) EXPECT_FALSE(b.climbing || b.derailed) << "bogie " << b.bogie;
  // the leading wheelset of each bogie on its outer (right) flange root, inside the flange-contact margin
  for (int w : {0, 2}) {
    const WheelsetQuasiStaticReport& ws = r.wheelsets[w];
    EXPECT_TRUE(ws.wheel[1].flange_contact) << "wheelset " << w;
    EXPECT_LT(ws.pose.lateral_m, -6.0e-3) << "wheelset " << w;
    EXPECT_GT(ws.pose.lateral_m, -6.6e-3) << "wheelset " << w;
  }
}

}  // namespace
}  // namespace conforma
