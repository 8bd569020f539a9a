#pragma once
// Wear laws: the depth of material a contact cell removes per metre rolled through it.
//
// Two families:
//  * Wear-index (T-gamma/A) laws, paper 003 eqs. 14-17, docs/physics-reference.md §8.1:
//      I_w = |p_t . s|                      [N/mm^2]  (p_t tangential traction, s relative slip [-])
//      K_w = K_w(I_w)                        [ug/(m mm^2)]  mass per metre rolled and mm^2 of surface
//      depth per metre rolled = K_w / rho   (rho in ug/mm^3 equals rho in kg/m^3 numerically)
//    The built-in USFD (Lewis & Dwyer-Joyce 2004 / Braghin et al. 2006) law is usfd_wear_rate(); any
//    piecewise-linear K_w(I_w) is a WearIndexLaw (table of breakpoints, jumps as repeated abscissae).
//  * Archard with a wear-coefficient map k(p, v_slip), paper 000 eqs. 6-10 and Tables 2-3,
//    docs/physics-reference.md §8.2:  depth = k p d_slip / H with d_slip = |s| dx, v_slip = |s| V.
//
// All functions are pure; SI units except where a name carries the field's unit (N/mm^2, ug/(m mm^2)).
#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "conforma/material.hpp"

namespace conforma {

// ---------------------------------------------------------------- wear-index (T-gamma/A) laws

// USFD law (docs/physics-reference.md §8.1, coefficients for R8T wheel vs UIC60 900A rail as in Braghin et al.
// 2006, confirmed by a third-party code):
//   K = 5.3 I                 I < 10.4          (mild)
//   K = 55.0                  10.4 <= I <= 77.2 (severe)
//   K = 61.9 I - 4778.7       I > 77.2          (catastrophic)
// Paper 003 eq. 15 prints 55.1 for the severe plateau; docs/physics-reference.md and the third-party code use
// 55.0 (0.2 % apart). 55.0 is the default; set severe_rate to 55.1 to follow paper 003 literally.
// The law is discontinuous at 77.2 (61.9*77.2 - 4778.7 = -0.02, not 55): the catastrophic branch
// restarts from about zero. Negative rates (just above 77.2) are clamped to 0.
struct UsfdCoefficients {
  double mild_slope = 5.3;                   // [ug/(m mm^2) per N/mm^2]
  double mild_limit_N_mm2 = 10.4;            // I_w where the mild branch ends [N/mm^2]
  double severe_rate = 55.0;                 // [ug/(m mm^2)]
  double severe_limit_N_mm2 = 77.2;          // I_w where the severe plateau ends [N/mm^2]
  double catastrophic_slope = 61.9;          // [ug/(m mm^2) per N/mm^2]
  double catastrophic_intercept = -4778.7;   // [ug/(m mm^2)]
};

// USFD regime of a wear index: Mild (I < mild_limit), Severe (mild_limit <= I <= severe_limit), Catastrophic (above).
enum class WearRegime { Mild, Severe, Catastrophic };
const char* to_string(WearRegime regime);  // "mild", "severe", "catastrophic"

// USFD wear rate K_w [ug/(m mm^2)] at wear index I_w [N/mm^2] (closed form above).
double usfd_wear_rate(double wear_index_N_mm2, const UsfdCoefficients& c = {});
WearRegime usfd_regime(double wear_index_N_mm2, const UsfdCoefficients& c = {});

// Wear index of one cell, paper 003 eq. 14: I_w = |p_t . s| converted to N/mm^2 (1 N/mm^2 = 1e6 Pa).
double wear_index_N_mm2(const Eigen::Vector2d& traction_Pa, const Eigen::Vector2d& slip);

// Depth [m] removed per metre rolled for a wear rate K_w [ug/(m mm^2)] and density [kg/m^3]
// (paper 003 eqs. 16-17): K_w [ug/mm^2 per m] / rho [ug/mm^3] = K_w/rho [mm per m] -> * 1e-3 [m per m].
double depth_per_rolled_metre_from_rate(double rate_ug_m_mm2, double density_kg_m3);

// Piecewise-linear K_w(I_w) through breakpoints (I_k, K_k), I non-decreasing, first I = 0. A jump is two
// consecutive points with the same I; exactly at a jump the LEFT value (first of the two) applies.
// Beyond the last point the last segment continues linearly. Rates below 0 are clamped to 0.
struct WearIndexPoint {
  double wear_index_N_mm2 = 0.0;  // I_k [N/mm^2], >= 0
  double rate_ug_m_mm2 = 0.0;     // K_k [ug/(m mm^2)]
};
struct WearIndexLaw {
  std::string name;                    // for messages and output ("usfd", the file's name line)
  std::vector<WearIndexPoint> points;  // the breakpoints, at least 2
  // Throws InputError naming the law when the table is malformed (fewer than 2 points, not finite,
  // decreasing I, first I != 0, more than two points at one I).
  void validate() const;
  double rate(double wear_index_N_mm2) const;  // [ug/(m mm^2)]
  // The USFD closed form as a table (breakpoints at the regime limits, last point at 200 N/mm^2).
  static WearIndexLaw Usfd(const UsfdCoefficients& c = {});
};

// ---------------------------------------------------------------- Archard wear-coefficient maps

// k(p, v_slip): velocity bins (upper limits increasing, the last one +inf), each with a coefficient for
// p <= severe_pressure_ratio * H ("mild", regions K2..K4) and for p > severe_pressure_ratio * H
// (region K1). A value exactly on a bin limit belongs to the lower bin.
struct ArchardBin {
  double velocity_upper_m_s = std::numeric_limits<double>::infinity();  // upper limit of the bin [m/s]
  double k_mild = 0.0;    // [-]
  double k_severe = 0.0;  // [-]
};
struct ArchardMap {
  std::string name;                    // for messages and output
  double hardness_Pa = 2.75e9;         // H [Pa]
  double severe_pressure_ratio = 0.8;  // p > 0.8 H -> k_severe (paper 000 Table 2)
  std::vector<ArchardBin> bins;        // velocity bins, upper limits increasing, the last +inf
  void validate() const;  // throws InputError naming the map
  double coefficient(double pressure_Pa, double sliding_velocity_m_s) const;  // k [-]

  // Jendel (2002) map as quoted in paper 000 Table 2 (ranges K1 = 300-400e-4, K2 = 1-10e-4 for
  // v < 0.2 m/s, K3 = 30-40e-4 for 0.2..0.7 m/s, K4 = 1-10e-4 above). The map gives ranges only; this
  // uses the MID-POINTS (350e-4, 5.5e-4, 35e-4, 5.5e-4), a choice of ours. H = 2.75 GPa is the middle
  // of the 2.5-3 GPa that docs/physics-reference.md §8.2 recalls [MEM, unverified].
  static ArchardMap Jendel();
  // Paper 000 Table 3 (scaled roller rig, soft Fe360 wheel / Fe510 roller, tuned to the rig): wheel and
  // roller maps, values verbatim; the table labels them "m/km", we read them as the dimensionless Archard
  // coefficient of eq. 6-8 (as Jendel's). Hardness from paper 000 Table 4: HB 100 (wheel) / HB 160
  // (roller), taken as kgf/mm^2 (0.98 / 1.57 GPa). Rig-specific: recalibrate before full-scale use.
  static ArchardMap Paper000Wheel();
  static ArchardMap Paper000Roller();
};

// ---------------------------------------------------------------- one law for one body

// WearIndex: T-gamma/A law K_w(I_w) (WearIndexLaw); Archard: coefficient map k(p, v_slip) (ArchardMap).
enum class WearLawKind { WearIndex, Archard };
const char* to_string(WearLawKind kind);  // "wear_index", "archard"

struct WearLaw {
  WearLaw();  // wear-index kind with the USFD table; archard = ArchardMap::Jendel()
  WearLawKind kind = WearLawKind::WearIndex;  // which of the two below applies
  WearIndexLaw wear_index;  // used when kind == WearIndex
  ArchardMap archard;       // used when kind == Archard
  const std::string& name() const { return kind == WearLawKind::WearIndex ? wear_index.name : archard.name; }
  void validate() const;

  // Depth [m] removed per metre rolled through a cell with tangential traction p_t [Pa], relative slip
  // s [-] (slip velocity / V), normal pressure p [Pa] at rolling speed V [m/s] (V only enters the
  // Archard sliding velocity v_slip = |s| V). A cell of length dx along the rolling direction removes
  // depth_per_rolled_metre * dx per passage.
  //  wear index: K_w(|p_t . s| / 1e6) / rho * 1e-3                  (paper 003 eqs. 14-17)
  //  Archard:    k(p, |s| V) * p * |s| / H                            (paper 000 eqs. 8-9)
  double depth_per_rolled_metre(const Eigen::Vector2d& traction_Pa, const Eigen::Vector2d& slip,
                                double pressure_Pa, double rolling_speed_m_s, const Material& material) const;
};

// ---------------------------------------------------------------- wear-law files
// A small CSV format ('#' starts a comment, blank lines ignored, fields separated by commas):
//   kind,wear_index                      | kind,archard
//   name,<free text>                     | name,<free text>
//   point,<I_w N/mm^2>,<K_w ug/(m mm^2)> | hardness_Pa,<H>
//   point,...                            | severe_pressure_ratio,<0.8>
//                                        | bin,<v_upper m/s or inf>,<k_mild>,<k_severe>
// Throws InputError "<file>:<line>: ..." for malformed content.
WearLaw LoadWearLaw(const std::string& path);
WearLaw ParseWearLaw(const std::string& text, const std::string& source);
std::string FormatWearLaw(const WearLaw& law);

}  // namespace conforma
