#pragma once
// Track geometry irregularities along the track: synthesised from a published PSD (track_irregularity_psd.hpp),
// seeded and reproducible, or read from a measured file; evaluated at any distance s for the time-domain vehicle
// model (docs/physics-reference.md §15.2).
//
// SYNTHESIS (§15.2, the spectral representation of a stationary Gaussian process, Shinozuka & Deodatis 1991 eq. 45):
//   x(s) = sum_k a_k cos(Omega_k s + phi_k),  Omega_k = 2 pi k / L,  a_k = sqrt(2 S(Omega_k) dOmega),  dOmega = 2 pi / L,
// over the wavenumbers whose wavelength 2 pi / Omega_k lies in [wavelength_min_m, wavelength_max_m]; phi_k uniform
// in [0, 2 pi) from std::mt19937_64 (a fully specified generator) seeded by `seed` and the component, so the same
// options give the same track bit for bit on any machine and thread count. The signal is L-periodic and its
// variance over one period is exactly sum_k a_k^2 / 2 (the PSD's band integral up to the rectangle rule).
//
// MEASURED FILE (CSV, '#' comments and blank lines ignored, header with named columns in any order):
//   s_m                   distance along the track, strictly increasing (required)
//   alignment_m           lateral deviation of the track centre line, + towards the LEFT rail (required)
//   vertical_level_m      vertical deviation of the track centre line, + up (optional, default 0)
//   cross_level_rad       cross-level angle, + raises the LEFT rail (optional, default 0)
//   Errors name the file and line (InputError).
#include <cstdint>
#include <string>
#include <vector>

#include "conforma/track_irregularity_psd.hpp"

namespace conforma {

struct TrackIrregularityOptions {
  IrregularitySpectrum spectrum = IrregularitySpectrum::OreB176Low;
  double length_m = 1000.0;          // L: synthesised length (the signal is L-periodic), > 0
  double spacing_m = 0.25;           // sample spacing ds, > 0, <= wavelength_min_m / 4
  double wavelength_min_m = 3.0;     // band of the synthesised wavelengths (EN 14363 D1-D3: 3-150 m), > 0
  double wavelength_max_m = 150.0;   // >= wavelength_min_m and <= length_m
  std::uint64_t seed = 1;            // phases; components use independent streams
  bool cross_level = true;           // synthesise cross-level (ORE spectra only; FRA: left 0)
  void validate() const;             // InputError naming the option
};

// The irregularity at one distance.
struct TrackIrregularitySample {
  double alignment_m = 0.0;          // lateral deviation of the track centre line (+ left)
  double alignment_slope = 0.0;      // d(alignment)/ds (dimensionless): the track tangent's turn, rad
  double vertical_level_m = 0.0;     // + up
  double cross_level_rad = 0.0;      // + raises the left rail
};

class TrackIrregularity {
 public:
  TrackIrregularity() = default;
  // Samples at s_m (strictly increasing, >= 2 points); slopes of the alignment (empty: central differences).
  TrackIrregularity(std::string source, std::vector<double> s_m, std::vector<double> alignment_m,
                    std::vector<double> alignment_slope, std::vector<double> vertical_level_m,
                    std::vector<double> cross_level_rad);
  // Cubic Hermite in the alignment (values and slopes), linear in level and cross-level. Outside [s_begin, s_end]:
  // InputError naming s and the range (never an extrapolation).
  TrackIrregularitySample At(double s_m) const;
  double s_begin() const { return s_.empty() ? 0.0 : s_.front(); }
  double s_end() const { return s_.empty() ? 0.0 : s_.back(); }
  const std::string& source() const { return source_; }
  const std::vector<double>& s() const { return s_; }
  const std::vector<double>& alignment() const { return alignment_; }
  const std::vector<double>& alignment_slope() const { return slope_; }
  const std::vector<double>& vertical_level() const { return level_; }
  const std::vector<double>& cross_level() const { return cross_; }

 private:
  std::string source_;
  std::vector<double> s_, alignment_, slope_, level_, cross_;
};

// The empty (perfect) track over [0, length_m]: all zero.
TrackIrregularity PerfectTrack(double length_m);
TrackIrregularity SynthesizeTrackIrregularity(const TrackIrregularityOptions& options);
TrackIrregularity ReadTrackIrregularityCsv(const std::string& path);
// Columns s_m, alignment_m, alignment_slope, vertical_level_m, cross_level_rad, %.17g (round trip bit-exact).
void WriteTrackIrregularityCsv(const TrackIrregularity& track, const std::string& path);

}  // namespace conforma
