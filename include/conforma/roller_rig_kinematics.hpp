#pragma once
// Roller-rig kinematics (issue 18, paper 000 §2 eqs. 1-2, §3.1 (iii); docs/physics-reference.md §18.2): two rollers
// driven at omega_1 (left wheel) and omega_2 (right wheel), the free (undriven) wheelset turning at omega_3.
//
//   Creepage of contact i (paper 000 eq. 2):  xi_i = (omega_i R_i - omega_3 r_i) / (omega_i R_i)
//     R_i: roller rolling radius at the contact = R_r + z_roller(contact) (the mounted roller profile's height, origin
//          at its top), r_i: the loaded wheel's effective rolling radius r_w + z_wheel(contact) - delta (Hertz
//          approach delta: the contact solver's kinematics put the wheel centre delta lower onto the undeformed
//          roller; delta ~ 5 um = 5e-5 r_w at 50 kg); V_i = omega_i R_i the reference speed
//          (paper 000 eq. 13). The contact solver gets V_i as the forward speed and omega_3 as the axle speed, so its
//          creepages (creepage.hpp) are eq. 2 plus the yaw's lateral creepage and the spin.
//   First approximation (eq. 2 with opposite creepages, xi_1 = -xi_2, paper 000 §2):
//          omega_3 = 2 / (r_1 / (omega_1 R_1) + r_2 / (omega_2 R_2))
//   Solution: the wheelset turns freely, so the moment of the two longitudinal contact forces about the axle balances
//   the applied axle torque (0 for the free wheelset): g(omega_3) = r_1 F_x1 + r_2 F_x2 + T_axle = 0, a 1-D root
//   (Boost's TOMS 748 bracketing solver, started from the eq. 2 value inside the bracket omega_3 in
//   [min V_i/r_i, max V_i/r_i], where both creepages have one sign at each end). The longitudinal springs of the two axle boxes (stiffness k each, at +-b_s) then carry the net
//   longitudinal force and the yaw moment of the contact forces (quasi-static):
//          F_sL + F_sR + F_x1 + F_x2 = 0,   b_s (F_sR - F_sL) + y_1 F_x1 ... (moment about z, see the .cpp)
//   with spring deflections u = -F_s / k and the yaw deflection psi_s = (u_R - u_L) / (2 b_s).
// Forces are on the wheel, in the contact frame (x along the rolling direction), summed over the patches of a side.
#include <array>
#include <limits>
#include <string>

#include "conforma/roller_rig.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

// Paper 000 eq. 2 for one contact. InputError for a non-positive roller surface speed.
double RollerRigCreepage(double roller_speed_rad_s, double roller_radius_m, double wheelset_speed_rad_s,
                         double wheel_radius_m);
// The first approximation above (opposite creepages). InputError for non-positive speeds or radii.
double RollerRigEq2WheelsetSpeed(const std::array<double, 2>& roller_speed_rad_s,
                                 const std::array<double, 2>& roller_radius_m,
                                 const std::array<double, 2>& wheel_radius_m);

// The rig state one kinematics solve needs (measured or prescribed).
struct RollerRigKinematicsInput {
  double lateral_m = 0.0;                             // wheelset lateral shift y (geometry.hpp), m
  double yaw_rad = 0.0;                               // wheelset yaw psi, rad
  double lateral_velocity_m_s = 0.0;                  // dy/dt, m/s
  std::array<double, 2> roller_speed_rad_s{0.0, 0.0}; // omega_1 (left), omega_2 (right), rad/s, > 0
  std::array<double, 2> wheel_load_N{0.0, 0.0};       // vertical load on each wheel, N, > 0
  // Measured wheelset speed omega_3, rad/s (the rig's axle encoder); NaN (default): solved by the moment balance.
  double wheelset_speed_rad_s = std::numeric_limits<double>::quiet_NaN();
  double axle_torque_Nm = 0.0;                        // torque applied to the wheelset about the axle (0: free), N m
};

// validate() throws InputError for a value outside the ranges given.
struct RollerRigKinematicsOptions {
  WheelContactOptions contact;        // every contact solve (RollerRigContactOptions gives the rig defaults)
  // |g| <= this x (r_1 |F_x1| + r_2 |F_x2|) at the root, > 0. In full sliding at both contacts (constant mu) g is
  // flat (~1e-7 of the scale, from the spin) over the whole range between the saturation creepages, and the first
  // approximation (eq. 2, opposite creepages) is accepted: the balance does not determine omega_3 better there.
  double balance_tolerance = 1e-7;
  int max_evaluations = 60;           // contact-pair evaluations of the root find, >= 2
  // A contact whose load control stopped short (WheelContactStatus::NotConverged with patches, e.g. the contact point
  // jumping between the shoulders of a worn groove) is accepted when its carried vertical force is within this
  // fraction of the load (as the wear loop's load_acceptance, wear_simulation.hpp), >= 0; default 2 %.
  double load_acceptance = 0.02;
  // true: omega_3 is eq. 2's first approximation (opposite creepages at the loaded radii), no balance is solved (a
  // test plan that prescribes the creepage of each contact, paper 000 Table 5); false: the moment balance. A measured
  // omega_3 (RollerRigKinematicsInput) takes precedence over both.
  bool eq2_wheelset_speed = false;
  void validate() const;
};
// The rig's contact options: model hertz, FASTSIM 20 x 20 (paper 000 §3.4), strip width 0.1 mm x phi, patch
// combination distance 4 mm x phi, load balance of the pressure (the normal problem then does not depend on omega_3
// and is reused along the root find; the creep force's vertical part is below mu sin(delta) of the load on the tread).
WheelContactOptions RollerRigContactOptions(const RollerRigSetup& setup);

// One contact (one side) at the solved or measured omega_3.
struct RollerRigContactResult {
  WheelContactReport report;          // the contact solve (patches, forces, creepages; status)
  double roller_rolling_radius_m = 0.0;  // R_i = R_r + z_roller at the contact reference point, m
  double wheel_rolling_radius_m = 0.0;   // r_i: effective, r_w + z_wheel - approach (see above), m
  double roller_surface_speed_m_s = 0.0; // V_i = omega_i R_i, m/s
  double eq2_creepage = 0.0;          // paper 000 eq. 2 at the solved omega_3 (R_i, r_i)
  double fx_N = 0.0;                  // longitudinal creep force on the wheel, summed over patches, N
  double fy_N = 0.0;                  // lateral creep force on the wheel, summed over patches, N
  double fn_N = 0.0;                  // normal force, summed over patches, N
  double xi = 0.0;                    // longitudinal creepage of the largest patch (the solver's)
  double eta = 0.0;                   // lateral creepage of the largest patch
  double phi_per_m = 0.0;             // spin of the largest patch, 1/m
  double contact_y_m = 0.0;           // track-frame lateral position of the rigid contact point, m
};

// Converged: omega_3 solved (|g| within tolerance); Measured: omega_3 given (measured, or eq. 2 with
// eq2_wheelset_speed; no balance solved); NotConverged: the
// root find stopped at max_evaluations or lost its bracket (last iterate reported); NoContact: a wheel has no contact
// (zero load, or the wheel does not face its roller) - nothing is balanced; ContactError: a contact solve rejected the
// current profiles (e.g. a worn profile whose patch turns beyond 90 degrees; the message names it) - the input had
// been validated, so this is the state of the profiles, reported, not thrown.
enum class RollerRigKinematicsStatus { Converged, Measured, NotConverged, NoContact, ContactError };
// "converged", "measured", "not_converged", "no_contact", "contact_error"
const char* to_string(RollerRigKinematicsStatus status);

struct RollerRigKinematicsResult {
  RollerRigKinematicsStatus status = RollerRigKinematicsStatus::NoContact;  // see RollerRigKinematicsStatus
  std::string message;                       // reason when not Converged / Measured; "" otherwise
  double wheelset_speed_rad_s = 0.0;         // omega_3 solved (or measured), rad/s
  double eq2_wheelset_speed_rad_s = 0.0;     // the first approximation (opposite creepages), rad/s
  std::array<RollerRigContactResult, 2> contact;  // [left (roller 1), right (roller 2)]
  double axle_moment_residual_Nm = 0.0;      // g = r_1 F_x1 + r_2 F_x2 + T_axle at the result, N m
  std::array<double, 2> spring_force_N{0.0, 0.0};  // longitudinal spring force on the wheelset [left, right box], N
  double longitudinal_displacement_m = 0.0;  // mean spring deflection (u_L + u_R) / 2, m
  double yaw_deflection_rad = 0.0;           // (u_R - u_L) / (2 b_s), rad
  int evaluations = 0;                       // contact-pair evaluations
};

// InputError for bad input; no contact or no convergence is a status.
RollerRigKinematicsResult SolveRollerRigKinematics(const WheelsetTrackGeometry& geometry, const RollerRigSetup& setup,
                                                   const RollerRigKinematicsInput& input,
                                                   const RollerRigKinematicsOptions& options);

}  // namespace conforma
