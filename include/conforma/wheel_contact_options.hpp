#pragma once
// The options of a contact solve (one wheel in the pipeline, wheel_contact.hpp, or one patch, patch_solver.hpp):
// declared once, with their defaults; every other options struct that needs them holds a WheelContactOptions.
#include "conforma/bem_reference.hpp"
#include "conforma/conformity.hpp"
#include "conforma/contact_model.hpp"
#include "conforma/creepage.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/material.hpp"
#include "conforma/model_selection.hpp"

namespace conforma {

struct WheelContactOptions {
  ContactModel model = ContactModel::Hertz;
  Material material;
  double friction_coefficient = 0.3;
  // Load control (default): the wheel is pushed down until the vertical components of its patch forces carry
  // this load. Set vertical_load_N < 0 to use the pose as given (approach mode, for multibody coupling).
  double vertical_load_N = 10e3;
  double load_tolerance = kDefaultLoadTolerance;  // relative (load_control.hpp)
  int fastsim_elements = kDefaultFastsimElements;           // FASTSIM elements per strip (and strips for the Hertz ellipse)
  int kp_strips = kDefaultKpStrips;                  // strips across the contact of the KP solvers
  int bem_x_elements = kDefaultBemXElements;             // reference BEM elements along x (strips: the candidate's ds)
  double candidate_strip_width_m = 0.1e-3;
  // Load control, elastic flange: the wheel's reference (touching) position ignores gap minima whose rail
  // contact angle exceeds this, so a flange pressed against the rail interpenetrates and carries its force
  // elastically instead of lifting the wheel rigidly onto it (a worn, steep flange acts as a wall that the
  // rigid model can only pass by climbing). Default: every contact point counts (rigid flange).
  double max_touching_contact_angle_rad = 1e300;
  double conformity_threshold_deg = kConformityThresholdDeg;
  // `conformal` model: virtual-penetration rule. true (default): CONTACT's variable eps (ConformalKpecOptions);
  // false: Kik-Piotrowski's constant eps = 0.55 (ConformalKpOptions). See kik_piotrowski.hpp.
  bool conformal_variable_penetration = true;
  // `auto` model: thresholds of the per-patch choice (model_selection.hpp; its conformity threshold, 17.7 deg by
  // default, is separate from conformity_threshold_deg, which only sets the KP models' is_conformal flag).
  ModelSelectionOptions auto_selection;
  bool solve_tangential = true;        // false: normal problem only
  bool keep_fields = false;            // fill PatchReport::cells (pressure, traction, slip per element)
  FastsimOptions fastsim;              // bound and marching (hertz model)
  // When set, these creepages are used at every patch instead of the wheelset kinematics.
  bool creepages_given = false;
  Creepages creepages;
  void validate() const;  // InputError naming the option
};

}  // namespace conforma
