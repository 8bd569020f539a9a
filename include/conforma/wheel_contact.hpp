#pragma once
// One wheel's contact, from the wheelset pose to per-patch forces, with any contact model: the pipeline that the
// command line, the validation runners and (later) the wear loop and the C/Python interfaces call.
//
//   geometry  FindContactCandidates[ForLoad]  -> every interpenetration region as a PatchGeometry
//   normal    hertz | kp | kpec | conformal | reference (BEM)      (load control over the wheel's vertical push)
//             | auto: per patch hertz, kpec or conformal, chosen from the undeformed geometry (model_selection.hpp)
//   creepage  rigid slip from the wheelset velocities at the patch (per strip for the conformal model)
//   tangent   FASTSIM (hertz) | FASTSIM on the SDEC over the KP patch (kp, kpec) | curved-patch FASTSIM (conformal)
//             (auto: the tangential model of the patch's chosen normal model)
//   Zero creepage at a patch (all three exactly 0): the tangential solve is skipped (tangential_status
//   "no_creepage", creep forces, moment and power exactly 0, no cells) -- FASTSIM gives exactly zero traction and
//   slip there, so only the adhesion/slip areas and the cells (all adhesive, zero traction) are not reported.
//
// Frames: each wheel is reported in its side frame (geometry.hpp), i.e. the right wheel as the mirror image of a
// left wheel; forces are those ON THE WHEEL (Kalker's convention) in the patch's contact frame: fx along the track,
// fy along the rail profile towards the field side (+s), fn along the outward rail normal (pushing the wheel up).
// Wheel on roller (geometry.hpp): that frame turned by the contact's angle phi about the roller axis (fx along the
// roller's surface, fn through its axis; PatchReport::roller_angle_rad), so the side-frame sums include fx sin(phi).
#include <memory>
#include <string>
#include <vector>

#include "conforma/contact_candidates.hpp"
#include "conforma/creepage.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/geometry.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/material.hpp"
#include "conforma/model_selection.hpp"
#include "conforma/patch_solver.hpp"
#include "conforma/wheel_contact_options.hpp"

namespace conforma {

// One element of a solved patch (the fields the wear computation needs). Lengths in m.
struct ContactCell {
  double x_m = 0.0;            // along the track, from the wheel's diametral plane
  double s_m = 0.0;            // along the rail profile from the patch reference point (+ towards the field side)
  double rail_s_m = 0.0;       // arc length on the mounted rail profile
  double wheel_y_m = 0.0;      // wheel-profile lateral coordinate facing the cell
  double area_m2 = 0.0, length_x_m = 0.0;  // element area (m^2) and its length along x (area / strip width)
  double pressure_Pa = 0.0;    // normal pressure of the patch's normal solution at the element centre
  double traction_x_Pa = 0.0, traction_s_Pa = 0.0;  // on the wheel, local (x, s) frame
  double slip_x = 0.0, slip_s = 0.0;                // dimensionless slip (slip velocity / V); 0 in adhesion
  bool in_slip = false;        // the element slips (traction at the bound mu p)
};

// Per patch: the keys of `conforma contact --json` (units in the names). A patch is reported only when its normal
// problem found contact. The tangential fields (fx_N, fy_N, mz_Nm, adhesion_area_m2, slip_area_m2,
// frictional_power_W, the SDEC a_m / b_m, cells) are 0 / empty unless a FASTSIM ran: not with solve_tangential false,
// zero creepage (tangential_status "no_creepage") or the reference model ("not_solved").
struct PatchReport {
  ContactModel model = ContactModel::Hertz;  // the model that solved this patch (auto: the chosen one)
  double auto_alpha_c_deg = 0.0;             // auto only: the conformity index estimated for the choice, deg; else 0
  // normal_status: PatchNormalSolution::status ("ok", "hertz_regularised", "contact_at_patch_boundary", ...);
  // tangential_status: PatchTangentialSolution::status ("ok", "full_slip", "no_creepage", "not_solved", ...)
  std::string normal_status, tangential_status;
  // N, N, N, N m on the wheel in the patch's contact frame: normal force along the reference normal n0, creep forces
  // along x and along the rail profile t0 (+ field side), spin moment about n0
  double fn_N = 0.0, fx_N = 0.0, fy_N = 0.0, mz_Nm = 0.0;
  // Pa, Pa, m^2: maximum pressure, the model's p0 (patch_solver.hpp), contact area (KP models: on the curved surface)
  double pmax_Pa = 0.0, p0_Pa = 0.0, area_m2 = 0.0;
  // m: Hertz semi-axes (hertz), or the SDEC of the KP patch (kp, kpec, conformal; only when the tangential problem
  // was solved, else 0); 0 for the exact model
  double a_m = 0.0, b_m = 0.0;
  double width_m = 0.0, length_m = 0.0;      // extent along s^r and along x^r, m
  // Approach of this patch along its reference normal, m. KP models: the solved one. hertz and exact: the rigid
  // approach at the candidates' pose (load control: the Hertz push-down), without the load control's last push.
  double approach_m = 0.0;
  double contact_angle_rad = 0.0;            // + towards the gauge side (geometry.hpp)
  // Reference point in the mounted rail profile (y towards the field side, z up, origin at the rail top), m
  double y_contact_rail_m = 0.0, z_contact_rail_m = 0.0;
  double y_contact_wheel_m = 0.0;            // wheel-profile y at the reference point, m
  double rolling_radius_m = 0.0;             // wheel rolling radius at the reference point, m
  double roller_rolling_radius_m = 0.0;      // wheel on roller: the roller's R_r + z_r there, m (0: a rail)
  double roller_angle_rad = 0.0;             // wheel on roller: the point's angle about the roller axis (geometry.hpp)
  double lead_m = 0.0;                       // longitudinal position of the reference point (yaw lead), m
  // Creepages at the reference point (xi, eta dimensionless, phi in 1/m): the given ones (creepages_given) or from
  // the wheelset velocities (creepage.hpp)
  double xi = 0.0, eta = 0.0, phi_per_m = 0.0;
  double alpha_c_deg = 0.0;                  // conformity index (paper 003 eq. 13), deg; 0 for the hertz model
  bool is_conformal = false;                 // alpha_c_deg > conformity_threshold_deg (KP and exact models)
  // m^2, m^2, W; frictional_power_W = sum |traction . slip| V dA over the cells at the forward speed V
  double adhesion_area_m2 = 0.0, slip_area_m2 = 0.0, frictional_power_W = 0.0;
  double vertical_force_N = 0.0, lateral_force_N = 0.0;  // normal + tangential force on the wheel, side frame, N
  double reference_s_on_rail_m = 0.0;        // arc length of the reference point on the mounted rail, m
  // exact model: the convergence of its two iterative solves (0 for the other models): conjugate-gradient iterations
  // and last relative pressure change of the BEM normal solve at the final approach (BemResult), Gauss-Seidel sweeps
  // and last relative traction change of the tangential solve (ExactTangentialResult)
  int normal_iterations = 0, tangential_iterations = 0;
  double normal_residual = 0.0, tangential_residual = 0.0;
  // Only with WheelContactOptions::keep_fields and a solved tangential problem
  std::vector<ContactCell> cells;
};

// Ok: at least one patch in contact (and the load reached in load control). NoContact: no patch (no
// interpenetration, the wheel does not face the rail, or vertical_load_N == 0). NotConverged: load control failed:
// no load bracket (no patches reported), the load missed by more than 10x its tolerance (the last iterate's
// patches reported), or (total-force balance) the creep forces pull the wheel down so that no push-down carries the
// load, or its bracket was not found (the pressure-balanced solution reported; docs/physics-reference.md §3.6.1), or
// (LoadBalance::TotalConsistent) the candidates' load found no fixed point (the solution nearest to one reported).
enum class WheelContactStatus { Ok, NoContact, NotConverged };
const char* to_string(WheelContactStatus status);  // "ok", "no_contact", "not_converged"

struct WheelContactReport {
  WheelContactStatus status = WheelContactStatus::NoContact;  // see WheelContactStatus
  Side side = Side::Left;                    // the wheel solved
  ContactModel model = ContactModel::Hertz;  // WheelContactOptions::model (auto stays auto; per patch: PatchReport)
  WheelsetPose pose;                 // the pose the patches were solved at (vertical pushed down in load control)
  std::vector<PatchReport> patches;  // ordered along the rail, gauge side first
  // Sum over patches (side frame z), pressure and creep forces, N: what load control balances against the load
  // (WheelContactOptions::load_balance total, the default)
  double vertical_force_N = 0.0;
  // Vertical component of the pressure (normal) forces alone, N (balanced against the load with load_balance pressure)
  double pressure_vertical_force_N = 0.0;
  double lateral_force_N = 0.0;      // sum over patches (side frame eta, + towards the field side), N
  int load_iterations = 0;           // root-finder evaluations of the load control (total balance: §3.6.1); 0 in approach mode
  // Load control: the load the contact candidates (the patches' interpenetration regions) were found for, N: the
  // wheel load, or with LoadBalance::TotalConsistent the pressure forces' vertical load L of the fixed point
  // (§3.6.1 step 4; 0 in approach mode and for an unloaded wheel), and the number of candidate searches made (1, or
  // one per fixed-point iteration; 0 in approach mode and for an unloaded wheel)
  double candidate_load_N = 0.0;
  int candidate_searches = 0;
  // Plausibility warnings, one "code: message" line each (contact_plausibility.hpp): nominal radius far from the
  // profile's, friction outside 0.05-1, pressure above the material limit, load control not converged
  std::vector<std::string> warnings;
};

// Whether load control balances the wheel's total vertical force (pressure and creep forces solved together:
// LoadBalance::Total, a positive load and the tangential problem solved), and that balanced force of a report, N
// (vertical_force_N, else pressure_vertical_force_N): what the carried load of a result is measured by.
bool BalancesTotalVerticalForce(const WheelContactOptions& options);
double BalancedVerticalForce(const WheelContactReport& report, const WheelContactOptions& options);

// The wheel's main patch: the largest normal force, the first of equal ones (nullptr without a patch).
const PatchReport* MainPatch(const WheelContactReport& report);

// For the entry points (Python, C API, command line): InputError naming `where` unless the velocity is finite, the
// forward speed positive and the rigid creepages it implies at the nominal radius r0 (|v_y / V|, |Omega r0 / V - 1|,
// |yaw rate / V| in 1/m) within kMaxGivenCreepage: a yaw rate of 1e300 rad/s gave NaN forces with an OK status
// (fuzzing, session 25). The solvers themselves do not limit it (a time-domain run that diverges is a result).
void RequireRollingVelocity(const WheelsetVelocity& velocity, double nominal_radius_m, const std::string& where);
// InputError naming `name` unless load_N <= kMaxWheelLoadN (a larger number is a unit mistake); NaN is refused too.
void RequireWheelLoad(double load_N, const std::string& name);
// For the entry points: InputError naming `name` unless |approach_m| <= kMaxApproach_m.
void RequireApproach(double approach_m, const std::string& name);

// pose.vertical_m is the starting point of the push-down in load control and the actual position in approach
// mode. Throws InputError for bad options or velocities; no contact is a status.
WheelContactReport SolveWheelContact(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                     const WheelsetVelocity& velocity, const WheelContactOptions& options);

// Reuse of contact solutions between calls on ONE geometry (profiles unchanged), e.g. within one equilibrium
// solve, whose forward differences in the axle speed repeat the pose (normal problem reused) and whose trust-region
// steps repeat whole evaluations (report reused). Keyed by the geometry's address, the side, the pose and the
// options (the normal ones, plus velocity and tangential ones for a whole report): results are bit-identical to
// uncached calls. Thread-safe; at most max_entries of each kind are kept (cleared when full). Create one per
// geometry and drop it with the geometry (the address may be reused by the next one).
class WheelContactCache {
 public:
  explicit WheelContactCache(size_t max_entries = 1024);
  ~WheelContactCache();
  WheelContactCache(const WheelContactCache&) = delete;
  WheelContactCache& operator=(const WheelContactCache&) = delete;
  struct Stats {             // counts of calls since the cache was created
    long report_hits = 0;  // whole report reused
    long normal_hits = 0;  // normal problem reused, tangential solved
    long misses = 0;       // both solved
  };
  Stats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  friend WheelContactReport SolveWheelContactCached(const WheelsetTrackGeometry&, Side, const WheelsetPose&,
                                                    const WheelsetVelocity&, const WheelContactOptions&,
                                                    WheelContactCache&);
};

// SolveWheelContact through a cache (a separate name, so that &SolveWheelContact stays unambiguous).
WheelContactReport SolveWheelContactCached(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                           const WheelsetVelocity& velocity, const WheelContactOptions& options,
                                           WheelContactCache& cache);

}  // namespace conforma
