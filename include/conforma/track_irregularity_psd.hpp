#pragma once
// Published power spectral densities of track geometry irregularities (docs/physics-reference.md §15.1).
//
// All PSDs here are ONE-SIDED and in m^2 / (rad/m) over the angular wavenumber Omega = 2 pi / lambda (rad/m): the
// variance of an irregularity over a wavenumber band is the integral of S over that band (no factor 2).
//
//   ORE B176 (ERRI B176, "low" and "high" level of disturbance; European spectra for vehicle acceptance):
//     alignment, vertical level:  S(Omega) = A Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2))
//     Omega_c = 0.8246 rad/m, Omega_r = 0.0206 rad/m;
//     A_alignment = 2.119e-7 (low), 6.125e-7 (high) m rad; A_level = 4.032e-7 (low), 1.080e-6 (high) m rad.
//     cross-level, as a height difference of the two rails over the rail-centre distance 2 b (b = 0.75 m):
//     S_c(Omega) = (A_level / b^2) Omega_c^2 Omega^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2)(Omega^2 + Omega_s^2))
//     in rad^2 / (rad/m) (cross-level ANGLE), Omega_s = 0.4380 rad/m.
//   FRA track classes 1..6 (Garg & Dukkipati, Dynamics of Railway Vehicle Systems, 1984, §3; Hamid & Yang 1981):
//     S(Omega) = k A Omega_c^2 / (Omega^2 (Omega^2 + Omega_c^2)), k = 0.25, Omega_c = 0.8245 rad/m,
//     A in cm^2 rad/m per class: alignment 3.3634, 1.2107, 0.4128, 0.3027, 0.0762, 0.0339;
//     vertical level 1.2107, 1.0181, 0.6816, 0.5376, 0.2095, 0.0339 (converted here to m^2 rad/m).
#include <string>

namespace conforma {

enum class IrregularitySpectrum {
  OreB176Low,   // ORE B176, low level of disturbance (good European main line)
  OreB176High,  // ORE B176, high level of disturbance
  FraClass1,    // FRA track class 1 (worst, 10 mph freight)
  FraClass2,    // FRA class 2
  FraClass3,    // FRA class 3
  FraClass4,    // FRA class 4
  FraClass5,    // FRA class 5
  FraClass6,    // FRA class 6 (best, 110 mph)
};
const char* to_string(IrregularitySpectrum spectrum);  // "ore_b176_low", ..., "fra_class_6"
// Throws InputError naming the accepted names for an unknown one.
IrregularitySpectrum ParseIrregularitySpectrum(const std::string& name);

enum class IrregularityComponent {
  Alignment,      // lateral deviation of the track centre line, m
  VerticalLevel,  // vertical deviation of the track centre line, m
  CrossLevel,     // cross-level angle (height difference of the rails over their distance), rad
};

// Whether the spectrum defines a cross-level PSD (the ORE B176 levels; the FRA classes do not).
bool HasCrossLevelSpectrum(IrregularitySpectrum spectrum);

// S(Omega) in m^2/(rad/m) (cross-level: rad^2/(rad/m)); Omega > 0 in rad/m. FRA classes have no cross-level
// spectrum: InputError.
double IrregularityPsd(IrregularitySpectrum spectrum, IrregularityComponent component, double omega_rad_m);

// Exact integral of IrregularityPsd over [omega_min, omega_max] (0 < omega_min <= omega_max), from the partial
// fractions of the rational PSDs: the variance (m^2, rad^2 for cross-level) of the band.
double IrregularityBandVariance(IrregularitySpectrum spectrum, IrregularityComponent component, double omega_min_rad_m,
                                double omega_max_rad_m);

}  // namespace conforma
