// Track input of the time-domain model (vehicle_dynamics_track.hpp): the curve with clothoid transitions and cant
// ramps, and the relative position of the centre line between two stations (heading change and lateral offset)
// against the closed-form integrals of a constant and a linear curvature; across a break point of the curvature
// (the quadrature splits its panels at MakeCurveTrack's break points) to rounding, and without the break points
// (the integrand's kink inside a Gauss panel) within 1e-3 relative.
// test-links: dynamics

#include <gtest/gtest.h>

#include <cmath>

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

TEST(VehicleDynamicsTrack, SampledIrregularityInterpolatesValueAndSlope) {
  // samples of a sine of wavelength 10 m at 0.25 m: Catmull-Rom is within ~(h k)^2 / ... of the sine and its
  // slope, exact at the samples, continuous in slope, and 0 outside
  SampledTrackFunction f;
  f.s_begin_m = 5.0;
  f.spacing_m = 0.25;
  const double A = 3e-3, k = 2.0 * M_PI / 10.0;
  for (int i = 0; i <= 400; ++i) f.values.push_back(A * std::sin(k * i * f.spacing_m));
  TrackInput t;
  SetSampledIrregularities(t, f);
  EXPECT_EQ(t.alignment(5.0 + 0.25 * 17), f.values[17]);
  double max_value = 0.0, max_slope = 0.0;
  for (double s = 6.0; s < 100.0; s += 0.0137) {
    max_value = std::max(max_value, std::fabs(t.alignment(s) - A * std::sin(k * (s - 5.0))));
    max_slope = std::max(max_slope, std::fabs(t.alignment_derivative(s) - A * k * std::cos(k * (s - 5.0))));
  }
  EXPECT_LT(max_value, 1e-3 * A);
  EXPECT_LT(max_slope, 1e-2 * A * k);
  const double knot = 5.0 + 0.25 * 40;
  EXPECT_NEAR(t.alignment_derivative(knot - 1e-9), t.alignment_derivative(knot + 1e-9), 1e-9);
  EXPECT_EQ(t.alignment(4.0), 0.0);
  EXPECT_EQ(t.alignment(200.0), 0.0);
  SampledTrackFunction bad;
  bad.values = {1.0};
  EXPECT_THROW(SetSampledIrregularities(t, bad), InputError);
}

}  // namespace
}  // namespace conforma
