#pragma once
// EN 15302 equivalent-conicity benchmark (shared data profiles/en15302, docs/data.md): the nine wheel/rail
// combinations E1..E9 (wheels RUIC519{A,B,H,I}.dat, rail SUIC519A.dat already inclined 1:40, gauge
// 1435.16 mm at 14 mm, flange back 1360 mm, wheel diameters 920/920 or 920/918). Delta r(y) is computed
// with the wheelset roll held at zero and each wheel lowered onto its own rail (EquilibriumOptions::
// include_roll = false), which reproduces dr_ce_E<n>.dat best (the rigid roll about the axle centre shifts
// the contact-level lateral position by r0 * roll: E1 then has 90 of 137 points > 0.05 mm, not 36); the
// equivalent conicity by the EN 15302 kinematic integral (conicity.hpp) is compared with the tolerance band
// of ben_E<n>.dat at every listed amplitude. Measured agreement: tests/test_conicity_en15302.cpp.
//
// File orientations (from the data): wheel z is the height in the track (larger radius = lower), so the
// wheels are read with mirror_z; wheel y has the flange at negative y and the flange back at -70 mm; rail y
// points to the field side and z up (the file starts at the gauge point 14 mm below the crown).
#include <string>
#include <vector>

namespace conforma {

struct En15302Amplitude {
  // amplitude y_hat (mm) of a ben_E<n>.dat row; our equivalent conicity; the file's reference value and its
  // tolerance band [lower, upper] (conicities dimensionless, tan(gamma_e))
  double amplitude_mm = 0.0, conicity = 0.0, reference = 0.0, lower = 0.0, upper = 0.0;
  bool ok = false;  // status Ok and inside [lower, upper]
};

struct En15302Result {
  int combination = 0;                 // 1..9
  // lateral shift y, our Delta r (NaN where the equilibrium did not converge) and dr_ce_E<n>.dat's, on the reference
  // grid (0.1 mm), mm
  std::vector<double> y_mm, delta_r_mm, reference_delta_r_mm;
  double max_delta_r_error_mm = 0.0;   // max |Delta r - reference| over the grid, mm (inf when a point is NaN)
  int points_over_tolerance = 0;       // |Delta r - reference| > 0.05 mm (NaN points included)
  std::vector<En15302Amplitude> amplitudes;  // one per row of ben_E<n>.dat
  int outside_band = 0;                // amplitudes not ok
};

// Runs one combination (1..9). Throws InputError for a bad combination number or unreadable data.
En15302Result RunEn15302Combination(const std::string& shared_data_dir, int combination);

}  // namespace conforma
