#pragma once
// Vehicle description for the quasi-static curving model (kinematics_quasistatic.hpp): a chain of two-axle
// bogies joined by carbodies (a two-bogie vehicle, or an articulated train on Jacobs bogies such as the ALn 501
// "Minuetto" of paper 001 or the metro vehicle of paper 003 §3). Only what the steady lateral/yaw equilibrium
// needs: masses, the bogie geometry and the lateral/yaw stiffnesses of the suspension stages.
//
// Layout (track x forward): the bogies are numbered from the front (0 = leading), consecutive bogie centres are
// bogie_centre_distance_m apart and each pair of consecutive bogies carries one carbody (a chord of the curve).
// Each bogie has two wheelsets at +/- wheelbase/2 from its centre (wheelset 2i leading, 2i+1 trailing); each
// wheelset has two axleboxes, lateral_axlebox_spacing/2 = b_x either side of the track centre line, each with a
// longitudinal spring k_x and a lateral spring k_y to the bogie frame (primary suspension). The secondary
// suspension connects the bogie frame to the carbody(ies) with a lateral stiffness and a yaw stiffness.
#include <string>

namespace conforma {

// The most bogies a vehicle may have: a 32-car train unit of two bogies each. The dynamics' dense Jacobian grows as
// its square (1,000 bogies took 4.7 GB within 25 s before this bound).
constexpr int kMaxBogieCount = 64;

struct VehicleParameters {
  std::string name = "vehicle";
  double wheelset_mass_kg = 1300.0;
  double bogie_frame_mass_kg = 3000.0;
  double carbody_mass_per_bogie_kg = 15000.0;   // share of the carbody (and payload) mass carried by one bogie
  int bogie_count = 2;                          // 1 ... kMaxBogieCount
  double bogie_centre_distance_m = 15.0;        // between consecutive bogie centres
  double wheelbase_m = 2.5;                     // of the two-axle bogie (2a)
  double nominal_wheel_radius_m = 0.46;         // r0
  // Primary suspension, PER AXLEBOX (two axleboxes per wheelset).
  double primary_longitudinal_stiffness_N_m = 1.0e7;   // k_x
  double primary_lateral_stiffness_N_m = 5.0e6;        // k_y
  double lateral_axlebox_spacing_m = 2.0;              // 2 b_x: lateral distance between the two axleboxes
  // Secondary suspension, PER BOGIE (all springs of the stage together), bogie frame to carbody.
  double secondary_yaw_stiffness_Nm_rad = 5.0e5;
  double secondary_lateral_stiffness_N_m = 2.4e5;
  // Height above the rail top of the centre of gravity of the mass carried by the wheels, for the quasi-static
  // lateral load transfer Delta Q = m a_nc h / (2 b0) between the wheels of a wheelset; 0 disables it.
  double load_transfer_height_m = 0.0;
  double contact_half_distance_m = 0.75;        // b0: half the lateral distance of the nominal contact points
  // ---- Time-domain model only (vehicle_dynamics_model.hpp); the quasi-static curving model ignores these. ----
  // Typical values of a passenger bogie vehicle (orders of magnitude as in Iwnicki's Manchester benchmark
  // vehicle and Wickens 2003, recalled; not a particular vehicle's data).
  double wheelset_yaw_inertia_kgm2 = 700.0;       // I_wz about the vertical axis, > 0
  double wheelset_spin_inertia_kgm2 = 110.0;      // I_wy about the axle, > 0 (axle-speed degree of freedom)
  double bogie_frame_yaw_inertia_kgm2 = 2000.0;   // I_bz, > 0
  double carbody_yaw_gyration_radius_m = 6.0;     // carbody I_cz = m_carbody r^2 (a 22 m body: L / sqrt(12)), > 0
  // Primary dampers, PER AXLEBOX, in parallel with k_x and k_y (rubber-spring damping; 0: none).
  double primary_longitudinal_damping_Ns_m = 0.0; // c_x, N s/m, >= 0 (yaw damping 2 c_x b_x^2 per wheelset)
  double primary_lateral_damping_Ns_m = 0.0;      // c_y, N s/m, >= 0
  // Secondary dampers, PER BOGIE, bogie frame to carbody.
  double secondary_lateral_damping_Ns_m = 3.0e4;  // N s/m, >= 0 (lateral dampers)
  // Yaw dampers of the secondary stage, N m s/rad, >= 0: 0 none; a high-speed bogie has two of ~2e5 N s/m at
  // +/- 1.3 m, 2 c b^2 ~ 7e5 N m s/rad
  double secondary_yaw_damping_Nms_rad = 0.0;

  void validate() const;  // throws InputError naming the field
  int wheelset_count() const { return 2 * bogie_count; }
  // Mass carried by the wheels of one wheelset (carbody share, bogie frame and wheelset shares).
  double carried_mass_per_wheelset_kg() const {
    return 0.5 * (carbody_mass_per_bogie_kg + bogie_frame_mass_kg) + wheelset_mass_kg;
  }
  double total_mass_kg() const { return bogie_count * (carbody_mass_per_bogie_kg + bogie_frame_mass_kg + 2.0 * wheelset_mass_kg); }
  // Static vertical load of one wheel on level track: g * carried_mass_per_wheelset / 2.
  double static_wheel_load_N(double gravity_m_s2 = 9.81) const { return 0.5 * gravity_m_s2 * carried_mass_per_wheelset_kg(); }
};

// ALn 501 "Minuetto" DMU of the Aosta line (paper 001; shared/data/measured/aosta_minuetto/
// vehicle_aln501_minuetto.md): 3 coaches on 4 bogies (2 motor + 2 Jacobs), carbody masses 2 x 31568 + 14496 kg
// shared equally by the 4 bogies, motor bogie frame 3306 kg. Primary: Flexicoil (kx = ky = 1.26e6 N/m) in
// PARALLEL with the axlebox-arm silent block (Sutuco, kx = 2.0e7, ky = 1.5e7 N/m) per axlebox. Secondary: two
// airsprings per bogie (kx = ky = 1.2e5 N/m each) at +/- 1.0 m (assumed). NOT in the data sheet (assumed,
// documented as such): wheelbase 2.6 m, bogie centre distance 14.8 m, wheelset mass 1300 kg, axlebox spacing
// 2.0 m, wheel radius 0.43 m (scenario input), load-transfer height 1.5 m.
VehicleParameters MinuettoVehicle();

// Metro vehicle of paper 003 §3, Table 1: 5 bogies (2 end + 3 Jacobs) 10.85/11.0/11.0/10.85 m apart (mean
// 10.925 m), wheelbase 2.0 m, wheel diameter 711 mm. Masses and stiffnesses are not printed in the paper:
// typical metro values are used (documented in vehicle.cpp).
VehicleParameters MetroVehicle();

}  // namespace conforma
