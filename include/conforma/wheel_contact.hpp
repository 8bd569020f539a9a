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

// One element of a solved patch (the fields the wear computation needs).
struct ContactCell {
  double x_m = 0.0;            // along the track, from the wheel's diametral plane
  double s_m = 0.0;            // along the rail profile from the patch reference point (+ towards the field side)
  double rail_s_m = 0.0;       // arc length on the mounted rail profile
  double wheel_y_m = 0.0;      // wheel-profile lateral coordinate facing the cell
  double area_m2 = 0.0, length_x_m = 0.0;
  double pressure_Pa = 0.0;
  double traction_x_Pa = 0.0, traction_s_Pa = 0.0;  // on the wheel, local (x, s) frame
  double slip_x = 0.0, slip_s = 0.0;                // dimensionless slip (slip velocity / V)
  bool in_slip = false;
};

// Per patch: the keys of `conforma contact --json` (units in the names).
struct PatchReport {
  ContactModel model = ContactModel::Hertz;  // the model that solved this patch (auto: the chosen one)
  double auto_alpha_c_deg = 0.0;             // auto only: the conformity index estimated for the choice
  std::string normal_status, tangential_status;
  double fn_N = 0.0, fx_N = 0.0, fy_N = 0.0, mz_Nm = 0.0;
  double pmax_Pa = 0.0, p0_Pa = 0.0, area_m2 = 0.0;
  double a_m = 0.0, b_m = 0.0;               // Hertz semi-axes, or the SDEC / equivalent ellipse
  double width_m = 0.0, length_m = 0.0;      // extent along s^r and along x^r
  double approach_m = 0.0;                   // approach of this patch along its reference normal
  double contact_angle_rad = 0.0;            // + towards the gauge side (geometry.hpp)
  double y_contact_rail_m = 0.0, z_contact_rail_m = 0.0;  // reference point, mounted rail profile
  double y_contact_wheel_m = 0.0;            // wheel-profile y at the reference point
  double rolling_radius_m = 0.0;
  double lead_m = 0.0;                       // longitudinal position of the reference point (yaw lead)
  double xi = 0.0, eta = 0.0, phi_per_m = 0.0;  // creepages at the reference point
  double alpha_c_deg = 0.0;                  // conformity index (paper 003 eq. 13)
  bool is_conformal = false;
  double adhesion_area_m2 = 0.0, slip_area_m2 = 0.0, frictional_power_W = 0.0;
  double vertical_force_N = 0.0, lateral_force_N = 0.0;  // normal + tangential force on the wheel, side frame
  double reference_s_on_rail_m = 0.0;        // arc length of the reference point on the mounted rail
  std::vector<ContactCell> cells;            // only with WheelContactOptions::keep_fields
};

enum class WheelContactStatus { Ok, NoContact, NotConverged };
const char* to_string(WheelContactStatus status);

struct WheelContactReport {
  WheelContactStatus status = WheelContactStatus::NoContact;
  Side side = Side::Left;
  ContactModel model = ContactModel::Hertz;
  WheelsetPose pose;                 // the pose the patches were solved at (vertical pushed down in load control)
  std::vector<PatchReport> patches;  // ordered along the rail, gauge side first
  double vertical_force_N = 0.0;     // sum over patches (side frame z), pressure and creep forces
  // Vertical component of the pressure (normal) forces alone: what load control balances against the load.
  double pressure_vertical_force_N = 0.0;
  double lateral_force_N = 0.0;      // sum over patches (side frame eta, + towards the field side)
  int load_iterations = 0;
};

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
  struct Stats {
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
