#pragma once
// The track as the time-domain vehicle model sees it (vehicle_dynamics_model.hpp): functions of the distance s
// along the design centre line (m). Every member may be left empty (then 0).
//   curvature_per_m(s)  c = 1/R of the design centre line; > 0 turns LEFT (TrackClass convention: the left rail
//                       is the inner one)
//   cant_m(s)           signed superelevation, + raises the RIGHT rail (the outer rail of a left curve): the
//                       gravity component in the track plane is -g cant / cant_base (towards -y for cant > 0)
//   alignment_m(s)      lateral irregularity y_irr of the actual centre line from the design one, + left, m
//   alignment_slope(s)  d y_irr / ds (give it with alignment_m; empty: a central difference of alignment_m)
//   cross_level_m(s)    cross-level irregularity, + raises the right rail (added to the cant in the gravity term)
// Each body of the vehicle is described relative to the design centre line at its own s (local track frame, as
// in the quasi-static curving model); the contact sees the actual (irregular) rails.
#include <functional>
#include <memory>
#include <vector>

#include "conforma/track_irregularity.hpp"

namespace conforma {

struct TrackInput {
  std::function<double(double)> curvature_per_m;  // 1/m
  std::function<double(double)> cant_m;           // m
  std::function<double(double)> alignment_m;      // m
  std::function<double(double)> alignment_slope;  // rad (dimensionless)
  std::function<double(double)> cross_level_m;    // m
  // Stations where the curvature or its slope jumps (m, ascending; may be empty): the quadrature of
  // RelativeTrackPosition splits its panels there, so a piecewise-linear curvature is integrated exactly.
  std::vector<double> curvature_breaks_m;

  double curvature(double s) const { return curvature_per_m ? curvature_per_m(s) : 0.0; }
  double cant(double s) const { return cant_m ? cant_m(s) : 0.0; }
  double alignment(double s) const { return alignment_m ? alignment_m(s) : 0.0; }
  double alignment_derivative(double s) const;  // alignment_slope, else a central difference over +/- 1 mm
  double cross_level(double s) const { return cross_level_m ? cross_level_m(s) : 0.0; }
  // dc/ds, central difference over +/- 1 mm (exact for the piecewise-linear curvature of MakeCurveTrack away
  // from its break points)
  double curvature_derivative(double s) const;
};

// Tangent, entry transition, circular arc, exit transition, tangent, from s = 0. Transitions are clothoids
// (curvature linear in s) with linear cant ramps over the same length; beyond the exit transition the track is
// tangent for ever. validate() throws InputError naming the field.
struct CurveTrackSpec {
  double tangent_length_m = 50.0;     // m, >= 0: tangent before the entry transition
  double transition_length_m = 50.0;  // m, >= 0 (0: curvature and cant jump)
  double radius_m = 0.0;              // m, 0 = tangent track only; > 0 turns left, < 0 right; |R| >= 10 m
  double curve_length_m = 100.0;      // m, >= 0: the circular arc
  double cant_m = 0.0;                // m, >= 0: superelevation of the arc (raises the outer rail)
  void validate() const;
};
TrackInput MakeCurveTrack(const CurveTrackSpec& spec);

// Irregularities of a TrackIrregularity (track_irregularity.hpp: PSD synthesis or measured file) as the track
// input's alignment_m, alignment_slope and cross_level_m. Its cross-level angle (+ raises the LEFT rail) becomes the
// height -cross_level_rad * cant_base_m (+ raises the right rail, as the cant). The vertical level is not used (no
// vertical degrees of freedom). The functions keep a copy of the samples; outside the samples' range they throw
// InputError naming s and the range (TrackIrregularity::At): the irregularity must cover the run.
void SetTrackIrregularity(TrackInput& track, const TrackIrregularity& irregularity, double cant_base_m);

// Relative position of the design centre line between two stations s_from and s_to (small angles), in the
// local track frame at s_from: the heading change dTheta = int c ds and the lateral offset
// D = int_{s_from}^{s_to} (Theta(u) - Theta(s_from)) du = int_{s_from}^{s_to} (s_to - u) c(u) du (Cauchy's
// repeated-integral formula); constant c: dTheta = c d, D = c d^2 / 2. Gauss-Legendre, 4 points per panel of at
// most 1 m, panels split at TrackInput::curvature_breaks_m (exact for a curvature that is a cubic between them).
struct TrackRelativePosition {
  double heading_change_rad = 0.0;  // dTheta
  double lateral_offset_m = 0.0;    // D
};
TrackRelativePosition RelativeTrackPosition(const TrackInput& track, double s_from, double s_to);

}  // namespace conforma
