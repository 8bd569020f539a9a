// The fixed case set of `conforma bench` (benchmark_cases.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/contact_candidates.hpp"
#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/validation/validation_manchester.hpp"
// The analytic groove patch shared with the KP and BEM groove tests (one construction, not a copy).
#include "conforma/validation/analytic_patches.hpp"
#include "conforma/validation/worn_heavy_haul_track.hpp"

namespace conforma {

namespace {

// Creepages of the non-Manchester cases: moderate, partly sliding, with spin.
constexpr FastsimCreepages kDefaultCreepages{1.0e-3, 0.5e-3, 0.2};

}  // namespace

std::vector<BenchCase> MakeGrooveBenchCases(const std::vector<double>& groove_radii_m, double normal_load_N) {
  // CONTACT groove case (docs/data.md): wheel circle R = 10 mm, rolling radius 420 mm, G = 80 GPa, nu = 0.28.
  std::vector<BenchCase> cases;
  for (double groove_radius : groove_radii_m) {
    const double wheel_radius = 10.0e-3, rolling_radius = 0.420;
    if (!(groove_radius > wheel_radius)) throw InputError("groove radius must exceed the wheel radius of 10 mm");
    BenchCase c;
    char name[64];
    std::snprintf(name, sizeof name, "groove_%.2f", groove_radius * 1e3);
    c.name = name;
    c.family = "groove";
    c.patch = kp_test::GroovePatch(wheel_radius, groove_radius, rolling_radius, 12.0e-3, 241);
    c.normal_load_N = normal_load_N;
    c.creepages = kDefaultCreepages;
    // Hertz at the groove bottom: A = 1 / (2 r0), B = (1/R_w - 1/R_g) / 2 (concave groove)
    c.hertz_A_per_m = 0.5 / rolling_radius;
    c.hertz_B_per_m = 0.5 * (1.0 / wheel_radius - 1.0 / groove_radius);
    c.material.shear_modulus_Pa = 80e9;
    c.material.poisson_ratio = 0.28;
    cases.push_back(c);
  }
  return cases;
}

std::vector<BenchCase> BenchCasesFromPose(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                          double vertical_load_N, const Material& material,
                                          const FastsimCreepages& creepages, const std::string& name,
                                          const std::string& family) {
  const CandidateResult found = FindContactCandidatesForLoad(geometry, side, pose, vertical_load_N, material);
  std::vector<BenchCase> cases;
  if (found.status != CandidateStatus::Ok) return cases;
  const WheelContactResult rigid = geometry.RigidContact(side, found.pose);
  for (size_t k = 0; k < found.candidates.size(); ++k) {
    const ContactCandidate& cand = found.candidates[k];
    if (!(cand.normal_force_estimate_N > 0.0)) continue;
    BenchCase c;
    c.name = name + "_p" + std::to_string(k);
    c.family = family;
    c.patch = cand.patch;
    c.normal_load_N = cand.normal_force_estimate_N;
    c.creepages = creepages;
    c.material = material;
    // Hertz: the rigid contact point with the smallest gap inside the region (as the pipeline's hertz model)
    RigidContactPoint point = cand.reference;
    double best = 1e300;
    for (const RigidContactPoint& p : rigid.points)
      if (p.rail_s_m >= cand.region_start_s_m && p.rail_s_m <= cand.region_end_s_m && p.gap_m < best)
        best = p.gap_m, point = p;
    c.hertz_A_per_m = point.hertz_A_per_m;
    c.hertz_B_per_m = point.hertz_B_per_m;
    cases.push_back(c);
  }
  return cases;
}

std::vector<BenchCase> FlangeBenchCases(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                        double vertical_load_N, const Material& material, const std::string& name,
                                        const std::string& family) {
  std::vector<BenchCase> cases = BenchCasesFromPose(geometry, side, pose, vertical_load_N, material, kDefaultCreepages,
                                                    name, family);
  // the spin of a wheel rolling on a contact turned by delta from the vertical: phi = -sin(delta) / r
  // (docs/physics-reference.md §2.6; the sign of the reference file's left-wheel tread creepages)
  for (BenchCase& c : cases) {
    const std::vector<double>& s = c.patch.s_m;  // the wheel radius at the strip of the reference point (s = 0)
    const size_t k = static_cast<size_t>(
        std::min_element(s.begin(), s.end(), [](double a, double b) { return std::fabs(a) < std::fabs(b); }) - s.begin());
    const double r = c.patch.wheel_radius_m[k];
    if (r > 0.0) c.creepages.phi_per_m = -std::sin(c.patch.contact_angle_rad) / r;
  }
  return cases;
}

std::vector<BenchCase> MakeBenchCases(const std::string& shared_data_dir) {
  std::vector<BenchCase> cases;
  ProfileReadOptions wheel_read, rail_read;
  wheel_read.kind = ProfileKind::Wheel;
  rail_read.kind = ProfileKind::Rail;
  Material steel;  // G = 82 GPa, nu = 0.28

  // 1. Manchester sweep, left wheel (validation_manchester.hpp for the frame mapping)
  {
    const std::string examples = shared_data_dir + "/profiles/contact/examples/";
    const WheelsetTrackGeometry geometry(MakeSymmetricTrack(LoadProfile(examples + "MBench_S1002_v3.prw", wheel_read),
                                                            LoadProfile(examples + "MBench_UIC60_v3.prr", rail_read), 0.0));
    for (const ManchesterReferenceCase& m :
         ReadManchesterReference(shared_data_dir + "/reference/contact_mbench_a22_left.csv")) {
      WheelsetPose pose;
      pose.lateral_m = -m.y_ws_mm * 1e-3;
      pose.yaw_rad = -m.yaw_mrad * 1e-3;
      pose.roll_rad = m.roll_rad;
      char name[32];
      std::snprintf(name, sizeof name, "mbench_%02d", m.id);
      const auto found = BenchCasesFromPose(geometry, Side::Left, pose, 10e3, steel,
                                            {m.xi, m.eta, m.phi_per_mm * 1e3}, name, "mbench");
      cases.insert(cases.end(), found.begin(), found.end());
    }
  }
  // 2. CONTACT grooves
  {
    const auto grooves = MakeGrooveBenchCases({10.25e-3, 10.10e-3, 10.05e-3, 10.02e-3});
    cases.insert(cases.end(), grooves.begin(), grooves.end());
  }
  // 3. Worn pair (conformal heavy-haul wheel and rail), 10 kN
  {
    const std::string bank = shared_data_dir + "/profiles/contact/testbank/profiles/";
    const WheelsetTrackGeometry geometry(MakeSymmetricTrack(LoadProfile(bank + "worn_high_mileage.prw", wheel_read),
                                                            LoadProfile(bank + "site_b_hr.prr", rail_read), 0.0));
    for (double y_mm : {0.0, 3.0, 6.0}) {
      WheelsetPose pose;
      pose.lateral_m = y_mm * 1e-3;
      char name[32];
      std::snprintf(name, sizeof name, "worn_y%.0f", y_mm);
      const auto found = BenchCasesFromPose(geometry, Side::Left, pose, 10e3, steel, kDefaultCreepages, name, "worn");
      cases.insert(cases.end(), found.begin(), found.end());
    }
  }
  // 4. Flange root: S1002 / 60E1 at 1:40, yaw 20 mrad; the smallest lateral shift (0.1 mm steps) at which the
  //    10 kN push-down gives two separate regions (tread / flange root and flange)
  {
    const WheelsetTrackGeometry geometry(
        MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0), rail_inclination_1in40()));
    for (int k = 40; k <= 120; ++k) {
      WheelsetPose pose;
      pose.lateral_m = k * 0.1e-3;
      pose.yaw_rad = 0.02;
      const auto found = BenchCasesFromPose(geometry, Side::Left, pose, 10e3, steel, kDefaultCreepages,
                                            "flange_root", "flange_root");
      if (found.size() >= 2 &&
          std::fabs(found.front().patch.contact_angle_rad - found.back().patch.contact_angle_rad) > 0.3) {
        cases.insert(cases.end(), found.begin(), found.end());
        break;
      }
    }
  }
  // 5. Flange (issue 15): S1002 on the Manchester UIC60 1:40 rail (the profiles), the RIGHT wheel of the
  //    wheelset pose (y_ws = 5 ... 10 mm, yaw 2.4 y_ws mrad, roll of the CONTACT reference file) pushed into
  //    flange-root and flange-flank contact, 10 kN; every region (merged within the combine distance)
  {
    const std::string examples = shared_data_dir + "/profiles/contact/examples/";
    const WheelsetTrackGeometry geometry(MakeSymmetricTrack(LoadProfile(examples + "MBench_S1002_v3.prw", wheel_read),
                                                            LoadProfile(examples + "MBench_UIC60_v3.prr", rail_read), 0.0));
    for (const ManchesterReferenceCase& m :
         ReadManchesterReference(shared_data_dir + "/reference/contact_mbench_a22_left.csv")) {
      if (m.y_ws_mm < 4.99 || std::fmod(m.y_ws_mm + 1e-9, 1.0) > 1e-6) continue;  // y_ws = 5, 6, ..., 10 mm
      WheelsetPose pose;  // the mapping (validation_manchester.hpp): the same wheelset, its right wheel
      pose.lateral_m = -m.y_ws_mm * 1e-3;
      pose.yaw_rad = -m.yaw_mrad * 1e-3;
      pose.roll_rad = m.roll_rad;
      char name[32];
      std::snprintf(name, sizeof name, "flange_y%02.0f", m.y_ws_mm);
      const auto found = FlangeBenchCases(geometry, Side::Right, pose, 10e3, steel, name, "flange");
      cases.insert(cases.end(), found.begin(), found.end());
    }
  }
  // 6. Gauge corner (issue 15): the worn pair worn_high_mileage.prw on site_b_hr.prr with the issue's track (gauge
  //    1435.10 mm measured 15.875 mm below the top, flange back 1347.40 mm at profile y = 0, r0 = 444 mm, no
  //    inclination), right wheel, wheelset shifted y = 15.0, 15.4, 15.5 mm towards the right rail (tread alone, tread and
  //    gauge corner; the 137 kN tread patch costs the exact reference about 3.5 s), yaw 2 mrad, roll of the
  //    rigid equilibrium, 137 kN; and the issue's own pose, 15.5 mm at roll 0
  {
    const TrackSetup setup = WornHeavyHaulTrack(shared_data_dir);
    const WheelsetTrackGeometry geometry(setup);
    for (double y_mm : {15.0, 15.4, 15.5}) {
      const EquilibriumResult eq = geometry.SolveRigidEquilibrium(-y_mm * 1e-3, 2e-3);
      if (eq.status == EquilibriumStatus::NoContact) continue;
      char name[32];
      std::snprintf(name, sizeof name, "gauge_corner_y%.1f", y_mm);
      const auto found = FlangeBenchCases(geometry, Side::Right, eq.pose, 137e3, steel, name, "gauge_corner");
      cases.insert(cases.end(), found.begin(), found.end());
    }
    // the issue's pose: roll 0 at 15.5 mm, where the worn flange face touches too (three patches: flange face at
    // 74 deg, gauge corner at 35 deg, tread)
    WheelsetPose issue_pose;
    issue_pose.lateral_m = -15.5e-3;
    issue_pose.yaw_rad = 2e-3;
    const auto found = FlangeBenchCases(geometry, Side::Right, issue_pose, 137e3, steel, "gauge_corner_y15.5_roll0",
                                        "gauge_corner");
    cases.insert(cases.end(), found.begin(), found.end());
  }
  return cases;
}

}  // namespace conforma
