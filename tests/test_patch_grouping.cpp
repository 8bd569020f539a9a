// Patch grouping (CandidateOptions::combine_distance_m, contact_candidates.hpp; docs/physics-reference.md §1.6.1):
// two interpenetration regions a small gap apart along the rail profile are solved as one curved patch spanning
// both and the gap, with the local normals turning across it; they stay separate with combining off or with a
// combine distance below the gap. The merged patch carries the load in load control.
// test-links: pipeline  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "conforma/contact_candidates.hpp"
#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact.hpp"

using namespace conforma;

namespace {

constexpr double kRailRadius = 0.060;   // rail crown radius, m
constexpr double kWheelRadius = 0.061;  // concave wheel tread radius (closely conformal), m
constexpr double kDipWidth = 0.6e-3;    // Gaussian dip of the wheel at y = 0 (gap between the two regions), m
constexpr double kDipDepth = 0.05e-3;   // m

// Rail: circular crown of radius R (top at the origin), half-width 35 mm, steep flanks down to -30 mm.
Profile CrownRail() {
  const double R = kRailRadius, w = 0.035, drop = R - std::sqrt(R * R - w * w);
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i <= 20; ++i) p.emplace_back(-w - 0.001 + 0.001 * i / 20.0, -0.03 + (0.03 - drop) * i / 20.0);
  for (int i = 1; i <= 1400; ++i) {
    const double y = -w + 2 * w * i / 1400.0;
    p.emplace_back(y, std::sqrt(R * R - y * y) - R);
  }
  for (int i = 1; i <= 20; ++i) p.emplace_back(w + 0.001 * i / 20.0, -drop - (0.03 - drop) * i / 20.0);
  ProfileFitOptions o;
  o.function_of_y = false;
  return Profile::FromPoints(p, ProfileKind::Rail, o);
}

// Wheel: concave circular tread of radius Rw wrapping the crown (radius r0 + z_w, z_w = Rw - sqrt(Rw^2 - y^2)),
// with a shallow narrow dip (smaller radius) at y = 0 that splits the interpenetration into two regions.
// Centred at wheel-profile y = yc.
Profile DippedWheel(double dip_depth, double yc) {
  const double Rw = kWheelRadius;
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i <= 1600; ++i) {
    const double y = -0.040 + 0.080 * i / 1600.0;
    const double dip = dip_depth * std::exp(-(y / kDipWidth) * (y / kDipWidth));
    p.emplace_back(yc + y, Rw - std::sqrt(Rw * Rw - y * y) - dip);
  }
  return Profile::FromPoints(p, ProfileKind::Wheel);
}

// The wheel profile centred on the wheel-profile y that faces the rail crown's top at the centred pose
// (eta = frame centre + wheel origin + y_w = rail origin, geometry.hpp), so that the dip sits over the crown top.
WheelsetTrackGeometry Track(double dip_depth) {
  const WheelsetTrackGeometry probe(MakeSymmetricTrack(DippedWheel(0.0, 0.0), CrownRail(), 0.0));
  const double yc = probe.rail_origin_eta_m(Side::Left) -
                    (probe.SideFrame(Side::Left, WheelsetPose{}).centre(1) + probe.wheel_origin_eta_m());
  return WheelsetTrackGeometry(MakeSymmetricTrack(DippedWheel(dip_depth, yc), CrownRail(), 0.0));
}

// The wheel lowered 30 um below first touch: the rigid interpenetration spans about +-13 mm of the crown
WheelsetPose Pushed(const WheelsetTrackGeometry& g) {
  WheelsetPose pose;
  double gap = 0.0, y = 0.0;
  EXPECT_TRUE(g.MinimumVerticalGap(Side::Left, pose, &gap, &y));
  pose.vertical_m -= gap + 30e-6;
  return pose;
}

CandidateOptions Combine(double distance_m) {
  CandidateOptions o;
  o.combine_distance_m = distance_m;
  return o;
}

}  // namespace

TEST(PatchGrouping, TwoAdjacentRegionsAreOneCurvedPatch) {
  const WheelsetTrackGeometry g = Track(kDipDepth);
  const WheelsetPose pose = Pushed(g);
  // separate: two regions on either side of the dip, a gap between them
  const CandidateResult separate = FindContactCandidates(g, Side::Left, pose, Combine(0.0));
  ASSERT_EQ(separate.status, CandidateStatus::Ok);
  ASSERT_EQ(separate.candidates.size(), 2u);
  const ContactCandidate& a = separate.candidates[0];
  const ContactCandidate& b = separate.candidates[1];
  const double gap_s = b.region_start_s_m - a.region_end_s_m;
  EXPECT_GT(gap_s, 0.3e-3);
  EXPECT_LT(gap_s, 4e-3);  // below CONTACT's D_COMB
  // each separate patch is nearly flat on its own side of the crown
  EXPECT_GT(std::fabs(a.patch.contact_angle_rad - b.patch.contact_angle_rad), 0.1);

  // default (4 mm): one patch over both regions and the gap
  const CandidateResult merged = FindContactCandidates(g, Side::Left, pose);
  ASSERT_EQ(merged.status, CandidateStatus::Ok);
  ASSERT_EQ(merged.candidates.size(), 1u);
  const ContactCandidate& m = merged.candidates[0];
  EXPECT_NEAR(m.region_start_s_m, a.region_start_s_m, 1e-9);
  EXPECT_NEAR(m.region_end_s_m, b.region_end_s_m, 1e-9);
  const PatchGeometry& p = m.patch;
  ASSERT_GE(p.strips(), 2u);
  // strips cover both regions and the gap contiguously (uniform ds)
  const double s_ref = p.reference_s_on_rail_m;
  EXPECT_LE(p.s_m.front() + s_ref, a.region_start_s_m);
  EXPECT_GE(p.s_m.back() + s_ref, b.region_end_s_m);
  for (size_t j = 1; j < p.strips(); ++j) EXPECT_NEAR(p.s_m[j] - p.s_m[j - 1], p.ds_m, 1e-12);
  // reference at the centre of the combined interval
  EXPECT_NEAR(s_ref, 0.5 * (a.region_start_s_m + b.region_end_s_m), 1e-9);
  // local normals of a circular crown: alpha(s) turns by ds / R per unit arc length, across the whole span
  // (patch.hpp: + towards +s, alpha = s / R on a circle)
  for (size_t j = 0; j < p.strips(); ++j) EXPECT_NEAR(p.alpha_rad[j], p.s_m[j] / kRailRadius, 2e-4) << j;
  const double alpha_span = p.alpha_rad.back() - p.alpha_rad.front();
  const double region_span = (b.region_end_s_m - a.region_start_s_m) / kRailRadius;
  EXPECT_GT(alpha_span, region_span);  // the margins add to the regions' span
  // the gap is open inside the dip (positive gap strips between the two regions), closed in both regions
  double gap_at_centre = -1.0;
  for (size_t j = 0; j < p.strips(); ++j) {
    EXPECT_TRUE(std::isfinite(p.gap_m[j]));
    if (std::fabs(p.s_m[j] + s_ref - 0.5 * (a.region_end_s_m + b.region_start_s_m)) < p.ds_m) gap_at_centre = p.gap_m[j];
  }
  EXPECT_GT(gap_at_centre - 0.0, p.rigid_approach_m);  // the dip's strips do not interpenetrate
  EXPECT_GT(p.rigid_approach_m, 0.0);

  // a combine distance just below the gap keeps them separate, just above merges them
  EXPECT_EQ(FindContactCandidates(g, Side::Left, pose, Combine(0.9 * gap_s)).candidates.size(), 2u);
  EXPECT_EQ(FindContactCandidates(g, Side::Left, pose, Combine(1.1 * gap_s)).candidates.size(), 1u);
}

TEST(PatchGrouping, SingleRegionIsUnchangedByCombining) {
  const WheelsetTrackGeometry g = Track(0.0);  // no dip: one region
  const WheelsetPose pose = Pushed(g);
  const CandidateResult off = FindContactCandidates(g, Side::Left, pose, Combine(0.0));
  const CandidateResult on = FindContactCandidates(g, Side::Left, pose);
  ASSERT_EQ(off.candidates.size(), 1u);
  ASSERT_EQ(on.candidates.size(), 1u);
  EXPECT_EQ(off.candidates[0].patch.s_m, on.candidates[0].patch.s_m);
  EXPECT_EQ(off.candidates[0].patch.gap_m, on.candidates[0].patch.gap_m);
  EXPECT_EQ(off.candidates[0].patch.alpha_rad, on.candidates[0].patch.alpha_rad);
}

TEST(PatchGrouping, NegativeCombineDistanceIsAnInputError) {
  const WheelsetTrackGeometry g = Track(kDipDepth);
  EXPECT_THROW(FindContactCandidates(g, Side::Left, Pushed(g), Combine(-1e-3)), InputError);
  WheelContactOptions o;
  o.patch_combine_distance_m = -1e-3;
  EXPECT_THROW(o.validate(), InputError);
}

TEST(PatchGrouping, MergedPatchCarriesTheLoadInLoadControl) {
  const WheelsetTrackGeometry g = Track(kDipDepth);
  WheelsetVelocity v;
  v.forward_speed_m_s = 10.0;
  v.axle_angular_velocity_rad_s = 10.0 / 0.46;
  for (ContactModel model : {ContactModel::Conformal, ContactModel::Kpec, ContactModel::Exact}) {
    for (double combine : {0.0, kDefaultCombineDistanceM}) {
      WheelContactOptions o;
      o.model = model;
      o.vertical_load_N = 20e3;
      o.patch_combine_distance_m = combine;
      o.solve_tangential = false;
      const WheelContactReport r = SolveWheelContact(g, Side::Left, WheelsetPose{}, v, o);
      ASSERT_EQ(r.status, WheelContactStatus::Ok) << to_string(model) << " combine " << combine;
      // at this load the two regions of the rigid search are 30 um deep or less: separate without combining
      ASSERT_EQ(r.patches.size(), combine > 0.0 ? 1u : 2u) << to_string(model);
      double fn = 0.0;
      for (const PatchReport& p : r.patches) {
        EXPECT_TRUE(std::isfinite(p.fn_N) && std::isfinite(p.pmax_Pa) && std::isfinite(p.area_m2));
        EXPECT_GT(p.pmax_Pa, 0.0);
        fn += p.fn_N;
      }
      // load control balances the vertical pressure force; the symmetric merged patch's normal is vertical, so
      // its normal force is the load
      EXPECT_NEAR(r.pressure_vertical_force_N, o.vertical_load_N, 1e-4 * o.vertical_load_N) << to_string(model);
      if (combine > 0.0) {
        EXPECT_NEAR(r.patches[0].contact_angle_rad, 0.0, 1e-3);
        EXPECT_NEAR(fn, o.vertical_load_N, 1e-3 * o.vertical_load_N) << to_string(model);
      }
    }
  }
}
