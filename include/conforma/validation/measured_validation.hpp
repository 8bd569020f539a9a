#pragma once
// Validation of a wear simulation against measured wheels (issue 6, `conforma validate`):
//   (a) wheel reference dimensions Sd, Sh, qR (wheel_dimensions.hpp) measured against distance run, and
//   (b) measured wheel profiles at given distances.
//
// Simulated values between wear steps: a wear step ends where its largest removed depth reaches the cap
// (ScenarioUpdate::cap_m, 0.4 mm; paper 003 §6), so the simulated km values are set by the cap, not chosen by the
// user, and rarely coincide with the measured km. A simulated dimension at a measured km is the LINEAR
// INTERPOLATION in km between the two wear steps (or the initial profile, km 0) that bracket it. A measured km
// beyond the last simulated step is not extrapolated: the point is reported as beyond the simulation and left out
// of the error statistics.
//
// Simulated profile at a measured km: the profiles of the two bracketing steps a (earlier) and b are blended point
// by point, P(t) = P_a + t (Q_b - P_a), t = (km - km_a) / (km_b - km_a), where Q_b is the point of b closest to P_a
// (wear removes material along the normals, so Q_b - P_a is close to the normal of a).
// ProfileInterpolation::Nearest takes the nearer step instead.
//
// Profile distance (MeasureProfileDistance): the simulated profile is sampled every `spacing_m` of arc length; at
// each sample the distance to the measured curve is the distance to its closest point (i.e. along the measured
// curve's normal: the normal distance). Sign: positive where the measured surface lies OUTSIDE the simulated one
// (along the simulated outward normal: the simulation removed more material than measured). Only samples in the
// WORN ZONE count: where the simulated profile lies at least `worn_zone_min_depth_m` (default 0.01 mm) inside the
// initial (unworn) profile, or, when given, inside a lateral range [y_min, y_max]. Samples whose closest measured
// point is an end of the measured curve (the measurement does not cover them) are left out and counted.
// Reported: RMS and maximum of |distance|, the signed mean, and the zone's lateral extent.
//
// Measured dimension file (CSV, '#' comment lines, blank lines ignored, first other line is the header):
//   km,QR_mm,FH_mm,FT_mm          (MD061 fleet average: FT = flange thickness Sd, FH = flange height Sh, QR = qR)
// Column names are case-insensitive: km; Sd: ft_mm | sd_mm; Sh: fh_mm | sh_mm; qR: qr_mm. km is required and at
// least one dimension column; other columns are ignored (listed in ignored_columns). Every row has one field per
// header column; values must be finite and > 0 (km >= 0); km strictly increasing. Errors are InputError
// "<file>:<line>: <what>".
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "conforma/profile.hpp"
#include "conforma/wear_simulation.hpp"
#include "conforma/wheel_dimensions.hpp"

namespace conforma {

// ---------------------------------------------------------------- reference dimensions
// The wheel reference dimensions (wheel_dimensions.hpp, docs/physics-reference.md §8.9): Sd flange thickness, Sh
// flange height, qR flange slope measure; the values are the indices into the per-dimension arrays below.
enum class ReferenceDimension { Sd = 0, Sh = 1, qR = 2 };
constexpr std::array<ReferenceDimension, 3> kReferenceDimensions = {ReferenceDimension::Sd, ReferenceDimension::Sh,
                                                                    ReferenceDimension::qR};
const char* to_string(ReferenceDimension dimension);  // "Sd", "Sh", "qR"
double DimensionValue(const WheelDimensions& dimensions, ReferenceDimension dimension);  // [m]

struct MeasuredDimensionPoint {
  double km = 0.0;                                 // distance run, km, >= 0
  int line = 0;                                    // 1-based line in the file
  std::array<std::optional<double>, 3> value_m;   // m (file: mm), by ReferenceDimension; empty: column absent
};

struct MeasuredDimensions {
  std::string source;                              // file path (or the source name given to the parser)
  std::array<bool, 3> has{false, false, false};    // column present, by ReferenceDimension
  std::vector<MeasuredDimensionPoint> points;      // km strictly increasing
  std::vector<std::string> ignored_columns;        // header names not used, as written
};

// Throws InputError "<file>:<line>: <what>" (unreadable file, missing km / dimension column, wrong field count,
// non-numeric, NaN/inf or non-positive value, km not strictly increasing, no data rows).
MeasuredDimensions ReadMeasuredDimensions(const std::string& path);
MeasuredDimensions ParseMeasuredDimensions(const std::string& text, const std::string& source);

// ---------------------------------------------------------------- simulated series and interpolation
struct SimulatedDimensionSeries {
  std::vector<int> step;                     // 0 = initial profile, then the wear steps
  std::vector<double> km;                    // strictly increasing, km[0] = 0
  std::vector<WheelDimensions> dimensions;   // Sd/Sh/qR of each profile
};
// Initial profile at km 0 and every wheel step of the LAST rail step (with a fixed rail: all steps).
SimulatedDimensionSeries DimensionSeriesOf(const WearSimulationResult& result);

// Interpolated: the km lies within the simulated series (bracketed by two entries, or on one); BeyondSimulation:
// after its last step (not extrapolated).
enum class InterpolationStatus { Interpolated, BeyondSimulation };
const char* to_string(InterpolationStatus status);  // "interpolated", "beyond_simulation"

struct StepBracket {
  InterpolationStatus status = InterpolationStatus::Interpolated;  // see InterpolationStatus
  size_t before = 0, after = 0;  // indices into the series (equal when km hits a step exactly)
  double weight = 0.0;           // of `after`: value = (1 - weight) v[before] + weight v[after]
};
// Bracket of km in a strictly increasing km list starting at 0; km in [0, km.back()] (1e-9 relative slack at the
// end). Throws InputError for km < 0 or not finite, or an empty list.
StepBracket BracketKm(const std::vector<double>& km_list, double km);

struct InterpolatedDimension {
  StepBracket bracket;   // the simulated entries used
  double value_m = 0.0;  // 0 when BeyondSimulation
};
InterpolatedDimension InterpolateDimension(const SimulatedDimensionSeries& series, ReferenceDimension dimension,
                                           double km);

// ---------------------------------------------------------------- dimension comparison
struct DimensionComparisonPoint {
  double km = 0.0;  // measured distance, km
  int line = 0;  // line of the measured file
  ReferenceDimension dimension = ReferenceDimension::Sd;  // the dimension compared
  StepBracket bracket;  // simulated steps used (series indices)
  int step_before = 0, step_after = 0;  // wear step numbers (0 = initial)
  double simulated_m = 0.0, measured_m = 0.0;  // m (simulated 0 when BeyondSimulation)
  double error_m = 0.0;  // simulated - measured, m (0 and not counted when BeyondSimulation)
};

struct DimensionErrorSummary {
  int points = 0;                 // compared points (interpolated)
  int beyond_simulation = 0;      // measured points after the last simulated step (not counted)
  double rms_error_m = 0.0;       // sqrt(mean(error^2)) over the compared points, m (0 when none)
  double max_abs_error_m = 0.0;   // max |error| over the compared points, m
  double mean_error_m = 0.0;      // bias (simulated - measured), m
};

struct DimensionComparison {
  std::vector<DimensionComparisonPoint> points;   // in file order, Sd, Sh, qR within a row
  std::array<DimensionErrorSummary, 3> summary;   // by ReferenceDimension (points = 0 when not measured)
};

DimensionComparison CompareDimensions(const SimulatedDimensionSeries& simulated, const MeasuredDimensions& measured);
// Statistics of the points of one dimension (e.g. pooled over several measured files).
DimensionErrorSummary SummariseDimensionErrors(const std::vector<DimensionComparisonPoint>& points,
                                               ReferenceDimension dimension);

// ---------------------------------------------------------------- profiles
// Linear: blend of the two bracketing profiles (header comment); Nearest: the profile of the nearer step in km.
enum class ProfileInterpolation { Linear, Nearest };
const char* to_string(ProfileInterpolation mode);  // "linear", "nearest"

// Blend of two wheel profiles (see the header comment): t = 0 gives a, t = 1 the closest points of b along a.
// The result keeps a's point order and sample spacing. Throws InputError for t outside [0, 1] or empty profiles.
Profile InterpolateProfile(const Profile& a, const Profile& b, double t);

struct SimulatedProfile {
  StepBracket bracket;            // series indices (0 = initial profile)
  int step_before = 0, step_after = 0;   // wear step numbers of the bracket (0 = initial)
  double km_before = 0.0, km_after = 0.0;  // their distances, km
  ProfileInterpolation mode = ProfileInterpolation::Linear;  // as requested
  Profile profile;                // empty when BeyondSimulation
};
// The simulated wheel profile at km (last rail step, like DimensionSeriesOf).
SimulatedProfile SimulatedProfileAt(const WearSimulationResult& result, double km,
                                    ProfileInterpolation mode = ProfileInterpolation::Linear);

// validate() throws InputError outside the ranges given.
struct ProfileDistanceOptions {
  double spacing_m = 0.1e-3;                 // sampling of the simulated profile, m, > 0
  double worn_zone_min_depth_m = 0.01e-3;    // m, >= 0: worn zone: simulated profile this far inside the initial one
  std::optional<std::array<double, 2>> lateral_range_m;  // m; if set, the zone is y in [range[0], range[1]] instead
  // Measured profiles (MiniProf) are referenced to the flange back and to z = 0 at the taping line, so they carry
  // no absolute radius. true: shift the measured profile in z so that its height at the taping line (y = 0)
  // equals the simulated one (tread wear at the taping line is then not part of the distance). false: as read.
  bool align_taping_line = false;
  void validate() const;
};

// Measured: at least one sample counted; EmptyZone: no sample in the worn zone covered by the measurement (every
// statistic 0).
enum class ProfileDistanceStatus { Measured, EmptyZone };
const char* to_string(ProfileDistanceStatus status);  // "measured", "empty_zone"

// Lengths in m.
struct ProfileDistanceResult {
  ProfileDistanceStatus status = ProfileDistanceStatus::EmptyZone;  // see ProfileDistanceStatus
  int points = 0;                      // samples in the zone and covered by the measurement
  int outside_measurement = 0;         // samples in the zone whose closest measured point is an end of the curve
  double rms_m = 0.0, max_m = 0.0;     // of |distance|
  double mean_signed_m = 0.0;          // > 0: measured outside the simulated surface (simulation wore more)
  double y_at_max_m = 0.0;             // lateral position of the largest |distance|
  double zone_y_min_m = 0.0, zone_y_max_m = 0.0;  // lateral extent of the counted samples
  double alignment_shift_m = 0.0;      // z shift applied to the measured profile (align_taping_line; else 0)
  // the counted samples: lateral position on the simulated profile and signed distance (for plots)
  std::vector<double> sample_y_m, sample_signed_distance_m;
};

// `initial` defines the worn zone (unused when options.lateral_range_m is set). Throws InputError for empty
// profiles, bad options, or align_taping_line when either profile has no point at y = 0.
ProfileDistanceResult MeasureProfileDistance(const Profile& simulated, const Profile& measured, const Profile& initial,
                                             const ProfileDistanceOptions& options = {});

}  // namespace conforma
