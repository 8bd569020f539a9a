#pragma once
// A wheel or rail cross-section profile: a smooth planar curve parametrised by arc length s.
//
// Profile coordinates (metres inside the program; files are in mm and converted at the boundary):
//   y  lateral, positive towards the FIELD side (away from the track centre), for both wheel and rail
//      ("right-side profile" as in CONTACT; a left-side wheel or rail uses the same profile mirrored by
//      the track, never by the profile).
//   z  rail:  vertical, positive UP, origin at the top of the rail head in its own (uninclined) frame.
//      wheel: radial height above the taping line, positive towards a LARGER radius (flange tip z > 0);
//             the rolling radius at y is r(y) = r_nominal + z(y). Taping line at y = 0, flange back at
//             y = -0.070 m for S1002-type wheels (flange at negative y).
// Orientation: s increases from the gauge/flange side (small y) towards the field side (large y).
// normal(s) is the unit normal to the LEFT of the tangent, which points OUT of the body for both wheel
// (towards larger radius) and rail (upwards on the crown).
// curvature(s) is signed, positive where the surface is convex (rail crown, wheel flange tip) and negative
// where it is concave (worn wheel tread hollow, S1002 flange root).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace conforma {

// A wheel or rail cross-section is a few hundred mm at most: a profile point farther than this from the origin is a
// length-unit or data error (Profile::FromPoints, and the file readers' checks before any other).
constexpr double kMaxProfileCoordinate_m = 10.0;

// Wheel: z is the radial height above the taping line; Rail: z is up from the rail top (coordinates above).
enum class ProfileKind { Wheel, Rail };
const char* to_string(ProfileKind kind);  // "wheel", "rail"

struct ProfileFitOptions {
  // Smoothing of the fit through the input points, as the RMS residual allowed per point [m].
  // 0 interpolates the points exactly (after removing duplicates). > 0: parametric cubic smoothing spline
  // (Reinsch; penalised least squares solved with CHOLMOD) whose RMS distance to the points equals this value;
  // set it to the measurement noise level.
  double smoothing_rms_m = 0.0;  // m, default 0
  // Spacing of the arc-length resampling that the profile stores [m]; default 0.1 mm.
  double sample_spacing_m = 0.1e-3;
  // If true, FromPoints sorts the input by y (so unsorted clouds are accepted); the file readers sort an unordered
  // cloud but keep a curve that folds back (measured flange tips, undercut gauge faces) in its order, parametrised
  // by arc length. If false, input order defines the curve.
  bool function_of_y = true;
};

class Profile {
 public:
  Profile() = default;
  // Builds the profile from points (y, z) in metres. `source` names the origin (file name) for messages.
  // Throws InputError when the points are too few, not finite, or the curve self-intersects.
  static Profile FromPoints(std::vector<Eigen::Vector2d> points_m, ProfileKind kind,
                            const ProfileFitOptions& options = {}, const std::string& source = "points");
  // Builds the profile from samples taken as they are, as the nodes s_i = i h of the stored splines (no refit, no
  // resampling; h = polyline length / (n - 1)). Only for samples that are uniform in arc length up to rounding, e.g.
  // a profile's own samples() moved by far less than its spacing; a refit would not keep a property of the samples
  // (such as y never decreasing) between its new nodes. Throws InputError for fewer than 4 or non-finite samples.
  static Profile FromArcLengthSamples(const std::vector<Eigen::Vector2d>& samples, ProfileKind kind,
                                      const std::string& source = "samples");

  // The profile with the samples first, first + 1, ... replaced by `moved`, on the same arc-length grid (spacing and
  // length kept): for samples moved by far less than the spacing, e.g. wear removed along the normal (paper 000 eqs.
  // 19-21) in real time, where FromArcLengthSamples would re-solve the whole profile. The splines' second derivatives
  // are re-solved over the moved samples and kMovedSplineMargin samples on either side with the ones beyond kept
  // (a natural cubic spline's response to a local change decays by 2 - sqrt(3) = 0.268 per sample: 40 samples bring
  // it below 1e-22 of the change, under the rounding of the kept values). InputError for samples outside the profile
  // or not finite.
  Profile WithMovedSamples(size_t first, const std::vector<Eigen::Vector2d>& moved) const;
  static constexpr int kMovedSplineMargin = 40;
  size_t sample_count() const { return y_.size(); }
  Eigen::Vector2d sample_at(size_t i) const { return {y_[i], z_[i]}; }  // stored sample i (i < sample_count())

  // The same curve translated by (dy, dz): samples shifted, spline second derivatives, grid and parametrisation kept
  // (exact: no refit).
  Profile Translated(double dy, double dz, const std::string& source) const;

  ProfileKind kind() const { return kind_; }
  const std::string& source() const { return source_; }
  bool empty() const { return y_.empty(); }
  double length() const { return length_; }  // total arc length [m]
  double spacing() const { return h_; }      // arc-length step of the stored samples [m]

  Eigen::Vector2d position(double s) const;  // (y, z) [m]; s is clamped to [0, length]
  Eigen::Vector2d tangent(double s) const;   // unit, towards increasing s
  Eigen::Vector2d normal(double s) const;    // unit, outward (left of the tangent)
  double curvature(double s) const;          // signed [1/m], convex > 0
  // Angle of the outward normal from +z, positive when the normal leans towards -y [rad] (i.e. the
  // surface slope angle: atan(dz/dy) for a function-like profile).
  double slope_angle(double s) const;

  double y_min() const { return y_min_; }
  double y_max() const { return y_max_; }
  // Height z at lateral position y on the function-like part of the curve (the first crossing in s order
  // whose tangent is not vertical); empty outside the profile's y range.
  std::optional<double> height_at(double y) const;
  // Arc length of the first crossing of the vertical line at y (see height_at).
  std::optional<double> s_at(double y) const;
  // Nearest point on the curve to q: returns its arc length.
  double closest_s(const Eigen::Vector2d& q) const;

  // The stored samples (uniform in s), and resampling at another spacing.
  std::vector<Eigen::Vector2d> samples() const;
  std::vector<Eigen::Vector2d> sample(double spacing_m) const;

 private:
  ProfileKind kind_ = ProfileKind::Rail;
  std::string source_;
  double h_ = 0.0, length_ = 0.0, y_min_ = 0.0, y_max_ = 0.0;
  // Natural cubic splines y(s), z(s) on the uniform grid s_i = i h: values and second derivatives.
  std::vector<double> y_, z_, y2_, z2_;
  // Maximal runs of consecutive segments [y_i, y_i+1] along which y strictly increases (direction +1) or decreases
  // (-1), in order of s: s_at finds the first segment that contains y by a binary search per run instead of a scan
  // over all samples (the same segment the scan finds).
  struct MonotonicRun {
    int first_segment, last_segment, direction;
  };
  std::vector<MonotonicRun> y_runs_;
  void locate(double s, int& i, double& t) const;
  void set_y_range();  // y_min_, y_max_, y_runs_ from y_
};

// First pair (i, j), j >= i + 2, of polyline segments [p_i, p_i+1] and [p_j, p_j+1] that properly cross.
std::optional<std::pair<size_t, size_t>> find_self_intersection(const std::vector<Eigen::Vector2d>& polyline);

}  // namespace conforma
