// Track input of the time-domain model (vehicle_dynamics_track.hpp): the curve with clothoid transitions and cant
// ramps, and the relative position of the centre line between two stations (heading change and lateral offset)
// against the closed-form integrals of a constant and a linear curvature; across a break point of the curvature
// (the quadrature splits its panels at MakeCurveTrack's break points) to rounding, and without the break points
// (the integrand's kink inside a Gauss panel) within 1e-3 relative.
// test-links: dynamics

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/vehicle_dynamics_track.hpp"

namespace conforma {
namespace {

CurveTrackSpec Spec() {
  CurveTrackSpec k;
  k.tangent_length_m = 20.0;
  k.transition_length_m = 40.0;
  k.radius_m = -400.0;  // turning right
  k.curve_length_m = 60.0;
  k.cant_m = 0.09;
  return k;
}

TEST(VehicleDynamicsTrack, CurveWithTransitionsAndCantRamps) {
  const TrackInput t = MakeCurveTrack(Spec());
  EXPECT_EQ(t.curvature(10.0), 0.0);
  EXPECT_NEAR(t.curvature(40.0), -0.5 / 400.0, 1e-15);  // half-way up the entry transition
  EXPECT_NEAR(t.curvature(90.0), -1.0 / 400.0, 1e-15);
  EXPECT_NEAR(t.curvature(150.0), -0.25 / 400.0, 1e-15);  // a quarter of the way down the exit
  EXPECT_EQ(t.curvature(200.0), 0.0);
  // a right curve's outer rail is the left one: the cant is negative (+ raises the right rail)
  EXPECT_NEAR(t.cant(40.0), -0.045, 1e-15);
  EXPECT_NEAR(t.cant(90.0), -0.09, 1e-15);
  EXPECT_NEAR(t.curvature_derivative(40.0), -1.0 / (400.0 * 40.0), 1e-12);
  CurveTrackSpec bad = Spec();
  bad.radius_m = 5.0;
  EXPECT_THROW(MakeCurveTrack(bad), InputError);
}

TEST(VehicleDynamicsTrack, RelativePositionMatchesTheClosedFormIntegrals) {
  const TrackInput t = MakeCurveTrack(Spec());
  const double c = -1.0 / 400.0, dc = c / 40.0;
  // on the arc: dTheta = c d, D = c d^2 / 2 (either direction)
  for (const double d : {1.25, -1.25, -5.46, 7.0}) {
    const TrackRelativePosition r = RelativeTrackPosition(t, 90.0, 90.0 + d);
    EXPECT_NEAR(r.heading_change_rad, c * d, 1e-15);
    EXPECT_NEAR(r.lateral_offset_m, 0.5 * c * d * d, 1e-15);
  }
  // inside the entry transition, c = dc (u - 20): with a = s_P - 20, b = s_C - 20
  //   dTheta = dc (b^2 - a^2) / 2,   D = dc (b^3 / 6 - b a^2 / 2 + a^3 / 3)
  for (const auto& [sp, sc] : {std::pair<double, double>{30.0, 35.5}, {50.0, 41.0}}) {
    const double a = sp - 20.0, b = sc - 20.0;
    const TrackRelativePosition r = RelativeTrackPosition(t, sp, sc);
    EXPECT_NEAR(r.heading_change_rad, 0.5 * dc * (b * b - a * a), 1e-15);
    EXPECT_NEAR(r.lateral_offset_m, dc * (b * b * b / 6.0 - b * a * a / 2.0 + a * a * a / 3.0), 1e-14);
  }
  // across the start of the transition (tangent 16 .. 20, then c = dc (u - 20) up to 25.5)
  {
    const double b = 5.5;
    const TrackRelativePosition r = RelativeTrackPosition(t, 16.0, 25.5);
    EXPECT_NEAR(r.heading_change_rad, 0.5 * dc * b * b, 1e-17);
    EXPECT_NEAR(r.lateral_offset_m, dc * b * b * b / 6.0, 1e-16);
    TrackInput no_breaks = t;
    no_breaks.curvature_breaks_m.clear();
    const TrackRelativePosition q = RelativeTrackPosition(no_breaks, 16.0, 25.5);
    EXPECT_NEAR(q.heading_change_rad / (0.5 * dc * b * b), 1.0, 1e-3);
    EXPECT_NEAR(q.lateral_offset_m / (dc * b * b * b / 6.0), 1.0, 1e-3);
  }
  // no curvature function: zero
  const TrackRelativePosition z = RelativeTrackPosition(TrackInput{}, 0.0, 10.0);
  EXPECT_EQ(z.heading_change_rad, 0.0);
  EXPECT_EQ(z.lateral_offset_m, 0.0);
}

TEST(VehicleDynamicsTrack, IrregularityOfTheTrackModuleBecomesTheTrackInput) {
  // a sine alignment with its slope and a cross-level angle, sampled at 0.25 m
  std::vector<double> s, y, dy, z, cl;
  const double A = 3e-3, k = 2.0 * M_PI / 10.0;
  for (int i = 0; i <= 400; ++i) {
    s.push_back(5.0 + 0.25 * i);
    y.push_back(A * std::sin(k * 0.25 * i));
    dy.push_back(A * k * std::cos(k * 0.25 * i));
    z.push_back(0.0);
    cl.push_back(1e-3 * std::cos(k * 0.25 * i));
  }
  const TrackIrregularity irr("sine", s, y, dy, z, cl);
  TrackInput t = MakeCurveTrack(CurveTrackSpec{});
  SetTrackIrregularity(t, irr, 1.5);
  for (const double x : {5.0, 17.3, 60.125, 104.9}) {
    EXPECT_EQ(t.alignment(x), irr.At(x).alignment_m);
    EXPECT_EQ(t.alignment_derivative(x), irr.At(x).alignment_slope);
    EXPECT_EQ(t.cross_level(x), -1.5 * irr.At(x).cross_level_rad);  // + raises the right rail
  }
  EXPECT_NEAR(t.alignment(17.3), A * std::sin(k * 12.3), 1e-3 * A);  // Hermite between the samples
  EXPECT_EQ(t.curvature(0.0), 0.0);                                    // the curve is kept (tangent here)
  EXPECT_THROW(t.alignment(200.0), InputError);                       // beyond the samples: never extrapolated
}

}  // namespace
}  // namespace conforma
