#pragma once
// Wear scenario: everything one run of the wear loop (wear_simulation.hpp) needs, read from a YAML file.
//
// File layout (units in the key names; every key optional unless marked; unknown keys are an InputError naming
// the key and the file):
//   name: default_metro
//   vehicle: { base: metro | minuetto, bogie_count: 5, wheelbase_m: 2.0, ... any VehicleParameters field }
//   kinematics: { provider: quasistatic | centred | kinematic | dynamic, tangent_amplitude_mm: 3, tangent_phases: 8,
//                 cant_base_m: 1.5, free_axle_rotation: true, axle_torque_Nm: 0, contact_model: hertz,
//                 dynamic: { duration_s: 4, settle_s: 1, sample_interval_s: 0.02, stepper: rosenbrock4,
//                            steps_per_s_max: 4000,
//                            contact: direct | lut, lut_creep: polach | fastsim (with contact: lut),
//                            stall_model: auto | none (with contact: lut),
//                            irregularity: { spectrum: ore_b176_low, seed: 1, wavelength_min_m: 3,
//                                            wavelength_max_m: 70 } | none } }
//       quasistatic: kinematics_quasistatic.hpp (Ceres, contact model in the loop) -- the default;
//       centred:     every wheelset centred and unyawed, yaw rate V/R, pure rolling (fast, for tests);
//       kinematic:   the kinematic curving estimate of wear_simulation.hpp (flange contact + angle of attack);
//       dynamic:     each class run in the time domain (dynamic_kinematics.hpp, dynamics layer: the commands inject
//                    it through WearSimulationOptions::kinematics_factory); `dynamic` holds its settings (the
//                    defaults shown; ScenarioDynamicKinematics).
//   track: { gauge_mm: 1435, rail_inclination: "1:20" | 0.05 (rad) }
//   profiles: { wheel: S1002 | <file>, rail: 50E4 | 60E1 | 54E1 | 50E6 | <file>, wheel_radius_mm: 355.5,
//               wheel_mirror / rail_mirror: false, wheel_z_down / rail_z_down: false, wheel_units / rail_units: mm | m,
//               wheel_smoothing_mm / rail_smoothing_mm: 0, wheel_format / rail_format: auto }  (how a profile file
//               is read, as --wheel-mirror ... on the command line; docs/profiles-and-formats.md §3)
//       a built-in rail is generated UNINCLINED and mounted with track.rail_inclination; a rail file is mounted
//       with the inclination too (give rail_inclination: 0 for files that are already canted).
//   material: { shear_modulus_Pa, poisson_ratio, density_kg_m3 }
//   friction: 0.3                       (default friction of the classes)
//   elastic_flange_deg: 60              (optional: contacts steeper than this are elastic flange contacts that may
//                                        interpenetrate at a wheel's reference position; absent: rigid flange)
//   load_tolerance: 1e-6                (optional: relative tolerance of every wheel's load control,
//                                        WheelContactOptions::load_tolerance; a contact that misses it by more
//                                        than 10x is not converged)
//   load_balance: total                 (optional: total | pressure | total-consistent, WheelContactOptions::
//                                        load_balance of the curving and wear solves, docs/physics-reference.md §3.6.1)
//   kp_spin_about_centre: false         (optional: WheelContactOptions::kp_spin_about_patch_centre of the curving and
//   kp_local_flexibilities: false        wear solves, FASTSIM variants on the KP patches, docs/physics-reference.md §5.4)
//   load_acceptance: 0.10               (optional: a not converged wheel contact still gives wear when its carried
//                                        load is within this fraction of the wheel load; else it is a failed one)
//   wear_law: usfd | <wear-law file>    (wear_law.hpp; the same law for wheel and rail unless rail_wear_law given)
//   rail_wear_law: usfd | <file>
//   contact_model: conformal            (hertz | kp | kpec | conformal; the command line may override)
//   update: { cap_mm: 0.4, smoothing_mm: 5.0, steps: 20, substeps: 1 (each step in this many sub-steps of
//             cap_mm / substeps, docs/physics-reference.md §8.12), total_km: 0 (0: no limit; the last step is
//             shortened to land on it), max_curvature_1_m: 1000, overhang_cut: conserve_area | wear_off
//             (ProfileUpdateOptions::cut_conserves_area; default conserve_area) }
//   rail: { fixed: true, steps: 0, cap_mm: 0.1, spacing_mm: 0 }  (fixed: paper 003 §7; steps m > 0: paper 003
//         Fig. 11; spacing_mm: arc-length spacing of the updated rails, 0 = that of the rail before the step)
//   track_classes: [ { name, radius_m (0 = tangent), cant_mm, speed_kmh, share (fractions or percent; they are
//                      normalised to sum 1), friction, acceleration_m_s2 | axle_torque_Nm } ... ]
//                      (acceleration_m_s2: traction > 0 / braking < 0 phase of the class, every axle driven alike:
//                      axle torque m a r0 with m the carried mass per wheelset; TrackClass::axle_torque_Nm)
//   track_classes_csv: <file> with columns radius_m,cant_mm,speed_kmh,share_percent ('#' comments); the
//                      remainder to 100 % becomes a tangent class at tangent_speed_kmh (key of the same map).
//   published: { source: "...", steps: 7, models: { conformal: { km, tread_wear_mm, flange_wear_mm, sd, sh, qr }, ... } }
//                      (figures of a published study of the same case, for `conforma compare`'s report;
//                      published_study.hpp)
// Relative file paths are resolved against the scenario file's folder; a path starting with $CONFORMA_DATA_DIR/ is
// in the shared data folder (data_paths.hpp SharedDataDir). Lengths in the file in mm where named.
#include <cstdint>
#include <string>
#include <vector>

#include "conforma/contact_model.hpp"
#include "conforma/kinematics.hpp"
#include "conforma/load_control.hpp"
#include "conforma/material.hpp"
#include "conforma/profile.hpp"
#include "conforma/published_study.hpp"
#include "conforma/track_irregularity_psd.hpp"
#include "conforma/wheel_contact_options.hpp"
#include "conforma/vehicle.hpp"
#include "conforma/wear_distribution.hpp"

namespace conforma {

// The kinematics provider of the scenario (`kinematics.provider` above): QuasiStatic (quasistatic), Centred
// (centred), Kinematic (kinematic).
// Dynamic (dynamic): the time-domain provider of the dynamics layer (dynamic_kinematics.hpp).
enum class KinematicsProvider { QuasiStatic, Centred, Kinematic, Dynamic };
const char* to_string(KinematicsProvider provider);  // "quasistatic", "centred", "kinematic", "dynamic"

// The `kinematics.dynamic` map: how the `dynamic` provider runs each track class in the time domain
// (dynamic_kinematics.hpp). Every field optional; bad values are an InputError naming the key.
struct ScenarioDynamicKinematics {
  double duration_s = 4.0;          // simulated time per class after settle_s whose samples are kept, s, > 0
  double settle_s = 1.0;            // simulated time discarded at the start (transient from the initial state), s, >= 0
  double sample_interval_s = 0.02;  // time between kept samples, s, > 0 and <= duration_s
  std::string stepper = "rosenbrock4";  // rosenbrock4 | dopri5 (vehicle_dynamics.hpp DynamicsStepper)
  // The integration's step budget, steps (accepted and rejected) per simulated second, > 0: a class that needs more
  // stops there (StepLimit); with dopri5 (stiff creep forces at a flange bound the explicit step) it is run again
  // with rosenbrock4 on the same budget (dynamic_kinematics.hpp). Normal runs take 200-1000 per s
  // (docs/physics-reference.md §16.5, §16.7).
  double steps_per_s_max = 4000.0;
  // Contact of the runs: `direct` (the curving contact model solved at every evaluation, SolveWheelContact) or `lut`
  // (a contact look-up table of each wheel step's geometry built in memory, contact_lut.hpp; its rigid equilibrium
  // and contact forces from the table; dynamic_kinematics_lut.hpp).
  bool lut_contact = false;         // contact: lut
  std::string lut_creep = "polach"; // lut_creep (contact: lut only): polach | fastsim (contact_lut.hpp LutCreepForce)
  // stall_model (contact: lut only): auto | none. auto: a class whose run on a hertz table stops at the step budget
  // (both steppers) is run again on a table of the `auto` contact model (dynamic_kinematics.hpp); none: it falls back.
  std::string stall_model = "auto";
  // Track irregularity (track_irregularity.hpp SynthesizeTrackIrregularity) under every class; `irregularity: none`
  // gives the perfect track (the samples then settle on the steady curving state).
  bool irregularity = true;
  IrregularitySpectrum spectrum = IrregularitySpectrum::OreB176Low;  // spectrum: ore_b176_low | ... | fra_class_6
  std::uint64_t seed = 1;           // seed: phases of the synthesis (same seed: the same track, bit for bit)
  double wavelength_min_m = 3.0;    // > 0
  double wavelength_max_m = 70.0;   // >= wavelength_min_m
};

// The `kinematics` map; the fields of QuasiStaticOptions of the same names.
struct ScenarioKinematics {
  KinematicsProvider provider = KinematicsProvider::QuasiStatic;  // default quasistatic
  double tangent_amplitude_m = 3e-3;  // m (tangent_amplitude_mm in the file)
  int tangent_phases = 8;             // phases of the tangent-track oscillation
  double cant_base_m = 1.5;           // m
  bool free_axle_rotation = true;     // false: axle speed V / r0
  // Drive torque per axle, N m (+ traction, - braking, 0 free rolling; docs/physics-reference.md §12.3).
  double axle_torque_Nm = 0.0;
  // Contact model inside the quasi-static curving solve (the multibody side). Unset: the wear step's model (the
  // co-simulation of paper 003 §2). A cheaper model here (e.g. hertz, as a multibody code with its own contact
  // would use) leaves the wear step's contact model unchanged and makes conformal runs several times faster.
  bool contact_model_set = false;                    // kinematics.contact_model given
  ContactModel contact_model = ContactModel::Hertz;  // read only with contact_model_set
  ScenarioDynamicKinematics dynamic;                 // kinematics.dynamic (used by the dynamic provider only)
};

struct ScenarioUpdate {
  double cap_m = 0.4e-3;               // largest wheel depth of a step (paper 003 §6)
  double smoothing_cutoff_m = 5e-3;    // DepthSmoothingOptions::cutoff_wavelength_m
  int steps = 20;                      // wheel steps (per rail step)
  // Sub-steps per wheel step (docs/physics-reference.md §8.12): each with its own kinematics and wear on the profile
  // the previous one left and a cap of cap_m / substeps, so a step still removes at most cap_m; 1: paper 003's update
  int substeps = 1;
  double total_km = 0.0;               // 0: unlimited; otherwise stop (and shorten the last step) at this distance
  double max_curvature_1_m = 1.0e3;    // validity check (ProfileValidityOptions)
  bool overhang_cut_conserves_area = true;  // ProfileUpdateOptions::cut_conserves_area (overhang_cut key)
};

struct ScenarioRail {
  bool fixed = true;        // the rail is not updated (default; paper 003 §7)
  int steps = 0;            // m rail steps (paper 003 Fig. 11) when not fixed
  double cap_m = 0.1e-3;    // RailStepOptions::max_depth_per_step_m
  // RailStepOptions::output_spacing_m (virtual and averaged rails), >= 0; 0 = the spacing of the rail before the
  // step. The refit of a profile on a uniform arc-length grid (natural cubic spline) misplaces the curve by
  // O(h^2 x curvature jump) between the nodes where the rail's curvature jumps (the arcs of a standard rail): at
  // 0.1 mm up to ~5e-8 m, at 0.05 mm ~3e-9 m (docs/physics-reference.md §8.8).
  double output_spacing_m = 0.0;
};

struct Scenario {
  std::string name;
  std::string source;  // file the scenario came from
  VehicleParameters vehicle;
  ScenarioKinematics kinematics;
  double gauge_m = 1.435;
  double rail_inclination_rad = 0.0;
  std::string wheel_name, rail_name;  // built-in name or file path, as given
  Profile wheel, rail;                // rail uninclined (mounted with rail_inclination_rad)
  Material material;
  double friction_coefficient = 0.3;
  // elastic_flange_deg: contact points steeper than this may interpenetrate at a wheel's reference position
  // (WheelContactOptions::max_touching_contact_angle_rad), in the curving solve and the wear step. Absent: rigid.
  double elastic_flange_angle_rad = 1e300;
  // load_tolerance: WheelContactOptions::load_tolerance of the curving and wear solves
  double load_tolerance = kDefaultLoadTolerance;
  // load_balance: WheelContactOptions::load_balance of the curving and wear solves (default total)
  LoadBalance load_balance = LoadBalance::Total;
  // kp_spin_about_centre, kp_local_flexibilities: WheelContactOptions::kp_spin_about_patch_centre,
  // kp_local_flexibilities of the curving and wear solves (default off, as there)
  bool kp_spin_about_patch_centre = WheelContactOptions{}.kp_spin_about_patch_centre;
  bool kp_local_flexibilities = WheelContactOptions{}.kp_local_flexibilities;
  double load_acceptance = 0.10;  // load_acceptance: StepWearOptions::load_acceptance
  WearModel wear;
  ContactModel model = ContactModel::Conformal;
  ScenarioUpdate update;
  ScenarioRail rail_steps;
  std::vector<TrackClass> classes;  // shares sum to 1
  PublishedStudy published;         // published: figures of a published study of the case (compare report only)
  void validate() const;            // InputError naming the field and the file
  // Track set-up of the scenario with the given wheel and (mounted or not) rails.
  TrackSetup MakeTrackSetup() const;
};

// Throws InputError "<file>: <what>" for unreadable/malformed files, unknown keys and bad values.
Scenario LoadScenario(const std::string& path);
// LoadScenario with overrides "key.path=value" (the commands' --set, src/simulation/scenario_overrides.cpp): each
// value is read as YAML (a scalar, or a flow map / list such as "{contact: lut, duration_s: 64}") and replaces the
// node at the dotted key path of the file (maps created where missing) before the scenario is read; the scenario's
// source names the overrides. InputError for an override without '=', an empty value or key part, or a path through
// a node that is not a map; unknown keys and bad values as in the file.
Scenario LoadScenario(const std::string& path, const std::vector<std::string>& overrides);
// The scenario's contact settings on `options` (material, elastic flange, load tolerance and balance, the KP FASTSIM
// variants): what the curving solve, the wear step and the curving command share. Model and load are not touched.
void ApplyScenarioContact(const Scenario& scenario, WheelContactOptions* options);
Scenario ParseScenario(const std::string& yaml_text, const std::string& source, const std::string& base_dir = ".");

}  // namespace conforma
