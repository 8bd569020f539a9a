// Manchester contact benchmark, left wheel (shared data reference/contact_mbench_a22_left.csv, CONTACT
// results): S1002 on UIC60 1:40 (already canted in the file), gauge 1435 at 14 mm, flange back 1360,
// r0 = 460 mm, 10 kN, yaw = 2.4 y mrad. Checks the frames (rigid equilibrium roll), the contact reference
// point (centre of the interpenetration region) and contact angle of the elastic candidates, and reports the
// creepages.
//
// Frame mapping found from the data (CONTACT reports the left wheel in its own track frame x forward,
// y to the RIGHT, z down): y_ours = -y_ws, yaw_ours = -yaw, roll_ours = roll_ws (both raise the left wheel
// for > 0), rail-profile y_ours = -y_cp_rail (CONTACT's left-rail y points to the gauge side), contact angle
// delta_ours = delta_cp (+ towards the gauge side), creepages identical (creepage.hpp convention).
// test-links: geometry  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "conforma/contact_candidates.hpp"
#include "conforma/creepage.hpp"
#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"

using namespace conforma;

namespace {

struct Case {
  double y_ws_mm, yaw_mrad, roll_rad, y_cp_rail_mm, delta_cp_rad, xi, eta, phi_per_mm;
};

std::vector<Case> read_cases() {
  std::ifstream in(std::string(CONFORMA_SHARED_DATA) + "/reference/contact_mbench_a22_left.csv");
  EXPECT_TRUE(in.good());
  std::string line;
  std::getline(in, line);
  std::vector<Case> cases;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string tok;
    std::vector<std::string> v;
    while (std::getline(ss, tok, ',')) v.push_back(tok);
    if (v.size() < 15) continue;
    cases.push_back({std::stod(v[1]), std::stod(v[2]), std::stod(v[3]), std::stod(v[5]), std::stod(v[7]),
                     std::stod(v[12]), std::stod(v[13]), std::stod(v[14])});
  }
  return cases;
}

WheelsetTrackGeometry make_geometry() {
  const std::string dir = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/examples/";
  TrackSetup t = MakeSymmetricTrack(LoadProfile(dir + "MBench_S1002_v3.prw"), LoadProfile(dir + "MBench_UIC60_v3.prr"),
                                    0.0);  // the .prr rail is already canted 1:40
  t.gauge_m = 1.435;
  t.gauge_height_m = 0.014;
  t.flange_back_distance_m = 1.360;
  t.flange_back_position_m = -0.070;
  t.nominal_radius_m = {0.46, 0.46};
  return WheelsetTrackGeometry(t);
}

WheelsetPose pose_of(const Case& c) {
  WheelsetPose p;
  p.lateral_m = -c.y_ws_mm * 1e-3;
  p.yaw_rad = -c.yaw_mrad * 1e-3;
  p.roll_rad = c.roll_rad;
  return p;
}

}  // namespace

TEST(ManchesterA22, RigidEquilibriumRollMatchesReference) {
  const auto cases = read_cases();
  ASSERT_EQ(cases.size(), 21u);
  const WheelsetTrackGeometry g = make_geometry();
  WheelsetPose guess;
  for (const Case& c : cases) {
    const WheelsetPose p = pose_of(c);
    const EquilibriumResult e = g.SolveRigidEquilibrium(p.lateral_m, p.yaw_rad, guess);
    ASSERT_EQ(e.status, EquilibriumStatus::Converged) << "y_ws " << c.y_ws_mm;
    guess = e.pose;
    std::printf("y_ws %4.1f mm: roll %9.5f mrad (reference %9.5f)\n", c.y_ws_mm, e.pose.roll_rad * 1e3, c.roll_rad * 1e3);
    // sign and size of the roll: both wheels touching, the wheel on the larger radius is lifted
    EXPECT_NEAR(e.pose.roll_rad, c.roll_rad, 0.05 * std::abs(c.roll_rad) + 2e-5) << "y_ws " << c.y_ws_mm;
  }
}

TEST(ManchesterA22, ContactReferencePointAngleAndCreepages) {
  const auto cases = read_cases();
  const WheelsetTrackGeometry g = make_geometry();
  const Material steel;  // G = 82 GPa, nu = 0.28
  CandidateOptions bare;          // interpenetration region at the full Hertz approach
  CandidateOptions kp = bare;     // Kik-Piotrowski virtual penetration (docs/physics-reference.md §3.1)
  kp.penetration_factor = 0.55;
  double worst_y = 0, worst_y_bare = 0, worst_delta = 0;
  for (const Case& c : cases) {
    const WheelsetPose p = pose_of(c);
    const CandidateResult r = FindContactCandidatesForLoad(g, Side::Left, p, 10e3, steel, kp);
    const CandidateResult rb = FindContactCandidatesForLoad(g, Side::Left, p, 10e3, steel, bare);
    ASSERT_EQ(r.status, CandidateStatus::Ok);
    // tread contact: the main region (deepest interpenetration); at y = 0 the very flat gap has a second
    // shallow minimum 11 mm further out that forms its own small region
    auto main_patch = [](const CandidateResult& res) {
      return *std::max_element(res.candidates.begin(), res.candidates.end(), [](const auto& a, const auto& b) {
        return a.patch.rigid_approach_m < b.patch.rigid_approach_m;
      });
    };
    const ContactCandidate k = main_patch(r);
    const double y_cp = -k.patch.reference_point_m.x() * 1e3;
    const double y_cp_bare = -main_patch(rb).patch.reference_point_m.x() * 1e3;
    const double delta = k.patch.contact_angle_rad;
    WheelsetVelocity v;
    v.forward_speed_m_s = 2.0;
    v.axle_angular_velocity_rad_s = 2.0 / 0.46;  // pure rolling at the nominal radius
    const Creepages cr = ComputeCreepages(g, Side::Left, r.pose, v, k.reference.wheel_point_m, delta);
    std::printf("y_ws %4.1f: y_cp %7.3f (bare %7.3f, ref %7.3f) delta %7.4f (ref %7.4f) | xi %10.3e (ref %10.3e) "
                "eta %10.3e (ref %10.3e) phi %10.3e/mm (ref %10.3e) lead %6.2f mm\n",
                c.y_ws_mm, y_cp, y_cp_bare, c.y_cp_rail_mm, delta, c.delta_cp_rad, cr.longitudinal, c.xi, cr.lateral,
                c.eta, cr.spin_per_m * 1e-3, c.phi_per_mm, k.reference.lead_m * 1e3);
    worst_y = std::max(worst_y, std::abs(y_cp - c.y_cp_rail_mm));
    worst_y_bare = std::max(worst_y_bare, std::abs(y_cp_bare - c.y_cp_rail_mm));
    worst_delta = std::max(worst_delta, std::abs(delta - c.delta_cp_rad));
    EXPECT_NEAR(y_cp, c.y_cp_rail_mm, 1.0) << "y_ws " << c.y_ws_mm;
    EXPECT_NEAR(delta, c.delta_cp_rad, 0.01) << "y_ws " << c.y_ws_mm;
    // creepages: lateral from yaw and spin from the contact angle are set by the geometry alone
    EXPECT_NEAR(cr.lateral, c.eta, 0.02 * std::abs(c.eta) + 1e-5) << "y_ws " << c.y_ws_mm;
    EXPECT_NEAR(cr.spin_per_m * 1e-3, c.phi_per_mm, 0.1 * std::abs(c.phi_per_mm) + 2e-6) << "y_ws " << c.y_ws_mm;
  }
  std::printf("max |y_cp - ref| = %.3f mm (virtual penetration 0.55), %.3f mm (full Hertz approach); "
              "max |delta - ref| = %.4f rad\n", worst_y, worst_y_bare, worst_delta);
}
