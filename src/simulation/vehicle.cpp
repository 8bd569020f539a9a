// Vehicle description for the quasi-static curving model (vehicle.hpp).
#include "conforma/vehicle.hpp"

#include "conforma/error.hpp"

namespace conforma {

void VehicleParameters::validate() const {
  require_positive(wheelset_mass_kg, "wheelset_mass_kg");
  require_non_negative(bogie_frame_mass_kg, "bogie_frame_mass_kg");
  require_non_negative(carbody_mass_per_bogie_kg, "carbody_mass_per_bogie_kg");
  if (bogie_count < 1 || bogie_count > kMaxBogieCount)
    throw InputError("vehicle field 'bogie_count' must lie in [1, " + std::to_string(kMaxBogieCount) + "] (got " +
                     std::to_string(bogie_count) + ")");
  if (bogie_count > 1) require_positive(bogie_centre_distance_m, "bogie_centre_distance_m");
  else require_non_negative(bogie_centre_distance_m, "bogie_centre_distance_m");
  require_positive(wheelbase_m, "wheelbase_m");
  require_positive(nominal_wheel_radius_m, "nominal_wheel_radius_m");
  require_positive(primary_longitudinal_stiffness_N_m, "primary_longitudinal_stiffness_N_m");
  require_positive(primary_lateral_stiffness_N_m, "primary_lateral_stiffness_N_m");
  require_positive(lateral_axlebox_spacing_m, "lateral_axlebox_spacing_m");
  require_non_negative(secondary_yaw_stiffness_Nm_rad, "secondary_yaw_stiffness_Nm_rad");
  require_non_negative(secondary_lateral_stiffness_N_m, "secondary_lateral_stiffness_N_m");
  require_non_negative(load_transfer_height_m, "load_transfer_height_m");
  require_positive(contact_half_distance_m, "contact_half_distance_m");
  require_positive(wheelset_yaw_inertia_kgm2, "wheelset_yaw_inertia_kgm2");
  require_positive(wheelset_spin_inertia_kgm2, "wheelset_spin_inertia_kgm2");
  require_positive(bogie_frame_yaw_inertia_kgm2, "bogie_frame_yaw_inertia_kgm2");
  require_positive(carbody_yaw_gyration_radius_m, "carbody_yaw_gyration_radius_m");
  require_non_negative(primary_longitudinal_damping_Ns_m, "primary_longitudinal_damping_Ns_m");
  require_non_negative(primary_lateral_damping_Ns_m, "primary_lateral_damping_Ns_m");
  require_non_negative(secondary_lateral_damping_Ns_m, "secondary_lateral_damping_Ns_m");
  require_non_negative(secondary_yaw_damping_Nms_rad, "secondary_yaw_damping_Nms_rad");
}

VehicleParameters MinuettoVehicle() {
  VehicleParameters v;
  v.name = "ALn 501 Minuetto";
  v.wheelset_mass_kg = 1300.0;                                   // assumed
  v.bogie_frame_mass_kg = 3306.0;                                // motor bogie frame
  v.carbody_mass_per_bogie_kg = (2.0 * 31568.0 + 14496.0) / 4.0; // 3 coaches on 4 bogies
  v.bogie_count = 4;
  v.bogie_centre_distance_m = 14.8;                              // assumed
  v.wheelbase_m = 2.6;                                           // assumed (2.5-2.8 m typical)
  v.nominal_wheel_radius_m = 0.43;                               // scenario input
  v.primary_longitudinal_stiffness_N_m = 1.26e6 + 2.0e7;         // Flexicoil || Sutuco
  v.primary_lateral_stiffness_N_m = 1.26e6 + 1.5e7;
  v.lateral_axlebox_spacing_m = 2.0;                             // assumed
  v.secondary_lateral_stiffness_N_m = 2.0 * 1.2e5;               // two airsprings
  v.secondary_yaw_stiffness_Nm_rad = 2.0 * 1.2e5 * 1.0 * 1.0;    // kx b^2 per airspring, b = 1.0 m (assumed)
  v.load_transfer_height_m = 1.5;                                // carbody zG 1.91 m, lower bogie/wheelset masses
  return v;
}

VehicleParameters MetroVehicle() {
  VehicleParameters v;
  v.name = "metro vehicle (paper 003)";
  v.bogie_count = 5;
  v.bogie_centre_distance_m = (10.85 + 11.0 + 11.0 + 10.85) / 4.0;
  v.wheelbase_m = 2.0;
  v.nominal_wheel_radius_m = 0.711 / 2.0;
  // not printed in paper 003: typical metro values
  v.wheelset_mass_kg = 1100.0;
  v.bogie_frame_mass_kg = 2500.0;
  v.carbody_mass_per_bogie_kg = 14000.0;
  v.primary_longitudinal_stiffness_N_m = 1.0e7;
  v.primary_lateral_stiffness_N_m = 4.0e6;
  v.lateral_axlebox_spacing_m = 1.9;
  v.secondary_lateral_stiffness_N_m = 3.0e5;
  v.secondary_yaw_stiffness_Nm_rad = 3.0e5;
  v.load_transfer_height_m = 1.3;
  return v;
}

}  // namespace conforma
