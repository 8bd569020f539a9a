// The wheel-contact pipeline (wheel_contact.hpp): mirror symmetry of the two wheels, load mode vs approach mode,
// conservation of the per-cell fields, zero creepage, no contact and bad input.
// test-links: pipeline  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact.hpp"
#include "pipeline_test_geometry.hpp"

using namespace conforma;

namespace {
const WheelsetTrackGeometry& Geometry() { return test::PipelineGeometry(); }
using test::Pose;
using test::Rolling;
const ContactModel kModels[] = {ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal};
}  // namespace

TEST(WheelContactPipeline, LeftAndRightWheelsAreMirrorImagesOnACentredWheelset) {
  const WheelsetPose pose = Pose(0.0, 0.0);
  for (ContactModel m : kModels) {
    WheelContactOptions o;
    o.model = m;
    const WheelContactReport l = SolveWheelContact(Geometry(), Side::Left, pose, Rolling(), o);
    const WheelContactReport r = SolveWheelContact(Geometry(), Side::Right, pose, Rolling(), o);
    ASSERT_EQ(l.patches.size(), r.patches.size()) << to_string(m);
    for (size_t j = 0; j < l.patches.size(); ++j) {
      EXPECT_NEAR(l.patches[j].fn_N, r.patches[j].fn_N, 1e-6 * l.patches[j].fn_N) << to_string(m);
      EXPECT_NEAR(l.patches[j].pmax_Pa, r.patches[j].pmax_Pa, 1e-6 * l.patches[j].pmax_Pa) << to_string(m);
      EXPECT_NEAR(l.patches[j].fx_N, r.patches[j].fx_N, 1e-6 * std::fabs(l.patches[j].fn_N)) << to_string(m);
      EXPECT_NEAR(l.patches[j].fy_N, r.patches[j].fy_N, 1e-6 * std::fabs(l.patches[j].fn_N)) << to_string(m);
    }
  }
}

TEST(WheelContactPipeline, ApproachModeAtTheLoadedPoseReproducesTheLoadModeForces) {
  const WheelsetPose pose = Pose(3.0, 1.0);
  for (ContactModel m : kModels) {
    WheelContactOptions o;
    o.model = m;
    const WheelContactReport loaded = SolveWheelContact(Geometry(), Side::Left, pose, Rolling(), o);
    ASSERT_EQ(loaded.status, WheelContactStatus::Ok) << to_string(m);
    o.vertical_load_N = -1.0;  // pose as given
    const WheelContactReport given = SolveWheelContact(Geometry(), Side::Left, loaded.pose, Rolling(), o);
    ASSERT_EQ(given.status, WheelContactStatus::Ok) << to_string(m);
    // the load is carried by the total vertical force (total-force balance, issue 15)
    EXPECT_NEAR(given.vertical_force_N, 10e3, 10e3 * 1e-3) << to_string(m);
    EXPECT_NEAR(given.pressure_vertical_force_N, loaded.pressure_vertical_force_N, 10e3 * 1e-3) << to_string(m);
  }
}

TEST(WheelContactPipeline, CellFieldsIntegrateToThePatchForces) {
  const WheelsetPose pose = Pose(2.0, 2.0);
  for (ContactModel m : kModels) {
    WheelContactOptions o;
    o.model = m;
    o.keep_fields = true;
    const WheelContactReport r = SolveWheelContact(Geometry(), Side::Left, pose, Rolling(), o);
    ASSERT_FALSE(r.patches.empty());
    const PatchReport& p = r.patches.front();
    ASSERT_FALSE(p.cells.empty()) << to_string(m);
    double load = 0, fx = 0, area = 0, dx_area = 0;
    for (const ContactCell& c : p.cells) {
      load += c.pressure_Pa * c.area_m2;
      fx += c.traction_x_Pa * c.area_m2;
      area += c.area_m2;
      dx_area += c.length_x_m > 0 ? 1 : 0;
      EXPECT_TRUE(std::isfinite(c.wheel_y_m) && std::isfinite(c.rail_s_m));
      EXPECT_LE(std::hypot(c.traction_x_Pa, c.traction_s_Pa), o.friction_coefficient * c.pressure_Pa * 1.02 + 1.0);
    }
    EXPECT_NEAR(load, p.fn_N, 0.02 * p.fn_N) << to_string(m);  // element-centre sampling of the pressure
    EXPECT_NEAR(area, p.area_m2, 0.03 * p.area_m2) << to_string(m);
    EXPECT_EQ(dx_area, static_cast<double>(p.cells.size()));
    if (m == ContactModel::Hertz) {
      EXPECT_NEAR(fx, p.fx_N, 1e-9 * p.fn_N);
    }
    EXPECT_NEAR(p.cells.front().rail_s_m, p.reference_s_on_rail_m + p.cells.front().s_m, 1e-12);
  }
}

TEST(WheelContactPipeline, NoCreepageMeansNoTangentialSolveAndNoCreepForce) {
  WheelContactOptions o;
  o.model = ContactModel::Conformal;
  o.creepages_given = true;  // all zero
  const WheelContactReport r = SolveWheelContact(Geometry(), Side::Left, Pose(1.0, 0.0), Rolling(), o);
  ASSERT_FALSE(r.patches.empty());
  for (const PatchReport& p : r.patches) {
    EXPECT_EQ(p.tangential_status, "no_creepage");
    EXPECT_EQ(p.fx_N, 0.0);
    EXPECT_EQ(p.fy_N, 0.0);
  }
}

TEST(WheelContactPipeline, LiftedWheelIsNoContactAndBadInputIsRefused) {
  WheelsetPose lifted = Pose(0.0, 0.0);
  lifted.vertical_m += 1e-3;
  WheelContactOptions o;
  o.vertical_load_N = -1.0;
  EXPECT_EQ(SolveWheelContact(Geometry(), Side::Left, lifted, Rolling(), o).status, WheelContactStatus::NoContact);
  EXPECT_THROW(ParseContactModel("fem"), InputError);
  o.vertical_load_N = NAN;
  EXPECT_THROW(SolveWheelContact(Geometry(), Side::Left, lifted, Rolling(), o), InputError);
  o.vertical_load_N = 10e3;
  o.friction_coefficient = -0.1;
  EXPECT_THROW(SolveWheelContact(Geometry(), Side::Left, lifted, Rolling(), o), InputError);
}
