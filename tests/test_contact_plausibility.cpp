// Plausibility warnings of SolveWheelContact (contact_plausibility.hpp): a wheel profile whose z origin is not at
// the taping line, friction outside 0.05-1, a pressure above the material limit, non-converged load control; and
// the frictional power of every model (sum of traction . slip velocity over the patch, nonzero under creepage).
// test-links: pipeline  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "conforma/contact_plausibility.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/wheel_contact.hpp"
#include "conforma/wheel_contact_fields.hpp"
#include "pipeline_test_geometry.hpp"

using namespace conforma;

namespace {

using test::PipelineGeometry;
using test::Pose;
using test::Rolling;

// The warnings with this code ("code: ...").
std::vector<std::string> WithCode(const WheelContactReport& r, const std::string& code) {
  std::vector<std::string> out;
  for (const std::string& w : r.warnings)
    if (w.rfind(code + ":", 0) == 0) out.push_back(w);
  return out;
}

std::string All(const WheelContactReport& r) {
  std::string s;
  for (const std::string& w : r.warnings) s += w + "\n";
  return s;
}

// S1002 with its z origin 20 mm below the taping line (every z + 20 mm): the tread rolls at r0 + 20 mm.
const WheelsetTrackGeometry& ShiftedWheelGeometry() {
  static const WheelsetTrackGeometry g = [] {
    std::vector<Eigen::Vector2d> points = MakeS1002().samples();
    for (Eigen::Vector2d& p : points) p.y() += 0.020;
    return WheelsetTrackGeometry(MakeSymmetricTrack(Profile::FromPoints(points, ProfileKind::Wheel),
                                                    MakeRail(RailSection::R60E1, 0.0), rail_inclination_1in40()));
  }();
  return g;
}

TEST(ContactPlausibility, NominalRadiusFarFromTheProfilesOnTheTread) {
  const WheelsetTrackGeometry& g = ShiftedWheelGeometry();
  const EquilibriumResult eq = g.SolveRigidEquilibrium(0.0, 0.0);
  ASSERT_EQ(eq.status, EquilibriumStatus::Converged);
  WheelContactOptions o;
  const WheelContactReport r = SolveWheelContact(g, Side::Left, eq.pose, Rolling(), o);
  ASSERT_EQ(r.status, WheelContactStatus::Ok);
  ASSERT_FALSE(r.patches.empty());
  const PatchReport& p = r.patches[0];
  EXPECT_NEAR(p.rolling_radius_m - 0.46, 0.020, 1.5e-3);  // the tread of S1002 is within ~1 mm of z = 0
  EXPECT_NEAR(p.xi, -(p.rolling_radius_m - 0.46) / 0.46, 2e-3);  // rolling at r0: xi ~ -0.043
  const std::vector<std::string> w = WithCode(r, "nominal_radius");
  ASSERT_EQ(w.size(), r.patches.size()) << All(r);
  EXPECT_NE(w[0].find("r0 = 460.0 mm"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("z origin is not at the taping line"), std::string::npos) << w[0];
  char offset[32];
  std::snprintf(offset, sizeof offset, "%+.1f mm from", (p.rolling_radius_m - 0.46) * 1e3);
  EXPECT_NE(w[0].find(offset), std::string::npos) << w[0];
}

TEST(ContactPlausibility, NoWarningForANewWheelOnTheTreadOrTheFlange) {
  WheelContactOptions o;
  for (ContactModel model : {ContactModel::Hertz, ContactModel::Kpec}) {
    o.model = model;
    for (double y_mm : {0.0, 8.0}) {  // 8 mm: the left wheel on its flange, r - r0 ~ +20 mm
      for (Side side : {Side::Left, Side::Right}) {
        const WheelContactReport r = SolveWheelContact(PipelineGeometry(), side, Pose(y_mm), Rolling(), o);
        ASSERT_EQ(r.status, WheelContactStatus::Ok);
        EXPECT_TRUE(r.warnings.empty()) << to_string(model) << " y " << y_mm << "\n" << All(r);
      }
    }
  }
}

TEST(ContactPlausibility, FrictionOutsideThePlausibleRange) {
  WheelContactOptions o;
  for (double mu : {5.0, 0.02}) {
    o.friction_coefficient = mu;
    const WheelContactReport r = SolveWheelContact(PipelineGeometry(), Side::Left, Pose(0.0), Rolling(), o);
    const std::vector<std::string> w = WithCode(r, "friction_coefficient");
    ASSERT_EQ(w.size(), 1u) << mu << "\n" << All(r);
    EXPECT_NE(w[0].find("mu = " + std::string(mu == 5.0 ? "5" : "0.02")), std::string::npos) << w[0];
  }
  o.friction_coefficient = 0.6;
  EXPECT_TRUE(SolveWheelContact(PipelineGeometry(), Side::Left, Pose(0.0), Rolling(), o).warnings.empty());
  // a law: its static value counts, not friction_coefficient
  o.friction_law = FrictionLaw::F1b(1.5, 0.4, 0.01);
  const WheelContactReport r = SolveWheelContact(PipelineGeometry(), Side::Left, Pose(0.0), Rolling(), o);
  ASSERT_EQ(WithCode(r, "friction_coefficient").size(), 1u) << All(r);
  EXPECT_NE(r.warnings[0].find("mu(0) = 1.5"), std::string::npos) << r.warnings[0];
}

TEST(ContactPlausibility, PressureAboveTheMaterialLimit) {
  WheelContactOptions o;
  o.vertical_load_N = 1e7;  // p0 ~ N^(1/3): 3.2 GPa at 2 MN, ~5.5 GPa at 10 MN on the tread of S1002 / 60E1
  const WheelContactReport r = SolveWheelContact(PipelineGeometry(), Side::Left, Pose(0.0), Rolling(), o);
  ASSERT_EQ(r.status, WheelContactStatus::Ok);
  ASSERT_GT(r.patches[0].pmax_Pa, kMaxPlausiblePressurePa);
  EXPECT_EQ(WithCode(r, "pressure_limit").size(), 1u) << All(r);
  o.vertical_load_N = 100e3;  // a heavy but plausible wheel load: ~2 GPa
  const WheelContactReport ok = SolveWheelContact(PipelineGeometry(), Side::Left, Pose(0.0), Rolling(), o);
  EXPECT_LT(ok.patches[0].pmax_Pa, kMaxPlausiblePressurePa);
  EXPECT_TRUE(WithCode(ok, "pressure_limit").empty()) << All(ok);
}

TEST(ContactPlausibility, LoadControlNotConverged) {
  WheelContactOptions o;
  o.vertical_load_N = 163e3;
  WheelContactReport r;
  r.status = WheelContactStatus::NotConverged;
  r.vertical_force_N = 131.2e3;
  r.pressure_vertical_force_N = 129.9e3;
  r.load_iterations = 40;
  r.patches.resize(1);
  r.patches[0].rolling_radius_m = 0.46;
  std::vector<std::string> w = ContactPlausibilityWarnings(r, PipelineGeometry(), o);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("load_not_converged:", 0), 0u) << w[0];
  // the balanced force: the total vertical force by default, the pressure alone with load_balance pressure
  EXPECT_NE(w[0].find("131200.0 N (total vertical force, pressure and creep forces) of the wheel load 163000.0 N"),
            std::string::npos)
      << w[0];
  o.load_balance = LoadBalance::Pressure;
  w = ContactPlausibilityWarnings(r, PipelineGeometry(), o);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("129900.0 N (pressure forces) of the wheel load 163000.0 N"), std::string::npos) << w[0];
  r.patches.clear();  // no load bracket
  w = ContactPlausibilityWarnings(r, PipelineGeometry(), o);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("no patch"), std::string::npos) << w[0];
  r.status = WheelContactStatus::Ok;
  EXPECT_TRUE(ContactPlausibilityWarnings(r, PipelineGeometry(), o).empty());
}

// Frictional power = V sum |p . s| dA over the elements (docs/physics-reference.md §2.4), nonzero under creepage,
// for every model (kp and kpec reported 0 before: their FASTSIM got no rolling speed).
TEST(ContactPlausibility, FrictionalPowerIsTheFieldIntegralForEveryModel) {
  for (ContactModel model : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal}) {
    WheelContactOptions o;
    o.model = model;
    o.keep_fields = true;
    o.kp_strips = 15;
    o.fastsim_elements = 12;
    const WheelsetVelocity v{20.0, 0.0, 1e-3, 20.0 / 0.459};  // creepage from the kinematics (braking, yaw rate)
    const WheelContactReport r = SolveWheelContact(PipelineGeometry(), Side::Left, Pose(3.0), v, o);
    ASSERT_EQ(r.status, WheelContactStatus::Ok) << to_string(model);
    for (const PatchReport& p : r.patches) {
      ASSERT_FALSE(p.cells.empty()) << to_string(model);
      double integral = 0.0;
      for (const ContactCell& c : p.cells) integral += CellWearIndexPa(c) * c.area_m2 * v.forward_speed_m_s;
      EXPECT_GT(p.frictional_power_W, 1.0) << to_string(model);
      EXPECT_NEAR(p.frictional_power_W, integral, 1e-9 * integral) << to_string(model);
    }
  }
}

// A falling friction law lowers the creep force in full slip (mu_d instead of mu_s), for every tangential model;
// a constant law equals friction_coefficient.
TEST(ContactPlausibility, FrictionLawReachesEveryModel) {
  for (ContactModel model : {ContactModel::Hertz, ContactModel::Kpec, ContactModel::Conformal}) {
    WheelContactOptions o;
    o.model = model;
    o.kp_strips = 15;
    o.fastsim_elements = 12;
    o.creepages_given = true;
    o.creepages = {0.02, 0.0, 0.0};  // full slip
    const WheelContactReport constant = SolveWheelContact(PipelineGeometry(), Side::Left, Pose(0.0), Rolling(), o);
    o.friction_law = FrictionLaw::F1b(0.3, 0.15, 1e-3);
    const WheelContactReport falling = SolveWheelContact(PipelineGeometry(), Side::Left, Pose(0.0), Rolling(), o);
    ASSERT_FALSE(constant.patches.empty());
    ASSERT_EQ(constant.patches.size(), falling.patches.size());
    const double fn = constant.patches[0].fn_N;
    EXPECT_NEAR(std::fabs(constant.patches[0].fx_N), 0.3 * fn, 0.02 * fn) << to_string(model);
    EXPECT_LT(std::fabs(falling.patches[0].fx_N), 0.2 * fn) << to_string(model);
    EXPECT_GT(std::fabs(falling.patches[0].fx_N), 0.14 * fn) << to_string(model);
  }
}

}  // namespace
