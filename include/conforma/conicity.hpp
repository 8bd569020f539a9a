#pragma once
// Rolling-radius difference Delta r(y) = r_left - r_right of a wheelset on straight track (rigid contact,
// vertical position and roll such that both wheels touch) and the equivalent conicity of EN 15302.
//
// Equivalent conicity (EN 15302, reference method): the wheelset's kinematic (Klingel) oscillation with the
// non-linear Delta r(y),  y'' = -Delta r(y) / (2 e r0), has the energy integral
//     y'^2 = (C - S(y)) / (e r0),   S(y) = integral of Delta r from the centre (S minimum, Delta r = 0),
// turning points y1 < y2 with S(y1) = S(y2) = C, amplitude y_hat = (y2 - y1) / 2 and wavelength
//     lambda = 2 sqrt(e r0) * integral_{y1}^{y2} dy / sqrt(C - S(y)).
// The equivalent conicity is the cone of the same wavelength (Klingel): tan(gamma_e) = (2 pi / lambda)^2 e r0
// = (pi / L)^2 with L = integral dy / sqrt(C - S); e and r0 cancel. This reproduces the EN 15302 benchmark
// values (ben_E<n>.dat) to 1e-3 from the benchmark's own Delta r tables.
// Alternative (for comparison only): harmonic (describing-function) linearisation about the same centre,
//     tan(gamma_e) = 1 / (2 pi y_hat) * integral_0^{2 pi} Delta r(y_c + y_hat sin t) sin t dt,
// which is exact for a cone but leaves the EN 15302 tolerance band for the strongly non-linear cases.
#include <vector>

#include "conforma/geometry.hpp"

namespace conforma {

// One entry per lateral shift (all vectors the same length); delta_r_m and the wheel y are 0 without contact.
struct RollingRadiusDifferenceCurve {
  std::vector<double> lateral_m;      // as requested, sorted ascending, m
  std::vector<double> delta_r_m;      // r_left - r_right at the smallest-gap contact of each wheel, m
  std::vector<double> roll_rad, vertical_m;  // solved roll (rad) and vertical position (m) of the wheelset pose
  std::vector<double> left_wheel_y_m, right_wheel_y_m;  // contact points in wheel-profile y, m
  std::vector<EquilibriumStatus> status;     // of SolveRigidEquilibrium at each shift
};
// Solves the rigid equilibrium at each lateral shift (continuation outwards from the shift nearest 0).
RollingRadiusDifferenceCurve ComputeRollingRadiusDifference(const WheelsetTrackGeometry& geometry,
                                                            std::vector<double> lateral_m, double yaw_rad = 0.0,
                                                            const EquilibriumOptions& options = {});

// KinematicIntegral: the EN 15302 reference method (wavelength of the Klingel oscillation, above);
// HarmonicLinearisation: the describing-function alternative (comparison only).
enum class ConicityMethod { KinematicIntegral, HarmonicLinearisation };
const char* to_string(ConicityMethod method);  // "kinematic integral", "harmonic linearisation"

// InputError for quadrature_points < 10.
struct ConicityOptions {
  ConicityMethod method = ConicityMethod::KinematicIntegral;  // default: the EN 15302 reference method
  // per half of the oscillation (kinematic integral; harmonic: 4x this over the period), >= 10
  int quadrature_points = 2000;
};

// Ok: conicity computed; AmplitudeOutOfRange: the oscillation of this amplitude leaves the Delta r table;
// NoCentre: Delta r has no sign change from - to + (no centre of the oscillation).
enum class ConicityStatus { Ok, AmplitudeOutOfRange, NoCentre };
const char* to_string(ConicityStatus status);  // "ok", "amplitude out of the Delta r range", "no centre (...)"

struct ConicityResult {
  ConicityStatus status = ConicityStatus::NoCentre;  // see ConicityStatus
  double amplitude_m = 0.0;          // y_hat as requested, m (set unless NoCentre)
  double equivalent_conicity = 0.0;  // tan(gamma_e), dimensionless, >= 0 (0 inside a plateau of Delta r = 0); Ok only
  double centre_m = 0.0;             // S minimum (Delta r = 0), m; set unless NoCentre
  double turning_left_m = 0.0, turning_right_m = 0.0;  // turning points y1 < y2 of the oscillation, m; Ok only
};

// Delta r given on an ascending lateral grid (linear between the points). Throws InputError for unsorted,
// non-finite or too short input, or a non-positive amplitude.
ConicityResult EquivalentConicity(const std::vector<double>& lateral_m, const std::vector<double>& delta_r_m,
                                  double amplitude_m, const ConicityOptions& options = {});

}  // namespace conforma
