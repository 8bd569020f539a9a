// test-links: rig
// One roller-rig sample (paper 000 §3.4-3.5, docs/physics-reference.md §18.3): zero creepage gives zero wear, the wear
// volume equals Archard's k N s / H summed over the contact cells (eq. 6-10 with eq. 17's passages), mirror symmetry,
// the sliding-mean filter and the profile update conserve the worn area, statuses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "conforma/error.hpp"
#include "conforma/roller_rig_sample.hpp"
#include "conforma/wear_law.hpp"

namespace conforma {
namespace {

constexpr double kPi = 3.14159265358979323846;
double Rpm(double rpm) { return rpm * 2.0 * kPi / 60.0; }

RollerRigSample Sample(double xi, double y = 0.0, double dt = 0.02) {
  RollerRigSample s;
  s.duration_s = dt;
  s.lateral_m = y;
  s.roller_speed_rad_s = {Rpm(500.0), Rpm(500.0) * (1.0 - xi) / (1.0 + xi)};
  s.wheel_load_N = {50.0 * 9.81, 50.0 * 9.81};
  return s;
}

// A cylindrical wheel on the roller crown: contact angle 0, so no spin either (the 0.036 rad cone has spin -sin(delta)/r
// and wears at zero longitudinal creepage).
TEST(RigSample, ZeroCreepageGivesZeroWear) {
  RollerRigSetup cylinder;
  cylinder.wheel_conicity_rad = 0.0;
  const RollerRigSampleOptions o = RollerRigSampleOptions::Defaults(cylinder);
  RollerRigState s0 = MakeRollerRigState(o), s1 = s0;
  const RollerRigSampleResult r0 = ProcessRigSample(o, &s0, Sample(0.0));
  const RollerRigSampleResult r1 = ProcessRigSample(o, &s1, Sample(0.05));
  ASSERT_EQ(r0.status, RollerRigSampleStatus::Ok) << r0.message;
  ASSERT_EQ(r1.status, RollerRigSampleStatus::Ok) << r1.message;
  for (int k = 0; k < 2; ++k) {
    EXPECT_GT(r1.wheel_wear_area_m2[k], 0.0);
    EXPECT_GT(r1.roller_wear_area_m2[k], 0.0);
    EXPECT_LE(r0.wheel_wear_area_m2[k], 1e-9 * r1.wheel_wear_area_m2[k]);
    EXPECT_LE(r0.roller_wear_area_m2[k], 1e-9 * r1.roller_wear_area_m2[k]);
    EXPECT_NEAR(r0.kinematics.contact[k].xi, 0.0, 1e-12);
  }
}

// Archard (paper 000 eq. 6): volume = k N S / H. Per cell, over dt: k p dA |s| V_i dt / H (sliding distance |s| V dt);
// the ring volumes (area x 2 pi r) must equal the sum over the cells with the roller / wheel surface travel of eq. 17,
// and sum p dA must be N. With paper 000 eq. 16 (strip depth = mean of C elements) the volume is 1/C of that.
TEST(RigSample, WearVolumeIsArchardKNSOverH) {
  RollerRigSampleOptions o = RollerRigSampleOptions::Defaults();
  for (double C : {1.0, 20.0})
  for (double xi : {0.02, 0.15}) {
    o.strip_mean_elements = C;
    RollerRigState st = MakeRollerRigState(o);
    const RollerRigSampleResult r = ProcessRigSample(o, &st, Sample(xi, 0.2e-3));
    ASSERT_EQ(r.status, RollerRigSampleStatus::Ok) << r.message;
    const ArchardMap wmap = ArchardMap::Paper000Wheel(), rmap = ArchardMap::Paper000Roller();
    const double w3 = r.kinematics.wheelset_speed_rad_s;
    for (int k = 0; k < 2; ++k) {
      const RollerRigContactResult& c = r.kinematics.contact[k];
      const double V = c.roller_surface_speed_m_s;
      double sum_w = 0.0, sum_r = 0.0, load = 0.0;
      for (const PatchReport& p : c.report.patches)
        for (const ContactCell& cell : p.cells) {
          load += cell.pressure_Pa * cell.area_m2;
          const double s = std::hypot(cell.slip_x, cell.slip_s);
          sum_w += wmap.coefficient(cell.pressure_Pa, s * V) * cell.pressure_Pa * cell.area_m2 * s / wmap.hardness_Pa;
          sum_r += rmap.coefficient(cell.pressure_Pa, s * V) * cell.pressure_Pa * cell.area_m2 * s / rmap.hardness_Pa;
        }
      EXPECT_NEAR(load, c.fn_N, 0.01 * c.fn_N) << xi;
      const double dt = 0.02;
      const double wheel_expected = sum_w * w3 * c.wheel_rolling_radius_m * dt / C;  // wheel travel omega_3 r dt
      const double roller_expected = sum_r * Sample(xi).roller_speed_rad_s[k] * c.roller_rolling_radius_m * dt / C;
      EXPECT_GT(wheel_expected, 0.0);
      EXPECT_NEAR(r.wheel_wear_volume_m3[k], wheel_expected, 1e-9 * wheel_expected) << xi << " side " << k;
      EXPECT_NEAR(r.roller_wear_volume_m3[k], roller_expected, 1e-9 * roller_expected) << xi << " side " << k;
    }
  }
}

TEST(RigSample, MirrorSymmetry) {
  const RollerRigSampleOptions o = RollerRigSampleOptions::Defaults();
  RollerRigState a = MakeRollerRigState(o), b = a;
  RollerRigSample sa = Sample(0.05, 0.3e-3), sb = sa;
  sb.roller_speed_rad_s = {sa.roller_speed_rad_s[1], sa.roller_speed_rad_s[0]};
  sb.lateral_m = -sa.lateral_m;
  const auto ra = ProcessRigSample(o, &a, sa), rb = ProcessRigSample(o, &b, sb);
  ASSERT_EQ(ra.status, RollerRigSampleStatus::Ok);
  ASSERT_EQ(rb.status, RollerRigSampleStatus::Ok);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(ra.wheel_wear_area_m2[k], rb.wheel_wear_area_m2[1 - k], 1e-6 * ra.wheel_wear_area_m2[k]);
    EXPECT_NEAR(ra.roller_wear_max_depth_m[k], rb.roller_wear_max_depth_m[1 - k], 1e-6 * ra.roller_wear_max_depth_m[k]);
    EXPECT_NEAR(ra.kinematics.contact[k].fx_N, rb.kinematics.contact[1 - k].fx_N, 1e-6 * std::abs(ra.kinematics.contact[k].fx_N));
  }
}

TEST(RigSample, SlidingMeanKeepsConstantsAndInteriorArea) {
  WearDistribution d = WearDistribution::Zero(1e-3, 1e-5);
  for (double& v : d.depth_m) v = 2e-6;
  const WearDistribution c = SlidingMean(d, 1e-4);
  for (double v : c.depth_m) EXPECT_NEAR(v, 2e-6, 1e-18);
  WearDistribution spike = WearDistribution::Zero(1e-3, 1e-5);
  spike.depth_m[50] = 1e-6;
  const WearDistribution s = SlidingMean(spike, 1e-4);
  EXPECT_NEAR(s.area_m2(), spike.area_m2(), 1e-12 * spike.area_m2());
  EXPECT_NEAR(s.depth_m[50], 1e-6 / 11.0, 1e-20);
}

// Ten steps: the raw depth is removed every step, the filtered wear at step 10; the area between the initial and the
// final wheel profile equals the summed wear area (the cone's normal is within 0.036 rad of the vertical).
TEST(RigSample, ProfileUpdateAndFilterConserveTheWornArea) {
  const RollerRigSampleOptions o = RollerRigSampleOptions::Defaults();
  RollerRigState st = MakeRollerRigState(o);
  const Profile w0 = st.wheel[0];
  double area = 0.0;
  for (int i = 1; i <= 10; ++i) {
    const RollerRigSampleResult r = ProcessRigSample(o, &st, Sample(0.15, 0.0, 0.02));
    ASSERT_EQ(r.status, RollerRigSampleStatus::Ok) << r.message;
    EXPECT_TRUE(r.profiles_updated);
    EXPECT_EQ(r.filtered, i == 10);
    area += r.wheel_wear_area_m2[0];
  }
  ASSERT_GT(area, 0.0);
  double between = 0.0;
  const double h = 2e-6;
  for (double y = w0.y_min() + 1e-4; y < w0.y_max() - 1e-4; y += h) {
    const auto z0 = w0.height_at(y), z1 = st.wheel[0].height_at(y);
    if (z0 && z1) between += (*z0 - *z1) * h;
  }
  EXPECT_NEAR(between, area, 0.01 * area);
  EXPECT_EQ(st.step, 10);
  EXPECT_NEAR(st.time_s, 0.2, 1e-12);
}

// Eq. 16's C belongs to Table 3 (Archard); the USFD wear-index law is not divided.
TEST(RigSample, StripMeanElementsApplyToArchardOnly) {
  RollerRigSampleOptions o = RollerRigSampleOptions::Defaults();
  o.wear_law = RollerRigWearLaw::WearIndex;
  RollerRigState s1 = MakeRollerRigState(o), s20 = s1;
  const RollerRigSampleResult r1 = ProcessRigSample(o, &s1, Sample(0.15));
  o.strip_mean_elements = 20.0;
  const RollerRigSampleResult r20 = ProcessRigSample(o, &s20, Sample(0.15));
  ASSERT_EQ(r1.status, RollerRigSampleStatus::Ok) << r1.message;
  ASSERT_EQ(r20.status, RollerRigSampleStatus::Ok) << r20.message;
  for (int k = 0; k < 2; ++k) {
    EXPECT_GT(r1.wheel_wear_area_m2[k], 0.0);
    EXPECT_EQ(r1.wheel_wear_area_m2[k], r20.wheel_wear_area_m2[k]);
    EXPECT_EQ(r1.roller_wear_area_m2[k], r20.roller_wear_area_m2[k]);
  }
}

TEST(RigSample, StatusesAndErrors) {
  const RollerRigSampleOptions o = RollerRigSampleOptions::Defaults();
  RollerRigState st = MakeRollerRigState(o);
  RollerRigSample s = Sample(0.05);
  s.wheel_load_N[0] = 0.0;
  const RollerRigSampleResult r = ProcessRigSample(o, &st, s);
  EXPECT_EQ(r.status, RollerRigSampleStatus::ContactFailed);
  EXPECT_FALSE(r.message.empty());
  EXPECT_EQ(st.step, 0);
  s = Sample(0.05);
  s.duration_s = 0.0;
  EXPECT_THROW(ProcessRigSample(o, &st, s), InputError);
  EXPECT_THROW(ProcessRigSample(o, nullptr, Sample(0.05)), InputError);
  EXPECT_THROW(RollerRigWearLawFromName("none"), InputError);
  for (double C : {0.5, 0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    RollerRigSampleOptions bad = o;
    bad.strip_mean_elements = C;
    EXPECT_THROW(ProcessRigSample(bad, &st, Sample(0.05)), InputError) << C;
  }
}

}  // namespace
}  // namespace conforma
