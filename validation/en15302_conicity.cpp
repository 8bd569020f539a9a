// EN 15302 benchmark runner (validation_en15302.hpp).
#include "conforma/validation/validation_en15302.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "conforma/conicity.hpp"
#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"

namespace conforma {

namespace {

struct Combination {
  char wheel_left, wheel_right;
  double diameter_left_mm, diameter_right_mm;
  double y_first_mm, y_last_mm;  // grid of dr_ce_E<n>.dat (shared data README.md)
};
// Combinations (shared data README.md; docs/data.md): E1 A/A, E2 B/B, E3 H/H, E4 I/I (920/920); E5..E8 the same
// with 920/918; E9 A/B 920/920.
const Combination kCombinations[9] = {
    {'A', 'A', 920, 920, -6.8, 6.8}, {'B', 'B', 920, 920, -6.8, 6.8}, {'H', 'H', 920, 920, -6.8, 6.8},
    {'I', 'I', 920, 920, -7.1, 7.1}, {'A', 'A', 920, 918, -6.8, 6.8}, {'B', 'B', 920, 918, -6.9, 6.8},
    {'H', 'H', 920, 918, -6.8, 6.7}, {'I', 'I', 920, 918, -7.1, 7.0}, {'A', 'B', 920, 920, -6.8, 6.8}};

std::vector<double> read_numbers(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot be read");
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  if (!in.eof()) throw InputError(path, 0, "non-numeric content");
  return v;
}

}  // namespace

En15302Result RunEn15302Combination(const std::string& shared_data_dir, int id) {
  if (id < 1 || id > 9) throw InputError("RunEn15302Combination: combination must be 1..9, got " + std::to_string(id));
  const Combination& c = kCombinations[id - 1];
  const std::string dir = shared_data_dir + "/profiles/en15302/";
  ProfileReadOptions wheel_options;
  wheel_options.kind = ProfileKind::Wheel;
  wheel_options.mirror_z = true;
  ProfileReadOptions rail_options;
  rail_options.kind = ProfileKind::Rail;
  const Profile rail = LoadProfile(dir + "SUIC519A.dat", rail_options);
  TrackSetup t;
  t.gauge_m = 1.43516;
  t.gauge_height_m = 0.014;
  t.flange_back_distance_m = 1.360;
  t.flange_back_position_m = -0.070;
  t.nominal_radius_m = {c.diameter_left_mm * 0.5e-3, c.diameter_right_mm * 0.5e-3};
  t.rail_inclination_rad = 0.0;
  t.wheel = {LoadProfile(dir + "RUIC519" + c.wheel_left + ".dat", wheel_options),
             LoadProfile(dir + "RUIC519" + c.wheel_right + ".dat", wheel_options)};
  t.rail = {rail, rail};
  const WheelsetTrackGeometry g(t);

  En15302Result r;
  r.combination = id;
  const std::string dr_path = dir + "dr_ce_E" + std::to_string(id) + ".dat";
  r.reference_delta_r_mm = read_numbers(dr_path);
  const int n = static_cast<int>(std::lround((c.y_last_mm - c.y_first_mm) / 0.1)) + 1;
  if (static_cast<int>(r.reference_delta_r_mm.size()) != n)
    throw InputError(dr_path, 0, "expected " + std::to_string(n) + " values");
  // Delta r on the reference grid plus 3 mm on each side for the large amplitudes
  const int margin = 30;
  std::vector<double> ys;
  for (int k = -margin; k < n + margin; ++k) ys.push_back((c.y_first_mm + 0.1 * k) * 1e-3);
  EquilibriumOptions no_roll;
  no_roll.include_roll = false;
  const RollingRadiusDifferenceCurve curve = ComputeRollingRadiusDifference(g, ys, 0.0, no_roll);
  for (int k = 0; k < n; ++k) {
    const int i = k + margin;
    r.y_mm.push_back(ys[i] * 1e3);
    r.delta_r_mm.push_back(curve.status[i] == EquilibriumStatus::Converged ? curve.delta_r_m[i] * 1e3 : std::nan(""));
    const double err = std::abs(r.delta_r_mm.back() - r.reference_delta_r_mm[k]);
    if (!(err <= 0.05)) ++r.points_over_tolerance;
    if (!(err <= r.max_delta_r_error_mm)) r.max_delta_r_error_mm = std::isfinite(err) ? err : INFINITY;
  }
  std::vector<double> yv, dv;
  for (size_t i = 0; i < ys.size(); ++i)
    if (curve.status[i] == EquilibriumStatus::Converged) {
      yv.push_back(ys[i]);
      dv.push_back(curve.delta_r_m[i]);
    }
  const std::string ben_path = dir + "ben_E" + std::to_string(id) + ".dat";
  std::ifstream in(ben_path);
  if (!in) throw InputError(ben_path, 0, "cannot be read");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    En15302Amplitude a;
    double up2, lo2;
    if (!(ls >> a.amplitude_mm >> a.reference >> a.upper >> a.lower >> up2 >> lo2)) continue;
    const ConicityResult cr = EquivalentConicity(yv, dv, a.amplitude_mm * 1e-3);
    a.conicity = cr.equivalent_conicity;
    a.ok = cr.status == ConicityStatus::Ok && a.conicity >= a.lower && a.conicity <= a.upper;
    r.outside_band += !a.ok;
    r.amplitudes.push_back(a);
  }
  return r;
}

}  // namespace conforma
