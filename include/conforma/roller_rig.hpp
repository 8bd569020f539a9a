#pragma once
// Roller-rig mode (issue 18, paper 000 §2, Table 1; docs/physics-reference.md §18): a single suspended wheelset on two
// independently driven rollers. This header: the rig set-up (Table 1 and what the paper does not print, as explicit
// options with documented defaults), the 1:5 profiles, and the TrackSetup of the rig (each roller stands in for a
// rail: TrackSetup::roller_radius_m = R_r on both sides; the geometric effect of the roller curvature along x is the
// geometry layer's, geometry.hpp).
//
// Sides: roller 1 is under the LEFT wheel (side index 0), roller 2 under the RIGHT wheel (index 1).
// Profiles (paper 000 §4):
//   wheel  "conical": the wear tests' simplified wheel, a straight cone of conicity wheel_conicity_rad (0.036 rad)
//                     from the flange-back position to y = +wheel_width_field_m (no flange);
//          "s1002":   S1002 scaled by the length factor (similitude.hpp, Length) - the adhesion tests' wheel;
//          else a profile file (profile_io.hpp), taken as it is (already at rig scale).
//   roller "uic60_1in20": 60E1 canted 1:20 scaled by the length factor (the paper's rollers; its undisclosed
//                     modification for the a/b ratio is left out, as in docs/physics-reference.md §7.5);
//          else a profile file, taken as it is (canted, at rig scale).
// The shared roller profiles (profiles/contact/ of the shared data, docs/data.md) are of other rigs (§7.5 there)
// and are not the default.
#include <array>
#include <string>

#include "conforma/geometry.hpp"
#include "conforma/material.hpp"
#include "conforma/profile.hpp"

namespace conforma {

// validate() throws InputError naming the field outside the range given.
struct RollerRigSetup {
  double roller_radius_m = 0.185;       // nominal roller radius R_r (Table 1), m, > 0
  double wheel_radius_m = 0.0944;       // nominal wheel radius r_w (Table 1), m, > 0
  double wheelset_mass_kg = 13.0;       // Table 1, kg, > 0 (not used by the quasi-static balance; reported)
  double inertia_x_kg_m2 = 0.28;        // I_x (Table 1), kg m^2, > 0
  double inertia_y_kg_m2 = 0.035;       // I_y about the axle (Table 1), kg m^2, > 0
  double inertia_z_kg_m2 = 0.28;        // I_z (Table 1), kg m^2, > 0
  double length_factor = 0.2;           // phi = rig / full scale (1:5), > 0; scales the track dimensions and profiles
  // Longitudinal suspension (paper 000 §2.1: two longitudinal helical springs per axle box, "high stiffness"; the
  // value is not printed): stiffness per axle box, N/m, > 0. Default 2e6 N/m: a full-scale primary longitudinal
  // stiffness of 10 MN/m per box scaled by phi (similitude contact_stress rule, stiffness ~ phi). An assumption.
  double longitudinal_stiffness_N_per_m = 2.0e6;
  // Lateral half-distance of the two axle boxes' longitudinal springs from the wheelset centre, m, > 0. Default
  // 0.2 m = 1 m (full-scale axle-box half-spacing) x phi. An assumption (not printed).
  double spring_half_spacing_m = 0.2;
  std::string wheel_profile = "conical";      // "conical", "s1002" or a profile file (see above)
  double wheel_conicity_rad = 0.036;          // "conical" wheel: cone angle (paper 000 §4), rad, in [0, 0.2]
  double wheel_width_field_m = 0.012;         // "conical" wheel: tread extent from the taping line to the field side, m, > 0
  std::string roller_profile = "uic60_1in20";  // "uic60_1in20" or a profile file (see above)
  Material wheel_material;                    // elastic constants of the wheel (project steel by default)
  Material roller_material;                   // of the roller; the contact solver uses wheel_material for both
  void validate() const;
};

// The rig's wheel and roller profiles (right-side convention of profile.hpp), built or read as described above.
// InputError for an unknown name that is not a readable file.
Profile MakeRollerRigWheelProfile(const RollerRigSetup& setup);
Profile MakeRollerRigRollerProfile(const RollerRigSetup& setup);

// The rig as a track set-up: gauge 1.435 m, gauge height 14 mm, flange-back distance 1.360 m and position -70 mm,
// all times phi; nominal radii r_w; roller_radius_m = R_r both sides; rail inclination 0 (the roller profile is
// already canted). wheel / roller: [left, right] profiles.
TrackSetup MakeRollerRigTrack(const RollerRigSetup& setup, std::array<Profile, 2> wheel, std::array<Profile, 2> roller);

// Geometry options at rig scale: table spacing 0.1 mm x phi, scan 0.5 mm x phi (GeometryOptions defaults x phi).
GeometryOptions RollerRigGeometryOptions(const RollerRigSetup& setup);

}  // namespace conforma
