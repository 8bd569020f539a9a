#pragma once
// The `dynamic` kinematics provider with a contact look-up table (`kinematics.dynamic.contact: lut`;
// docs/physics-reference.md §16.7): at every wheel step the table of the current wheel/rail geometry is built in
// memory (BuildContactLut, contact_lut.hpp) with the curving contact model and the contact options of the direct
// provider, and each class runs with the table's contact forces (MakeLutContactFunction, creep forces by
// `lut_creep`: Polach's closed form or FASTSIM) and the table's rigid equilibrium (MakeLutPoseFunction).
//
// GRID (DynamicKinematicsLutGrid): the default grid of `conforma lut build` (contact_lut_grid.hpp) extended
// outward where the scenario needs more: |y| up to the larger flange-contact shift of the two wheels
// (FlangeContactShift) + 3 mm (elastic flange penetration and dynamic overshoot); |psi| up to a |c|max + 8 mrad (a
// rigid bogie's wheelset yaw against the radial position, a = half the wheelbase, plus the yaw of the track
// irregularity); loads from Q_min / 2 to 3/2 Q_max, where Q_min, Q_max are the classes' quasi-static wheel loads
// Q0 -/+ m |a_nc| h / (2 b0) (the model's load transfer): the effective load of the total-force balance differs
// from Q by up to +/- 50 % at a flange (§17.4).
//
// A QUERY THE TABLE REFUSES (outside the grid, InputError of the evaluation; or a report with a non-finite force,
// position or angle of a patch) is never used: the contact / pose function records it and answers "not converged"
// (the integrator rejects the step), and the class then FAILS with
// the first refusal named (DynamicClassKinematics::failure), even when the integrator recovered with a smaller
// step. The provider first widens the table where the refusals were outside its lateral or yaw axis
// (SimulateClassKinematicsCoveringLut); a class that still fails falls back as for any failure (steps.csv
// kinematics_fallbacks).
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "conforma/contact_lut.hpp"
#include "conforma/dynamic_kinematics.hpp"

namespace conforma {

// The grid described above for the geometry and the scenario's classes, vehicle and kinematics options (model:
// the curving contact model). InputError for bad input.
ContactLutGrid DynamicKinematicsLutGrid(const Scenario& scenario, const WheelsetTrackGeometry& geometry, ContactModel model);

// The table of the geometry on that grid: BuildContactLut with the curving contact options
// (ScenarioQuasiStaticOptions(scenario, model).contact), OpenMP threads as the caller's (inside the wear loop's
// parallel region: one). header.generation_s holds the build's wall time.
std::shared_ptr<const ContactLut> BuildDynamicKinematicsLut(const Scenario& scenario, const WheelsetTrackGeometry& geometry,
                                                            ContactModel model);

// The same table on a given grid (a widened one, SimulateClassKinematicsCoveringLut).
std::shared_ptr<const ContactLut> BuildDynamicKinematicsLutOnGrid(const Scenario& scenario,
                                                                  const WheelsetTrackGeometry& geometry,
                                                                  ContactModel model, const ContactLutGrid& grid);

// One class with the table (SimulateClassKinematics with the table's contact and rigid pose, creep forces by the
// scenario's kinematics.dynamic.lut_creep). A refused query makes `failure` non-empty (see above).
DynamicClassKinematics SimulateClassKinematicsWithLut(const Scenario& scenario, const WheelsetTrackGeometry& geometry,
                                                      const TrackClass& track_class, ContactModel model,
                                                      std::shared_ptr<const ContactLut> table);

// The provider's run of a class (docs/physics-reference.md §16.7, "widening"): SimulateClassKinematicsWithLut, and
// when its only refusals were queries outside the table's lateral or yaw axis (a long window's irregularity or a
// curve can take a wheelset beyond the grid above), a table on the grid widened to cover them (the largest refused
// |y| + 1 mm, |psi| + 4 mrad, the axes' end spacing continued: CoverContactLutGrid) is built for this class alone
// and the class run again on it, at most kMaxLutWidenings times. A class still refused fails as above, the
// widenings named in `failure`; a widened run names its grid in series.source. Deterministic: a class's widening
// depends only on its own run (the other classes keep the wheel step's table). `last_table` (optional): the table
// of the returned run (the widened one, if any), for a rerun of the class (MakeDynamicKinematics' stepper rerun)
// that should not widen again.
constexpr int kMaxLutWidenings = 2;
constexpr double kLutWideningLateralMarginM = 1e-3;
constexpr double kLutWideningYawMarginRad = 4e-3;
DynamicClassKinematics SimulateClassKinematicsCoveringLut(const Scenario& scenario,
                                                          const WheelsetTrackGeometry& geometry,
                                                          const TrackClass& track_class, ContactModel model,
                                                          std::shared_ptr<const ContactLut> table,
                                                          std::shared_ptr<const ContactLut>* last_table = nullptr);

// The table of a run's current wheel step: built on the first request for a geometry whose profiles (wheel and
// rail samples of both sides, nominal radii, inclination) differ from the last one's, while the other classes'
// requests wait; thread-safe. `built` (optional): true when this call built it.
class DynamicKinematicsLutCache {
 public:
  std::shared_ptr<const ContactLut> get(const Scenario& scenario, const WheelsetTrackGeometry& geometry,
                                        ContactModel model, bool* built = nullptr);

 private:
  std::mutex mutex_;
  std::vector<double> key_;
  std::shared_ptr<const ContactLut> table_;
};

}  // namespace conforma
