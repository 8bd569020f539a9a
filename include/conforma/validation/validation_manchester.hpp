#pragma once
// Manchester contact benchmark, left wheel (CONTACT reference results, shared data
// reference/contact_mbench_a22_left.csv): new S1002 on UIC60 canted 1:40, gauge 1435 mm at 14 mm, flange-back
// distance 1360 mm, r0 = 460 mm, G = 82 GPa, nu = 0.28, mu = 0.3, 10 kN vertical load, 2 m/s, y = 0:0.5:10 mm,
// yaw = 2.4 y mrad, roll per case from the file.
//
// Mapping to CONTACT's frames (tests/test_manchester_geometry.cpp): wheelset y_ours = -y_ws, yaw_ours = -yaw,
// roll identical; y_cp_rail = -y_ours (rail profile),
// delta_cp = delta_ours, creepages identical; CONTACT's fx/fs have the signs of our forces on the wheel.
#include <string>
#include <vector>

#include "conforma/progress.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

// One row of the reference CSV, in CONTACT's frames and units (columns of the same names; roll: roll_ws_rad).
struct ManchesterReferenceCase {
  int id = 0;                                              // column `case`
  double y_ws_mm = 0.0, yaw_mrad = 0.0, roll_rad = 0.0;    // wheelset pose (CONTACT's track frame)
  double y_cp_rail_mm = 0.0, delta_cp_rad = 0.0;           // contact point on the rail profile, contact angle
  double fn_N = 0.0, fx_N = 0.0, fs_N = 0.0, mn_Nmm = 0.0;  // normal, creep forces (N) and spin moment (N mm)
  double xi = 0.0, eta = 0.0, phi_per_mm = 0.0;            // creepages (xi, eta dimensionless; spin 1/mm)
  double p_max_MPa = 0.0, area_mm2 = 0.0;                  // maximum pressure, contact area
};

// Reads the CSV (InputError naming the file and line on malformed content).
std::vector<ManchesterReferenceCase> ReadManchesterReference(const std::string& path);

struct ManchesterComparison {
  ManchesterReferenceCase reference;
  WheelContactReport report;  // left wheel
  // Ours: fn_N, area_mm2, fx_N, fs_N summed over all patches; pmax_MPa, y_cp_mm (CONTACT's rail y) and delta_rad of
  // the main patch (largest normal force). All 0 without a patch.
  double fn_N = 0.0, pmax_MPa = 0.0, area_mm2 = 0.0, fx_N = 0.0, fs_N = 0.0, y_cp_mm = 0.0, delta_rad = 0.0;
  double err_fn = 0.0, err_pmax = 0.0, err_area = 0.0;  // relative: ours / reference - 1
  double err_fx_N = 0.0, err_fs_N = 0.0;  // absolute [N]: ours - reference
  int patches = 0;                        // patches of the wheel
};

// Where the file's creepages are applied (with creepages_from_file).
//   OurReferencePoint: as given, at our patch's contact reference point (the default, the figures of the goldens).
//   ContactReferencePoint: moved from CONTACT's contact reference point y_cp to ours along the rigid-slip field
//     w_x(y) = xi - phi y (Kalker; docs/physics-reference.md §14.4): xi' = xi + phi (y_cp,ours - y_cp,CONTACT), both
//     in the rail-profile y of the file (CONTACT's contact-frame lateral axis of the left wheel points against it:
//     with the other sign the exact model misses CONTACT's F_x by up to 171 N on cases 2-21, with this one by <= 5 N).
//     eta and phi are unchanged. The two reference points are up to 2.1 mm apart (case 1), 0.8 mm on case 2.
enum class ManchesterCreepageOrigin { OurReferencePoint, ContactReferencePoint };

struct ManchesterOptions {
  ContactModel model = ContactModel::Conformal;  // WheelContactOptions::model
  bool creepages_from_file = true;  // use each case's xi, eta, phi (as the issue asks); else the kinematics
  ManchesterCreepageOrigin creepage_origin = ManchesterCreepageOrigin::OurReferencePoint;  // see above
  int fastsim_elements = kDefaultFastsimElements;  // WheelContactOptions::fastsim_elements, >= 2
  bool kp_spin_about_patch_centre = false;  // WheelContactOptions::kp_spin_about_patch_centre
  bool kp_local_flexibilities = false;      // WheelContactOptions::kp_local_flexibilities
  LoadBalance load_balance = LoadBalance::Total;  // WheelContactOptions::load_balance
  ProgressFunction on_progress;  // progress (progress.hpp), one unit per case ("case <id>"); empty: none
};

// Runs every case (profiles from the shared data folder `shared_data_dir`); cases are independent and run in
// parallel with OpenMP (results identical for any thread count).
std::vector<ManchesterComparison> RunManchesterA22(const std::string& shared_data_dir, const ManchesterOptions& options);

}  // namespace conforma
