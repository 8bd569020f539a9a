#pragma once
// The wear loop (paper 003 §§5-6 and Fig. 11, paper 001 §§6-7; docs/physics-reference.md §8.3):
//
//   for each rail step k (one, with the rail fixed -- paper 003 §7 -- the default):
//     wheel w = w_0
//     for each wheel step j:
//       geometry of (w, r_k)                                          (rebuilt: it precomputes from the profiles)
//       for each track class c (weight p_c):   kinematics samples of every wheelset (quasi-static or imported)
//         for each sample and each wheel:      SolveWheelContact(keep_fields) -> cells (p, p_t, slip, area, dx)
//                                              -> WearPatch (cells with zero slip are skipped: no wear)
//         IntegrateTrackClass per side (left wheels / right wheels, their rails)
//       CombineTrackClasses with the shares p_c; the wheel depth per metre is the mean of the two sides
//       (every wheel of the vehicle is one sample of "the" wheel profile, like a fleet average)
//       UpdateProfile(w, depth per metre, 1 m, cap)  -> w_{j+1}, the km of the step, Sd/Sh/qR
//     rails r_{k+1} = UpdateRail(r_k, rail depth per passage of each w_j, weights = km of step j)
//
// Determinism: samples are evaluated in parallel (OpenMP) into per-sample slots and summed sequentially in a
// fixed order, so the result does not depend on the number of threads.
#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <functional>
#include <string>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/kinematics.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/profile_update.hpp"
#include "conforma/rail_update.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_distribution.hpp"
#include "conforma/wheel_contact.hpp"
#include "conforma/wheel_dimensions.hpp"

namespace conforma {

using WearContactFunction = std::function<WheelContactReport(const WheelsetTrackGeometry&, Side, const WheelsetPose&,
                                                             const WheelsetVelocity&, const WheelContactOptions&)>;
// Kinematics of one track class on the current geometry (class index into Scenario::classes).
using KinematicsFunction =
    std::function<KinematicsSeries(const WheelsetTrackGeometry&, const TrackClass&, int class_index)>;

// ---------------------------------------------------------------- one step's wear
struct StepWearOptions {
  // model, material, discretisation; keep_fields, solve_tangential, load and friction are set per call
  WheelContactOptions contact;
  WearModel wear;                  // wheel and rail wear laws (wear_distribution.hpp)
  double grid_spacing_m = 0.1e-3;  // m, > 0: wear grids on the wheel and rail arc lengths
  // A wheel whose load control ended NotConverged is used when its carried vertical load (the balanced force: the
  // total vertical force, or the pressure forces with load_balance pressure) is within this fraction of the target
  // (otherwise it is a failed contact, without wear). Dimensionless, >= 0, default 10 % (scenario load_acceptance).
  double load_acceptance = 0.10;
  // A wheel whose load control finds no bracket with the chosen model (NotConverged without patches; seen with the
  // kp/conformal models at flange contact on worn profiles) is solved with the Hertz model instead (counted).
  bool hertz_fallback = true;
};

// The wear of one step. Depths in m: the wheel's per metre run (m/m), the rail's per passage.
struct StepWear {
  // combined over the classes; wheel depth per metre = mean of the sides; its rail depth is the left side's, its
  // distance and area outside the sums of the two sides
  TrackClassWear wheel;
  std::array<TrackClassWear, 2> side;      // [Left, Right] combined over the classes (rail: per passage)
  std::vector<std::array<TrackClassWear, 2>> per_class;  // [class][Left, Right], before the combination
  int samples = 0;                         // wheel contacts whose wear was used (loaded wheels, Ok or approximate)
  int failed_contacts = 0;                 // NoContact / NotConverged wheels (no wear taken from them)
  int approximate_contacts = 0;            // NotConverged wheels within load_acceptance (used)
  int hertz_fallback_contacts = 0;         // wheels solved with the Hertz model instead (hertz_fallback)
  // patches of the used wheel contacts; cells passed to the wear laws (cells that remove exactly nothing, e.g. in
  // adhesion, and cells off the wheel grid are left out)
  int patches = 0, slipping_cells = 0;
  // Patches of the wear samples by the model that solved them (PatchReport::model; with `auto` the chosen one,
  // with the Hertz fallback hertz), indexed by static_cast<int>(ContactModel).
  std::array<int, kContactModelCount> patches_by_model{};
  double wheel_area_off_grid_m2 = 0.0;     // m^2, cells that could not be mapped to the wheel arc length
};

// The wear computation's view of a solved contact cell, at wheel-profile arc length wheel_s_m.
WearCell WearCellOf(const ContactCell& cell, double wheel_s_m);

// series[c] are the samples of class c (weights of a wheelset within a class sum to 1). Throws InputError for
// inconsistent input; contact failures are counted.
StepWear ComputeStepWear(const WheelsetTrackGeometry& geometry, const std::vector<TrackClass>& classes,
                         const std::vector<KinematicsSeries>& series, const StepWearOptions& options,
                         const WearContactFunction& contact);

// ---------------------------------------------------------------- kinematics providers of a scenario
// Centred wheelsets: y = 0, psi = 0 at the rigid equilibrium, yaw rate V/R, axle speed V/r0, static wheel loads.
KinematicsSeries CentredKinematics(const Scenario& scenario, const WheelsetTrackGeometry& geometry,
                                   const TrackClass& track_class);
// Kinematic curving estimate (no force equilibrium; the fallback of the quasi-static provider): on a curve every
// bogie is a rigid frame on the chord, so both wheelsets are parallel to it: the leading wheelset has the angle of
// attack psi = -a c (towards the outer rail) and runs at flange contact (the smallest |y| towards the outer rail
// at which the outer wheel's rigid contact angle exceeds 0.5 rad); the trailing wheelset (psi = +a c) sits where
// the rolling radius difference gives pure rolling, r_L - r_R = -2 b0 r0 c (clipped at flange contact). On tangent
// track: the centred wheelset plus the Klingel oscillation of amplitude tangent_amplitude_m (as the quasi-static
// provider). Loads: static wheel load -/+ m a_nc h / (2 b0) on the inner/outer wheel. One bogie (two wheelsets).
KinematicsSeries KinematicCurvingEstimate(const Scenario& scenario, const WheelsetTrackGeometry& geometry,
                                          const TrackClass& track_class);
// Options of the scenario's quasi-static curving solve with `model` in the loop (tangent-track samples, cant base,
// axle rotation from the scenario's kinematics).
QuasiStaticOptions ScenarioQuasiStaticOptions(const Scenario& scenario, ContactModel model);
// The contact model of the curving solve: the scenario's kinematics.contact_model if set, else the wear model.
inline ContactModel CurvingContactModel(const Scenario& scenario, ContactModel wear_model) {
  return scenario.kinematics.contact_model_set ? scenario.kinematics.contact_model : wear_model;
}
// The scenario's provider. Quasi-static: a class whose solution is NoContact, derailed (a wheelset beyond flange
// contact + derailment margin, kinematics_quasistatic.hpp), climbing its flange, with a tangent-track sample
// whose axle torque balance failed, or NotConverged with a residual above kAcceptedCurvingResidual, falls back
// to the last accepted solution of the same class (from an earlier wear step of this function: the kinematics
// frozen over a step, as a multibody code updated every few steps would give), or to KinematicCurvingEstimate
// when there is none; `fallbacks` (optional, thread-safe) records each such class with the reason. The
// function keeps that per-class memory: one function per run.
constexpr double kAcceptedCurvingResidual = 0.05;  // max |scaled residual| (forces / Q0) of an accepted solve
// Why the provider rejects a quasi-static solve, in words ("" when it accepts it), e.g. "bogie 0 not converged:
// max residual 0.338 (ws1 lateral) > 0.05".
std::string QuasiStaticRejection(const QuasiStaticResult& result);
// Classes whose quasi-static solve was replaced, with the reason (thread-safe; entries in the order recorded).
class KinematicsFallbackLog {
 public:
  struct Entry {
    int class_index = 0;
    std::string class_name;
    std::string reason;       // QuasiStaticRejection
    std::string replacement;  // "previous solution" or "kinematic estimate"
  };
  void add(Entry entry);
  size_t size() const;
  std::vector<Entry> since(size_t first) const;  // entries [first, size()), sorted by class index
  // "R200: bogie 0 not converged: ...; used the kinematic estimate"
  static std::string describe(const Entry& entry);

 private:
  mutable std::mutex mutex_;
  std::vector<Entry> entries_;
};
// The `dynamic` provider is not made here (it lives in the dynamics layer): InputError naming
// WearSimulationOptions::kinematics_factory.
KinematicsFunction MakeScenarioKinematics(const Scenario& scenario, ContactModel model, const WearContactFunction& contact,
                                          std::shared_ptr<KinematicsFallbackLog> fallbacks = nullptr);

// ---------------------------------------------------------------- the whole run
struct WearSimulationOptions {
  WearSimulationOptions() { contact.model = ContactModel::Conformal; }
  // The contact solve of every sample: model (default conformal) and discretisation (fastsim_elements, kp_strips,
  // candidate_strip_width_m, ...). Set per call by the loop from the scenario: material, friction, vertical load,
  // elastic flange (max_touching_contact_angle_rad), keep_fields.
  WheelContactOptions contact;
  int steps = -1;                    // wheel steps per rail step; < 0: the scenario's (InputError when it ends < 1)
  double total_km = -1.0;            // km run per rail step; < 0: the scenario's (0 = unlimited: `steps` steps)
  double grid_spacing_m = 0.1e-3;    // m, > 0: wear grids on the wheel and rail arc lengths (StepWearOptions)
  // The accumulated wheel depth is tapered to zero (raised cosine) over this length at both ends of the wheel
  // profile before the update: at the very end of the profile (field-side edge, flange back) the removal along
  // the normal has no neighbour on one side and a worn edge turns into a kink that fails the validity check.
  // 0 disables the taper.
  double edge_taper_m = 3e-3;        // m, default 3 mm
  // Adaptive step (paper 001 §6.2: "the km_step can be variable and controlled by an adaptive procedure"): when
  // the updated wheel profile fails the validity check (a fold where the flange face is steep, a kink), the step
  // is repeated with half the depth cap, up to this many times (cap / 2^n). The same wear distribution is used:
  // only the distance the step represents shrinks. 0: stop at the first invalid profile.
  int invalid_step_halvings = 3;     // >= 0
  // Called after every wheel step (progress display, streaming output); may be empty.
  std::function<void(const struct WearStepRecord&)> on_step;
  // Makes the run's kinematics provider (when RunWearSimulation gets no KinematicsFunction) from the scenario, the
  // contact model of the curving solve (CurvingContactModel), the wear contact function and the run's fallback
  // log (its entries become steps.csv kinematics_fallbacks). Empty: MakeScenarioKinematics. The `dynamic`
  // provider lives in the dynamics layer above this one and comes in here (dynamic_kinematics.hpp
  // MakeWearKinematics).
  std::function<KinematicsFunction(const Scenario&, ContactModel, const WearContactFunction&,
                                   std::shared_ptr<KinematicsFallbackLog>)>
      kinematics_factory;
};

// One completed wheel step (a step whose profile update fails ends the run without a record).
struct WearStepRecord {
  int rail_step = 0;                 // k, 0-based
  int step = 0;                      // j, 1-based within the rail step
  double km = 0.0;                   // cumulative within the rail step, km
  double step_km = 0.0;              // distance the step represents, km
  double max_depth_m = 0.0;          // of the removed depth, m (= cap unless the last step was shortened)
  WheelDimensions dimensions;        // of the new profile
  double tread_wear_m = 0.0, flange_wear_m = 0.0;  // m, against the scenario's initial wheel; see WheelWearDepths
  int tread_hollows = 0;              // separate hollows of the tread (WheelWearDepths::tread_hollows)
  double wall_s = 0.0;               // wall-clock time of the step, s (not reproducible)
  Profile wheel;                     // the new wheel profile
  // raw (unsmoothed, before the edge taper) wheel wear rate of the step [m/m]
  WearDistribution wheel_depth_per_metre;
  WearDistribution removed_depth;           // smoothed, scaled depth removed [m]
  std::array<WearDistribution, 2> rail_depth_per_passage;  // [Left, Right], m per passage
  ProfileValidity validity;          // of the new profile (after any halvings)
  // the StepWear counters of the step
  int samples = 0, failed_contacts = 0, approximate_contacts = 0, hertz_fallback_contacts = 0;
  int kinematics_fallbacks = 0;      // classes where the quasi-static solution was replaced (see above)
  std::vector<std::string> kinematics_fallback_reasons;  // one per such class (KinematicsFallbackLog::describe)
  double depth_cap_m = 0.0;          // cap used, m (the scenario's, or halved by invalid_step_halvings)
  double overhang_cut_area_m2 = 0.0; // m^2, area cut from a flange worn past vertical (ProfileUpdateResult)
  // the overhang cut's area conservation (ProfileUpdateResult::cut_area_scale, cut_area_conserved): the factor on the
  // removed depth around the cut (1: no cut, or update.overhang_cut wear_off), and whether it balanced the areas
  double cut_area_scale = 1.0;
  bool cut_area_conserved = true;
  std::array<int, kContactModelCount> patches_by_model{};  // see StepWear
};

// Completed: every step ran (or total_km was reached). InvalidProfile: a wheel update stayed invalid after the
// halvings, or a rail update was invalid (the run stops there). NoWear: a wheel step removed nothing (the run stops).
enum class WearSimulationStatus { Completed, InvalidProfile, NoWear };
const char* to_string(WearSimulationStatus status);  // "completed", "invalid_profile", "no_wear"

struct WearSimulationResult {
  WearSimulationStatus status = WearSimulationStatus::Completed;  // see WearSimulationStatus
  std::string message;                                // "" when Completed; else "rail step k, wheel step j: ..."
  Profile initial_wheel;                              // the scenario's wheel
  WheelDimensions initial_dimensions;                 // Sd/Sh/qR of initial_wheel
  std::array<Profile, 2> initial_rail;               // mounted [Left, Right]
  std::vector<WearStepRecord> steps;                  // every completed wheel step, rail step after rail step
  std::vector<std::array<Profile, 2>> rails;          // r_1 .. r_m (empty with a fixed rail)
  std::vector<RailStepResult> rail_results;           // per rail step [Left, Right] in turn (empty with a fixed rail)
};

// Largest wear depth of `worn` relative to `initial`, measured along the initial profile's normals, over the
// tread (wheel-profile y > flange_root_y) and over the flange (y <= flange_root_y). flange_root_y = -25 mm
// (S1002: the flange root lies between y = -26 and -20 mm).
struct WheelWearDepths {
  double tread_m = 0.0, flange_m = 0.0;  // largest depth (>= 0, m) over the tread / the flange; 0: no wear there
  // Separate hollows of the tread: local maxima of the depth across the tread (y > flange root) whose topographic
  // prominence (height above the higher of the lowest depths between it and a deeper point on either side, or the
  // tread's ends) is at least max(20 um, 10 % of tread_m). A measured worn tread has one; grooves left by a few
  // sampled contact positions show as several (issue 16, item 5). 0: no tread wear.
  int tread_hollows = 0;
};
WheelWearDepths MeasureWheelWear(const Profile& initial, const Profile& worn, double flange_root_y_m = -0.025);

// Throws InputError for a contact model that cannot drive the wear loop (reference: normal problem only, no
// creep forces, no wear; IsWearContactModel) and for a depth smoothing the profile update cannot apply.
WearSimulationResult RunWearSimulation(const Scenario& scenario, const WearSimulationOptions& options,
                                       const WearContactFunction& contact, const KinematicsFunction& kinematics = {});
// Whether `model` solves the tangential problem the wear laws need (every model but reference).
bool IsWearContactModel(ContactModel model);
// The models IsWearContactModel accepts, comma-separated ("hertz, kp, kpec, conformal, auto").
std::string WearContactModelNames();
// Wheel contacts of the run that gave no wear (WearStepRecord::failed_contacts summed over the steps).
int LostContacts(const WearSimulationResult& result);
// What is missing from the run's result, "" when it is complete: a status other than Completed (the run stopped
// early, message), or wheel contacts lost in some steps (their count and steps).
std::string IncompleteReason(const WearSimulationResult& result);
// With the standard pipeline. Inline so that the core library does not depend on the pipeline library.
inline WearSimulationResult RunWearSimulation(const Scenario& scenario, const WearSimulationOptions& options) {
  return RunWearSimulation(scenario, options, &SolveWheelContact);
}

}  // namespace conforma
