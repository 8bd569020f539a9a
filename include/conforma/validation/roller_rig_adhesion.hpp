#pragma once
// Adhesion tests of the 1:5 scaled roller rig of paper 000 (§4, §5.1, Table 6; docs/physics-reference.md §7.5): the
// wheel-on-roller contact at the centred position, Kalker's linear theory (paper 000 eq. 22, F_x = G a b C11 xi) for
// the initial slope of each test, and the FASTSIM creep curve with slope reduction and a slip-velocity-dependent
// friction law (roller_rig_adhesion_fit.hpp identifies the law).
//
// Geometry (paper 000 §2.1, §4, Table 1): wheel S1002, roller UIC60 canted 1:20, both scaled 1:5; nominal radii
// r_w = 0.0944 m, R_r = 0.185 m. Along x both bodies are curved: A = 1/(2 r_w) + 1/(2 R_r). Across, B = (kappa_wheel +
// kappa_rail)/2 at the contact point of the full-scale wheelset centred on S1002 / 60E1 1:20 (rigid equilibrium,
// y = 0), divided by the length factor (curvatures scale as 1/phi). The paper's roller profile is "modified with
// respect to the standard UIC60 in order to compensate the curvature of the roller and to obtain the same a/b ratio
// as a wheelset on straight track" (§2.1, its ref. [17]); that modification is not printed, so two choices:
//   ScaledUic60:     B of the scaled profiles as they are (the modification left out);
//   TrackEllipseRatio: B such that A/B (hence a/b) equals the full-scale wheel-on-rail value at y = 0 (the design aim
//                    of the modification).
#include <string>
#include <vector>

#include "conforma/friction_law.hpp"
#include "conforma/hertz.hpp"
#include "conforma/material.hpp"

namespace conforma {

// One row of paper 000 Table 6 (validation/data/roller_rig_000_table6.csv).
struct RollerRigAdhesionTest {
  int test = 0;                        // test number 1..8
  double reference_speed_rpm = 0.0;    // roller 2 speed, rpm, > 0
  double wheel_load_kg = 0.0;          // vertical load on each wheel, kg, > 0
  double max_adhesion = 0.0;           // maximum adhesion coefficient F_x / N of the measured curve
  double steady_adhesion = 0.0;        // steady coefficient after the peak
  double initial_slope_N = 0.0;        // the printed "initial slope (N)"
  std::string condition;               // "dry" or "wet"
};
// Reads the CSV (header test,reference_speed_rpm,wheel_load_kg,max_adhesion,steady_adhesion,initial_slope_N,
// condition; '#' comment lines). InputError naming file and line for a malformed row or a value out of range.
std::vector<RollerRigAdhesionTest> ReadRollerRigAdhesionTable(const std::string& path);

// ScaledUic60, TrackEllipseRatio: the two choices of B described at the top of this file.
enum class RollerProfileChoice { ScaledUic60, TrackEllipseRatio };
const char* to_string(RollerProfileChoice choice);  // "scaled_uic60", "track_ellipse_ratio"

// validate(): InputError for a value out of the ranges given.
struct RollerRigAdhesionOptions {
  double wheel_radius_m = 0.0944;   // r_w (Table 1), m, > 0
  double roller_radius_m = 0.185;   // R_r (Table 1), m, > 0
  double length_factor = 0.2;       // phi = model / full (1:5), > 0
  double gravity_m_per_s2 = 9.81;   // load kg -> N, > 0
  // Both steels (39NiCrMo3 wheel, C45 roller): the paper gives no moduli; the project's steel (G 82 GPa, nu 0.28).
  Material material;
  RollerProfileChoice roller_profile = RollerProfileChoice::ScaledUic60;
  int fastsim_elements = 30;        // FASTSIM elements per strip and strips, >= 4
  void validate() const;
};

// The combined curvatures of the rig contact at the centred position.
struct RollerRigCurvatures {
  double A_per_m = 0.0;                 // 1/(2 r_w) + 1/(2 R_r)
  double B_per_m = 0.0;                 // see RollerProfileChoice
  double full_scale_A_per_m = 0.0;      // wheel on straight rail at full scale: cos(alpha_w)/(2 r), r = r_w / phi
  double full_scale_B_per_m = 0.0;      // (kappa_wheel + kappa_rail)/2 at full scale
  double full_scale_wheel_curvature_per_m = 0.0;  // S1002 at the contact point, convex > 0
  double full_scale_rail_curvature_per_m = 0.0;   // 60E1 1:20 at the contact point
  double contact_angle_rad = 0.0;       // rail normal from vertical (unchanged by the scaling)
  double wheel_profile_y_m = 0.0;       // contact point on the full-scale wheel profile (taping line 0)
};
// Full-scale S1002 / 60E1 1:20 wheelset (gauge 1435 mm, flange backs 1360 mm), rigid equilibrium at y = 0, yaw 0.
RollerRigCurvatures RollerRigCentredCurvatures(const RollerRigAdhesionOptions& options);

// Kalker's linear theory for one load (paper 000 eq. 22).
struct RollerRigLinearContact {
  double normal_force_N = 0.0;
  HertzResult hertz;              // a (rolling), b (lateral)
  double c11 = 0.0;               // Kalker C11 at a/b and nu
  double linear_slope_N = 0.0;    // G a b C11: dF_x/dxi at xi -> 0, N per unit creepage
};
RollerRigLinearContact RollerRigLinearTheory(const RollerRigCurvatures& curvatures, double normal_force_N,
                                             const Material& material);

// Rolling speed V = omega R_r of the reference roller, m/s.
double RollerRigRollingSpeed(double reference_speed_rpm, double roller_radius_m);

// Traction coefficient -F_x / N of FASTSIM on the Hertz ellipse (elliptic bound, centre-exact marching, no blending),
// pure longitudinal creepage xi >= 0, flexibilities divided by the slope reduction k (paper 002 eq. 9), the friction
// law of the local slip gamma (slip velocity / V); V = rolling_speed_m_per_s (> 0).
double RollerRigTractionCoefficient(const RollerRigLinearContact& contact, const Material& material,
                                    const FrictionLaw& law, double slope_reduction, double creepage,
                                    double rolling_speed_m_per_s, int elements);

}  // namespace conforma
