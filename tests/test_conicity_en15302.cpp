// EN 15302 equivalent-conicity benchmark (shared data profiles/en15302): Delta r(y) of the nine wheel/rail
// combinations E1..E9 against the reference functions dr_ce_E<n>.dat, and the equivalent conicity against
// the reference tolerance band ben_E<n>.dat at every listed amplitude.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "conforma/conicity.hpp"
#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"

using namespace conforma;

namespace {

const std::string kDir = std::string(CONFORMA_SHARED_DATA) + "/profiles/en15302/";

struct Combination {
  int id;
  char wheel_left, wheel_right;   // RUIC519<x>
  double diameter_left_mm, diameter_right_mm;
  double y_first_mm, y_last_mm;   // grid of dr_ce_E<n>.dat (data README)
};
// data README: E1 A/A, E2 B/B, E3 H/H, E4 I/I (920/920); E5..E8 the same with 920/918; E9 A/B 920/920.
const Combination kCombinations[] = {
    {1, 'A', 'A', 920, 920, -6.8, 6.8}, {2, 'B', 'B', 920, 920, -6.8, 6.8}, {3, 'H', 'H', 920, 920, -6.8, 6.8},
    {4, 'I', 'I', 920, 920, -7.1, 7.1}, {5, 'A', 'A', 920, 918, -6.8, 6.8}, {6, 'B', 'B', 920, 918, -6.9, 6.8},
    {7, 'H', 'H', 920, 918, -6.8, 6.7}, {8, 'I', 'I', 920, 918, -7.1, 7.0}, {9, 'A', 'B', 920, 920, -6.8, 6.8}};

std::vector<double> read_numbers(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  return v;
}

// The .dat wheels have z = height in the track (smaller radius up): z_ours = -z_file. Rails are z up.
Profile wheel_profile(char w) {
  ProfileReadOptions o;
  o.kind = ProfileKind::Wheel;
  o.mirror_z = true;
  return LoadProfile(kDir + "RUIC519" + w + ".dat", o);
}
Profile rail_profile() {
  ProfileReadOptions o;
  o.kind = ProfileKind::Rail;
  return LoadProfile(kDir + "SUIC519A.dat", o);
}

WheelsetTrackGeometry make_geometry(const Combination& c) {
  const Profile rail = rail_profile();
  TrackSetup t;
  t.gauge_m = 1.43516;  // data README: gauge 1435.16 mm
  t.gauge_height_m = 0.014;
  t.flange_back_distance_m = 1.360;
  t.flange_back_position_m = -0.070;
  t.nominal_radius_m = {c.diameter_left_mm * 0.5e-3, c.diameter_right_mm * 0.5e-3};
  t.rail_inclination_rad = 0.0;  // SUIC519A.dat is already inclined 1:40
  t.wheel = {wheel_profile(c.wheel_left), wheel_profile(c.wheel_right)};
  t.rail = {rail, rail};
  return WheelsetTrackGeometry(t);
}

}  // namespace

class En15302 : public ::testing::TestWithParam<Combination> {};

TEST_P(En15302, RollingRadiusDifferenceAndConicity) {
  const Combination& c = GetParam();
  const WheelsetTrackGeometry g = make_geometry(c);
  const std::vector<double> ref = read_numbers(kDir + "dr_ce_E" + std::to_string(c.id) + ".dat");
  const int n = static_cast<int>(std::lround((c.y_last_mm - c.y_first_mm) / 0.1)) + 1;
  ASSERT_EQ(static_cast<int>(ref.size()), n);
  // Delta r on the reference grid, plus a margin for the large amplitudes
  std::vector<double> ys;
  for (int k = -30; k < n + 30; ++k) ys.push_back((c.y_first_mm + 0.1 * k) * 1e-3);
  EquilibriumOptions no_roll;
  no_roll.include_roll = false;
  const RollingRadiusDifferenceCurve curve = ComputeRollingRadiusDifference(g, ys, 0.0, no_roll);
  double max_err = 0.0, y_at = 0.0;
  int bad = 0;
  for (int k = 0; k < n; ++k) {
    const int i = k + 30;
    ASSERT_EQ(curve.status[i], EquilibriumStatus::Converged) << "y = " << ys[i] * 1e3 << " mm";
    const double err = std::abs(curve.delta_r_m[i] * 1e3 - ref[k]);
    if (err > max_err) { max_err = err; y_at = ys[i] * 1e3; }
    if (err > 0.05) {
      ++bad;
      std::printf("E%d y=%6.2f mm: Delta r %9.4f mm, reference %9.4f mm\n", c.id, ys[i] * 1e3, curve.delta_r_m[i] * 1e3, ref[k]);
    }
  }
  std::printf("E%d: max |Delta r - reference| = %.4f mm at y = %.1f mm (%d of %d points > 0.05 mm)\n", c.id, max_err, y_at, bad, n);
  EXPECT_LE(max_err, 0.05);
  // equivalent conicity from our Delta r (only converged points)
  std::vector<double> yv, dv;
  for (size_t i = 0; i < ys.size(); ++i)
    if (curve.status[i] == EquilibriumStatus::Converged) { yv.push_back(ys[i]); dv.push_back(curve.delta_r_m[i]); }
  std::ifstream in(kDir + "ben_E" + std::to_string(c.id) + ".dat");
  std::string line;
  int rows = 0, outside = 0;
  double worst = 0.0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    double amp, tg, up, lo, up2, lo2;
    if (!(ls >> amp >> tg >> up >> lo >> up2 >> lo2)) continue;
    ++rows;
    const ConicityResult r = EquivalentConicity(yv, dv, amp * 1e-3);
    ASSERT_EQ(r.status, ConicityStatus::Ok) << "amplitude " << amp;
    worst = std::max(worst, std::abs(r.equivalent_conicity - tg));
    if (r.equivalent_conicity > up || r.equivalent_conicity < lo) {
      ++outside;
      std::printf("E%d amplitude %.1f mm: tan(gamma_e) %.4f outside [%.3f, %.3f] (reference %.3f)\n", c.id, amp,
                  r.equivalent_conicity, lo, up, tg);
    }
  }
  std::printf("E%d: %d amplitudes, %d outside the band, max |tan(gamma_e) - reference| = %.4f\n", c.id, rows, outside, worst);
  EXPECT_GE(rows, 65);
  EXPECT_EQ(outside, 0);
}

std::string CombinationName(const ::testing::TestParamInfo<Combination>& param_info) {
  return "E" + std::to_string(param_info.param.id);
}
INSTANTIATE_TEST_SUITE_P(Combinations, En15302, ::testing::ValuesIn(kCombinations), CombinationName);
