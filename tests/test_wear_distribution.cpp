// Wear distributions: longitudinal integration, circumference spreading, time/contact-point/class sums
// (paper 001 §6.2 eqs. 23-27, paper 003 §6 steps 1-3).
// test-links: wear  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/profile_update.hpp"
#include "conforma/rail_update.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wear_distribution.hpp"

using namespace conforma;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Elliptic patch (semi-axes a along x, b lateral) on an nx x ny grid, all cells in the severe USFD regime
// (p_t = 400 MPa along x, slip 0.1 -> I_w = 40 N/mm^2, K = 55 ug/(m mm^2)), centred at the given arc lengths.
WearPatch severe_patch(double a, double b, int nx, int ny, double wheel_s, double rail_s) {
  WearPatch patch;
  patch.rolling_speed_m_s = 20.0;
  patch.wheel_radius_m = 0.46;
  const double dx = 2 * a / nx, dy = 2 * b / ny;
  for (int j = 0; j < ny; ++j) {
    const double y = -b + (j + 0.5) * dy;
    for (int i = 0; i < nx; ++i) {
      const double x = -a + (i + 0.5) * dx;
      if ((x / a) * (x / a) + (y / b) * (y / b) > 1.0) continue;
      WearCell c;
      c.traction_Pa = {4e8, 0.0};
      c.slip = {0.1, 0.0};
      c.pressure_Pa = 1e9;
      c.area_m2 = dx * dy;
      c.length_x_m = dx;
      c.wheel_s_m = wheel_s + y;
      c.rail_s_m = rail_s + y;
      patch.cells.push_back(c);
    }
  }
  return patch;
}

const double kSevereDepthPerMetre = 55.0 / 7850.0 * 1e-3;  // [m per m rolled], paper 003 eqs. 16-17

}  // namespace

TEST(WearDistribution, GridAndDepositionConserveArea) {
  const WearDistribution g = WearDistribution::Zero(0.150, 0.1e-3);
  EXPECT_EQ(g.size(), 1501u);
  EXPECT_NEAR(g.length_m(), 0.150, 1e-15);
  // one cell of odd width at an odd position: deposited area = depth * width exactly
  WearPatch p;
  p.rolling_speed_m_s = 10.0;
  p.wheel_radius_m = 0.45;
  WearCell c;
  c.traction_Pa = {4e8, 0};
  c.slip = {0.1, 0};
  c.pressure_Pa = 1e9;
  c.length_x_m = 0.7e-3;
  c.area_m2 = 0.7e-3 * 1.37e-3;
  c.wheel_s_m = 10.3333e-3;
  c.rail_s_m = 0.2e-3;  // partly off the start of the rail grid
  p.cells.push_back(c);
  WearModel model;
  const PatchWear w = ComputePatchWear(p, model, g, g);
  const double depth = kSevereDepthPerMetre * 0.7e-3;
  EXPECT_NEAR(w.wheel_depth_per_passage.area_m2(), depth * 1.37e-3, 1e-12 * depth * 1.37e-3);
  EXPECT_EQ(w.wheel_area_outside_m2, 0.0);
  // rail: the part of the cell below s = 0 (0.485 mm of 1.37 mm) is reported outside, the rest kept
  EXPECT_NEAR(w.rail_area_outside_m2, depth * (0.685e-3 - 0.2e-3), 1e-12 * depth * 1e-3);
  EXPECT_NEAR(w.rail_depth_per_passage.area_m2() + w.rail_area_outside_m2, depth * 1.37e-3, 1e-12 * depth * 1.37e-3);
}

TEST(WearDistribution, LongitudinalIntegrationOfAnEllipticPatch) {
  // Strip at lateral offset y has length 2 a sqrt(1 - y^2/b^2): depth per passage = rate * strip length.
  const double a = 6e-3, b = 4e-3;
  const WearPatch patch = severe_patch(a, b, 400, 80, 70e-3, 30e-3);
  const WearDistribution wheel_grid = WearDistribution::Zero(0.140, 0.1e-3);
  const WearDistribution rail_grid = WearDistribution::Zero(0.070, 0.1e-3);
  const PatchWear w = ComputePatchWear(patch, WearModel{}, wheel_grid, rail_grid);
  // centre strip: 2a * rate; at y = b/2: 2a sqrt(3/4) * rate (grid nodes coincide with strip centres +-0.05 mm)
  const double centre = w.wheel_depth_per_passage.at(70e-3);
  EXPECT_NEAR(centre, 2 * a * kSevereDepthPerMetre, 0.01 * centre);
  EXPECT_NEAR(w.wheel_depth_per_passage.at(72e-3), 2 * a * std::sqrt(0.75) * kSevereDepthPerMetre, 0.01 * centre);
  EXPECT_NEAR(w.rail_depth_per_passage.at(30e-3), centre, 1e-12);
  // removed area per passage = rate * patch area (pi a b) up to the staircase of the cell mask
  EXPECT_NEAR(w.wheel_depth_per_passage.area_m2(), kSevereDepthPerMetre * kPi * a * b, 0.005 * kSevereDepthPerMetre * kPi * a * b);
  EXPECT_EQ(w.wheel_depth_per_passage.at(80e-3), 0.0);
}

TEST(WearDistribution, TimeContactPointAndClassSums) {
  const WearDistribution wheel_grid = WearDistribution::Zero(0.140, 0.1e-3);
  const WearDistribution rail_grid = WearDistribution::Zero(0.070, 0.1e-3);
  const WearPatch tread = severe_patch(5e-3, 4e-3, 100, 40, 70e-3, 35e-3);
  const WearPatch flange = severe_patch(3e-3, 2e-3, 60, 20, 30e-3, 10e-3);
  const PatchWear tread_pass = ComputePatchWear(tread, WearModel{}, wheel_grid, rail_grid);
  const PatchWear flange_pass = ComputePatchWear(flange, WearModel{}, wheel_grid, rail_grid);

  // class A: 3 samples of 2 m with tread only; class B: 1 sample of 5 m with tread + flange (2 contact points)
  std::vector<WearSample> class_a(3, WearSample{{tread}, 2.0});
  std::vector<WearSample> class_b{WearSample{{tread, flange}, 5.0}};
  const TrackClassWear A = IntegrateTrackClass(class_a, WearModel{}, wheel_grid, rail_grid);
  const TrackClassWear B = IntegrateTrackClass(class_b, WearModel{}, wheel_grid, rail_grid);
  EXPECT_DOUBLE_EQ(A.distance_m, 6.0);
  // wheel per metre = delta / (2 pi R) (paper 001 eq. 23); rail per passage = distance-weighted mean delta
  const double circumference = 2 * kPi * 0.46;
  EXPECT_NEAR(A.wheel_depth_per_metre.at(70e-3), tread_pass.wheel_depth_per_passage.at(70e-3) / circumference, 1e-20);
  EXPECT_NEAR(A.rail_depth_per_passage.at(35e-3), tread_pass.rail_depth_per_passage.at(35e-3), 1e-20);
  EXPECT_NEAR(B.wheel_depth_per_metre.area_m2(),
              (tread_pass.wheel_depth_per_passage.area_m2() + flange_pass.wheel_depth_per_passage.area_m2()) / circumference,
              1e-12 * B.wheel_depth_per_metre.area_m2());

  // classes with weights 0.7 / 0.3 (sum p_k = 1)
  const TrackClassWear mix = CombineTrackClasses({A, B}, {0.7, 0.3});
  for (double s : {30e-3, 50e-3, 70e-3})
    EXPECT_NEAR(mix.wheel_depth_per_metre.at(s), 0.7 * A.wheel_depth_per_metre.at(s) + 0.3 * B.wheel_depth_per_metre.at(s), 1e-22);
  EXPECT_NEAR(mix.rail_depth_per_passage.at(10e-3), 0.3 * flange_pass.rail_depth_per_passage.at(10e-3), 1e-20);
  EXPECT_THROW(CombineTrackClasses({A, B}, {0.7, 0.4}), InputError);
  EXPECT_THROW(CombineTrackClasses({A, B}, {1.0}), InputError);

  // streaming accumulators merged give the same as one pass
  WearAccumulator first(wheel_grid, rail_grid, WearModel{}), second(wheel_grid, rail_grid, WearModel{});
  first.add(class_a[0]);
  second.add(class_a[1]);
  second.add(class_a[2]);
  first.merge(second);
  EXPECT_NEAR(first.result().wheel_depth_per_metre.area_m2(), A.wheel_depth_per_metre.area_m2(), 1e-24);
}

TEST(WearDistribution, SeparateWheelAndRailLawsArchard) {
  // wheel: USFD; rail: Archard (Jendel map). One cell: p = 1 GPa, s = (0.01, 0), V = 30 m/s -> v_slip = 0.3 m/s,
  // k = 35e-4: rail depth per passage = k p |s| dx / H = 35e-4 * 1e9 * 0.01 * 0.5e-3 / 2.75e9 = 6.3636e-9 m.
  // Wheel: I_w = 4e8 * 0.01 / 1e6 = 4 N/mm^2 (mild) -> K = 21.2 -> 21.2 * 0.5e-3 / 7850 mm = 1.3503e-9 m.
  WearModel model;
  model.rail_law.kind = WearLawKind::Archard;
  WearPatch p;
  p.rolling_speed_m_s = 30.0;
  p.wheel_radius_m = 0.46;
  WearCell c;
  c.traction_Pa = {4e8, 0};
  c.slip = {0.01, 0};
  c.pressure_Pa = 1e9;
  c.length_x_m = 0.5e-3;
  c.area_m2 = 0.5e-3 * 1e-3;  // 1 mm wide: deposited area = depth * 1 mm
  c.wheel_s_m = 50e-3;
  c.rail_s_m = 20e-3;
  p.cells.push_back(c);
  const WearDistribution g = WearDistribution::Zero(0.1, 0.1e-3);
  const PatchWear w = ComputePatchWear(p, model, g, g);
  EXPECT_NEAR(w.rail_depth_per_passage.area_m2() / 1e-3, 6.363636e-9, 1e-14);
  EXPECT_NEAR(w.wheel_depth_per_passage.area_m2() / 1e-3, 21.2 * 0.5e-3 / 7850.0 * 1e-3, 1e-16);
}

TEST(WearDistribution, BadCellsAreNamed) {
  WearPatch p = severe_patch(5e-3, 4e-3, 10, 10, 70e-3, 35e-3);
  p.cells[3].pressure_Pa = -1.0;
  const WearDistribution g = WearDistribution::Zero(0.140, 0.1e-3);
  try {
    ComputePatchWear(p, WearModel{}, g, g);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wear cell 3"), std::string::npos) << e.what();
  }
}

TEST(WearDistribution, ChainFromCellsToUpdatedProfiles) {
  // Hertz-like patch on the S1002 tread (y = 0) against a 60E1 1:40 rail crown (y = 0): pressure
  // p0 sqrt(1 - x^2/a^2 - y^2/b^2), leading 60 % adhesion (no slip), trailing slip zone with traction mu p
  // along the slip (slip 2e-3 along x). Bookkeeping: removed wheel area per metre = sum(rate * area) / (2 pi R).
  const Profile wheel = MakeS1002();
  const Profile rail = MakeRail(RailSection::R60E1, rail_inclination_1in40());
  const double a = 6e-3, b = 5e-3, p0 = 1.1e9, mu = 0.3, R = 0.46, V = 25.0;
  const int nx = 60, ny = 50;
  const double dx = 2 * a / nx, dy = 2 * b / ny;
  WearPatch patch;
  patch.rolling_speed_m_s = V;
  patch.wheel_radius_m = R;
  const double sw0 = *wheel.s_at(0.0), sr0 = *rail.s_at(0.0);
  WearModel model;
  double expected_area = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = a - (i + 0.5) * dx, y = -b + (j + 0.5) * dy;  // i = 0 at the leading edge
      const double r2 = (x / a) * (x / a) + (y / b) * (y / b);
      if (r2 >= 1.0) continue;
      WearCell c;
      c.pressure_Pa = p0 * std::sqrt(1.0 - r2);
      const bool slipping = x < a * std::sqrt(1.0 - (y / b) * (y / b)) - 1.2 * a * std::sqrt(1.0 - (y / b) * (y / b));
      c.slip = slipping ? Eigen::Vector2d(2e-3, 0.0) : Eigen::Vector2d::Zero();
      c.traction_Pa = Eigen::Vector2d(mu * c.pressure_Pa * (slipping ? 1.0 : 0.5), 0.0);
      c.area_m2 = dx * dy;
      c.length_x_m = dx;
      c.wheel_s_m = sw0 + y;
      c.rail_s_m = sr0 + y;
      patch.cells.push_back(c);
      expected_area += model.wheel_law.depth_per_rolled_metre(c.traction_Pa, c.slip, c.pressure_Pa, V, Material{}) *
                       c.area_m2 / (2 * kPi * R);
    }
  const WearDistribution wheel_grid = WearDistribution::ForProfile(wheel), rail_grid = WearDistribution::ForProfile(rail);
  const TrackClassWear tc = IntegrateTrackClass({WearSample{{patch}, 100.0}}, model, wheel_grid, rail_grid);
  ASSERT_GT(expected_area, 0.0);
  EXPECT_NEAR(tc.wheel_depth_per_metre.area_m2(), expected_area, 1e-10 * expected_area);
  EXPECT_EQ(tc.area_outside_m2, 0.0);
  // I_w = 0.3 * 1.1e9 * sqrt(...) * 2e-3 / 1e6 <= 0.66 N/mm^2: mild regime everywhere
  const ProfileUpdateResult w = UpdateProfile(wheel, tc.wheel_depth_per_metre, 1.0);
  ASSERT_EQ(w.status, ProfileUpdateStatus::Updated) << w.message;
  EXPECT_NEAR(w.max_depth_m, 0.4e-3, 1e-12);
  EXPECT_NEAR(w.distance_step_m, 0.4e-3 / w.smoothing.depth.max_depth_m(), 1e-9 * w.distance_step_m);
  RecordProperty("wheel_km_per_0.4mm_step", std::to_string(w.distance_step_m / 1e3));
  const RailStepResult r = UpdateRail(rail, {tc.rail_depth_per_passage}, {}, 1.0);
  ASSERT_EQ(r.status, ProfileUpdateStatus::Updated) << r.message;
  EXPECT_NEAR(r.mean_removed_depth.max_depth_m(), 0.1e-3, 1e-6 * 0.1e-3);
}
