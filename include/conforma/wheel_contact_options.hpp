#pragma once
// The options of a contact solve (one wheel in the pipeline, wheel_contact.hpp, or one patch, patch_solver.hpp):
// declared once, with their defaults; every other options struct that needs them holds a WheelContactOptions.
#include <string>

#include "conforma/bem_reference.hpp"
#include "conforma/conformity.hpp"
#include "conforma/contact_candidates.hpp"
#include "conforma/contact_model.hpp"
#include "conforma/creepage.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/material.hpp"
#include "conforma/model_selection.hpp"

namespace conforma {

// The largest wheel load accepted (N): 10 MN is ~1,000 t on one wheel, 50 times the heaviest axle loads (~40 t per
// axle); above it the number is a unit mistake, and the load control's first push (Hertz, delta ~ N^(2/3)) would
// be astronomically large (a 1e308 N load kept the reference BEM busy for more than 300 s).
constexpr double kMaxWheelLoadN = 1e7;

// The largest given creepage accepted: |xi|, |eta| <= 1e3 (a relative slip of 100,000 %), |phi| <= 1e3 1/m (a wheel
// of 1 mm radius spinning about the contact normal). Beyond this nothing physical changes (full slip), and near
// 1e154 the squares of the creepages overflow: xi = 1e300 gave F_x = NaN, xi = 1e155 F_x = 0 (fuzzing, session 24).
constexpr double kMaxGivenCreepage = 1e3;
// The most FASTSIM elements per strip accepted (fastsim_elements): 10,000, ~300 times the default; 1e8 ran out of
// memory after 9 s.
constexpr int kMaxFastsimElements = 10000;
// The most KP strips across a patch accepted (kp_strips; KpOptions::strips_across_contact has the same bound).
constexpr int kMaxKpStrips = 100000;
// The largest push-down below rigid contact an entry point accepts in approach mode, m: an elastic approach is tens of
// micrometres; 15-100 mm went past the rail's tabulated head and came back as "no contact" (fuzzing, session 25).
constexpr double kMaxApproach_m = 10e-3;

// What load control balances against the load (docs/physics-reference.md §3.6.1).
//   Total:    the wheel's total vertical force, pressure AND creep forces of all patches (WheelContactReport::
//             vertical_force_N), as CONTACT, multibody codes and Nadal's criterion do: every load-control
//             evaluation solves the normal and the tangential problem at its push-down.
//   Pressure: the vertical component of the pressure forces alone (WheelContactReport::pressure_vertical_force_N),
//             the creep forces solved afterwards (the behaviour before issue 15; cheaper, wrong at a flange).
//   TotalConsistent: the total balance of Total with the contact candidates (interpenetration regions -> patches)
//             found for the load L the pressure forces carry at the solution (L = pressure_vertical_force_N, a fixed
//             point in L, §3.6.1 step 4) instead of for the wheel load Q: the patches are those of the wheel where it
//             actually stands, which at a flange with the creep force carrying part of the load lies far below the
//             Hertz push-down for Q; the solution is then the pressure-balanced solve at L (the contact look-up
//             table's node definition, §17.4) carrying Q in total. Costs one more candidate search and total
//             balance per fixed-point iteration (the hertz model, whose patches do not depend on the candidates'
//             load, is solved as with Total).
enum class LoadBalance { Total, Pressure, TotalConsistent };
// TotalConsistent: the fixed point stops at |P - L| <= max(load_tolerance, this) Q (§3.6.1 step 4). L enters the
// solution only through the candidates' Hertz push-down (delta ~ L^(2/3)): 1e-4 Q moves the candidates' pose by
// 7e-5 of the push-down (~10 nm at 0.1 mm), far below the 0.1 mm strips of the patches.
constexpr double kCandidateLoadTolerance = 1e-4;
const char* to_string(LoadBalance balance);             // "total", "pressure", "total-consistent"
LoadBalance ParseLoadBalance(const std::string& name);  // InputError for another name

// validate() throws InputError outside the ranges given below.
struct WheelContactOptions {
  ContactModel model = ContactModel::Hertz;  // contact model of every patch (auto: chosen per patch); default hertz
  Material material;                         // both bodies; default steel G = 82 GPa, nu = 0.28
  double friction_coefficient = 0.3;         // mu (-), >= 0, constant over the patch (with a constant friction_law)
  // Slip-dependent friction law mu(gamma) of every model's FASTSIM (friction_law.hpp, docs/physics-reference.md
  // §7.4). Kind Constant (default): friction_coefficient applies and these parameters are ignored; any other kind
  // replaces friction_coefficient (validated by FrictionLaw::validate).
  FrictionLaw friction_law;
  // N, finite, <= kMaxWheelLoadN. Load control (default, 10 kN): the wheel is pushed down until its vertical force
  // (load_balance: pressure and creep forces by default) carries this load; 0: unloaded wheel, no contact solved
  // (status NoContact). Set vertical_load_N < 0 to use the pose as given (approach mode, for multibody coupling).
  double vertical_load_N = 10e3;
  double load_tolerance = kDefaultLoadTolerance;  // relative (load_control.hpp), > 0; default 1e-6
  // FASTSIM elements per strip (and strips for the Hertz ellipse), >= 2; default 30
  int fastsim_elements = kDefaultFastsimElements;
  int kp_strips = kDefaultKpStrips;                  // strips across the contact of the KP solvers, >= 3; default 31
  // Reference / exact BEM (bem_reference.hpp): element size along x and along s of the grid built over the
  // interpenetration region of each patch, m, > 0; default 0.2 mm (CONTACT's usual grid)
  double exact_element_size_m = kDefaultBemElementSizeM;
  // Reference / exact BEM memory budget: the largest grid (elements) of one patch, >= 1; default 250,000 (~300 MB).
  // A larger grid is an InputError naming the grid, this budget and exact_element_size_m.
  long exact_max_elements = kDefaultBemMaxElements;
  // Strip width ds of the candidate patches (PatchGeometry::ds_m, contact_candidates.hpp), m, > 0; default 0.1 mm
  double candidate_strip_width_m = 0.1e-3;
  // Patch grouping (CandidateOptions::combine_distance_m, contact_candidates.hpp): interpenetration regions closer
  // than this along the rail profile are solved as one curved patch; 0 keeps them separate. m, >= 0; default 4 mm
  // (CONTACT's D_COMB).
  double patch_combine_distance_m = kDefaultCombineDistanceM;
  // Load control, elastic flange: the wheel's reference (touching) position ignores gap minima whose rail
  // contact angle exceeds this, so a flange pressed against the rail interpenetrates and carries its force
  // elastically instead of lifting the wheel rigidly onto it (a worn, steep flange acts as a wall that the
  // rigid model can only pass by climbing). Default: every contact point counts (rigid flange).
  double max_touching_contact_angle_rad = 1e300;  // rad
  // deg, finite; default 18: sets PatchReport::is_conformal (alpha_c_deg above it) of the KP and reference models
  double conformity_threshold_deg = kConformityThresholdDeg;
  // `conformal` model: virtual-penetration rule. true (default): CONTACT's variable eps (ConformalKpecOptions);
  // false: Kik-Piotrowski's constant eps = 0.55 (ConformalKpOptions). See kik_piotrowski.hpp.
  bool conformal_variable_penetration = true;
  // kp, kpec, conformal: FASTSIM variants on the KP patch (curved_fastsim.hpp, docs/physics-reference.md §5.4), both
  // off by default (Kalker's three flexibilities of the SDEC, spin about the patch reference point):
  // spin about the patch centre (CurvedFastsimOptions::spin_about_patch_centre) and strip-wise flexibilities from the
  // local half-length (CurvedFastsimOptions::local_flexibilities)
  bool kp_spin_about_patch_centre = false;
  bool kp_local_flexibilities = false;
  // `auto` model: thresholds of the per-patch choice (model_selection.hpp; its conformity threshold, 17.7 deg by
  // default, is separate from conformity_threshold_deg, which only sets the KP models' is_conformal flag).
  ModelSelectionOptions auto_selection;
  bool solve_tangential = true;        // false: normal problem only
  bool keep_fields = false;            // fill PatchReport::cells (pressure, traction, slip per element)
  // bound and blend_flexibilities: hertz model only; marching: every model's FASTSIM
  FastsimOptions fastsim;
  // When set, these creepages are used at every patch instead of the wheelset kinematics (then no per-strip rigid
  // slip for the conformal model, and the velocity's forward speed need not be > 0).
  bool creepages_given = false;
  Creepages creepages;                 // xi, eta (-), phi (1/m); finite, |.| <= kMaxGivenCreepage; read only with creepages_given
  // Load control: what is balanced against vertical_load_N (see LoadBalance); default total. With Total or
  // TotalConsistent (and solve_tangential) the normal problem depends on the velocity and the tangential options too.
  LoadBalance load_balance = LoadBalance::Total;
  void validate() const;  // InputError naming the option
  // The law every FASTSIM uses: friction_law, or Constant(friction_coefficient) when friction_law is constant.
  FrictionLaw effective_friction_law() const;
};

}  // namespace conforma
