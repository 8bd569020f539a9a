#pragma once
// Contact look-up table (LUT) of one wheel-rail pair (after paper 004, Santamaria et al. 2009: tabulated elastic
// multi-patch contact for dynamics; docs/architecture.md "Contact look-up table", interpolation and creep forces in
// docs/physics-reference.md §17).
//
// TABLE: per wheel side, a grid over the wheelset lateral shift y, yaw psi and the wheel's vertical load Q. At each
// node the wheelset's vertical position and roll are those of the rigid two-rail equilibrium at (y, psi), exactly
// as the quasi-static curving evaluates a wheelset (kinematics_quasistatic.hpp), and SolveWheelContact solves the
// wheel in load control with the PRESSURE balance (the normal solution is then independent of the velocity). Each
// node keeps every patch of that normal solution, ordered along the rail (gauge side first), and what the creep
// forces need at any velocity: the affine map from the wheelset velocities to the reference creepages (the
// pipeline's own creepages at four velocities, LutPatch::creepage_map), and for the KP models the patch itself on
// kLutStations lateral stations (a one-lobe patch's strips) with the affine map of each strip's rigid slip
// (LutPatch::stations).
//
// EVALUATION (EvaluateContactLut, MakeLutContactFunction): inside a grid cell whose eight corner nodes have one
// patch topology (same status, patch count, model per patch, each patch within match_distance_m along the rail of
// its partner) every patch field is interpolated tri-linearly, the load-dependent fields normalised by their
// Hertzian power of Q (forces / Q; lengths and pressures / Q^(1/3); area, approach / Q^(2/3)). Where the topology
// changes inside a cell whose corners are all Ok, the corners' patches are matched into PATCH TRACKS (same model,
// reference points within match_distance_m along the rail): a patch missing at a corner enters there with zero
// force (normal force, pressures, area, semi-axes, strip lengths), its geometry averaged over the corners that have
// it. A flange patch that appears, or a tread contact point that moves elsewhere, then changes the forces
// continuously across the cell, as the elastic contact does (a total-force balance has a root; the dynamics'
// integrator meets no force jump); two patches are never averaged into one. In a cell with a corner that is not
// Ok the topology of the nearest corner node is taken and only the corners with that topology are interpolated
// (weights renormalised): the change is placed within one grid step. Creep forces are solved at evaluation time for the actual velocity: hertz patches
// by FASTSIM on the stored ellipse with the interpolated creepages (the pipeline's hertz tangential solve); KP
// patches (kp, kpec, conformal) by the curved-patch FASTSIM scheme on the interpolated stations with per-strip rigid
// slip and the SDEC flexibilities (with given creepages or a slip-dependent friction law: FASTSIM on the SDEC
// ellipse centred at the patch centroid). With the TOTAL load balance (the default) the effective load Q_eff of the
// pressure balance is found such that Q_eff + (vertical creep forces at Q_eff) = Q (secant): close to the push the
// direct solver's total balance finds on the tread; at a flange, where the vertical creep forces are large, the
// pipeline keeps the candidate regions of Q pressed deeper and the two differ (docs/physics-reference.md §17.4).
// The pose's vertical position and roll are NOT used (the table's are those of the rigid equilibrium at (y, psi));
// a query outside the table is an InputError naming the axis and value (never extrapolated).
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/progress.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

// The grid axes (each strictly increasing, at least 2 values, finite). Units: m, rad, N.
struct ContactLutGrid {
  std::vector<double> lateral_m;  // wheelset lateral shift y, m (+ towards the left rail)
  std::vector<double> yaw_rad;    // wheelset yaw psi, rad
  std::vector<double> load_N;     // vertical wheel load Q, N, > 0
  void validate() const;          // InputError naming the axis
  size_t nodes() const { return lateral_m.size() * yaw_rad.size() * load_N.size(); }
  // node index of (i_y, i_psi, i_Q): load fastest
  size_t index(size_t iy, size_t ipsi, size_t iq) const { return (iy * yaw_rad.size() + ipsi) * load_N.size() + iq; }
};

// Lateral stations of a KP patch in the table, and the values kept per station (LutPatch::stations). As many
// stations as the KP solver's default strips (kDefaultKpStrips): a one-lobe patch's stations are then its strips and
// the table's creep forces at a node are the direct solve's (docs/physics-reference.md §17.3; 12 stations left up to
// 6 % of mu Q at the flange root).
constexpr int kLutStations = kDefaultKpStrips, kLutStationFields = 16;

// Default match distance of a table's patches (ContactLutHeader::match_distance_m): two nodes' patches whose
// reference points lie farther apart along the rail are different patches, so a contact point that jumps by more
// is a topology change (patch tracks, docs/physics-reference.md §17.2), not a position to interpolate. 2 mm: on
// S1002 / 50E4 1:20 the tread contact jumps by 2.1-2.5 mm near y = 3.8 mm, which 3 mm interpolated across
// (rail y p99 0.10-0.11 mm at 1000 random poses instead of 0.03-0.05 mm, §17.5).
constexpr double kDefaultLutMatchDistance_m = 2e-3;

// One patch of a node's normal solution (PatchReport fields; lengths m, forces N, pressures Pa, angles rad).
struct LutPatch {
  int model = 0;                        // ContactModel that solved the patch (as int)
  double y_contact_rail_m = 0.0, z_contact_rail_m = 0.0;  // reference point in the mounted rail profile
  double rail_s_m = 0.0;                // arc length of the reference point on the mounted rail (patch matching)
  double y_contact_wheel_m = 0.0;       // wheel-profile y at the reference point
  double lead_m = 0.0;                  // longitudinal position of the reference point
  double contact_angle_rad = 0.0;       // + towards the gauge side
  double rolling_radius_m = 0.0;
  double fn_N = 0.0;                    // normal force along n0
  double pressure_vertical_N = 0.0, pressure_lateral_N = 0.0;  // pressure resultant, side frame z / eta
  double pmax_Pa = 0.0, area_m2 = 0.0, approach_m = 0.0;
  double width_m = 0.0, length_m = 0.0;
  double a_m = 0.0, b_m = 0.0;          // Hertz semi-axes or the SDEC (KP models): FASTSIM's ellipse
  // Centre of the ellipse relative to the patch's spin origin (the reference point; along x and along the rail
  // profile): the area centroid of the KP patch (0 for hertz, whose ellipse is centred at its point). FASTSIM
  // runs on the ellipse with the creepages moved to this centre, so that an asymmetric patch's spin couples into
  // the forces as on the KP patch.
  double centre_x_m = 0.0, centre_s_m = 0.0;
  double alpha_c_deg = 0.0, auto_alpha_c_deg = 0.0;
  // Rigid creepages (xi, eta, phi [1/m]) = creepage_map * (1, v_lat / V, yaw_rate / V, axle_rate / V): the
  // creepages of creepage.hpp are affine in these (v = V x + omega x r, omega linear in the rates); row-major 3 x 4,
  // taken from the pipeline's own creepages at four velocities.
  std::array<double, 12> creepage_map{};
  // KP models: the rigid slip field of the patch's FASTSIM (per strip with the conformal model) fitted over the
  // patch about the ellipse centre, sigma = s - centre_s, x' = x - centre_x:
  //   w_x = c0 + c1 sigma + c2 sigma^2,   w_s = c3 + c4 sigma + c5 sigma^2 + (c6 + c7 sigma) x'
  // with (c0 .. c7) = slip_map * (1, v_lat / V, yaw_rate / V, axle_rate / V) (row-major 8 x 4; the rigid slip is
  // affine in these). FASTSIM on the ellipse then runs strip by strip with this slip (0 for hertz).
  std::array<double, 32> slip_map{};
  // KP models: the patch itself, resampled on kLutStations equal lateral stations over [station_s_min,
  // station_s_max] (along the rail profile from the spin origin, m). Per station k, row k of kLutStationFields:
  //   0 half-length c (m; 0: no contact there), 1 strip centre x (m), 2 peak pressure of the strip's semi-ellipse
  //   along x (Pa), 3 rotation alpha of the local normal from the reference normal (rad),
  //   4..15 the strip's rigid slip (w_x, w_s at x = 0, dw_s/dx [1/m]) = 3 x 4 map * (1, v_lat/V, yaw_rate/V,
  //   axle_rate/V), row-major.
  // FASTSIM then runs strip by strip on this patch (the curved-patch FASTSIM of the pipeline on a resampled patch).
  double station_s_min_m = 0.0, station_s_max_m = 0.0;
  std::array<double, kLutStations * kLutStationFields> stations{};
};

// Node status: the WheelContactStatus of the direct solve (as int), or kLutNoEquilibrium.
constexpr int kLutNoEquilibrium = 3;

struct LutNode {
  int status = 0;                 // WheelContactStatus (0 ok, 1 no_contact, 2 not_converged) or kLutNoEquilibrium
  double vertical_m = 0.0;        // pose of the solution (pushed down by load control), m
  double roll_rad = 0.0;          // roll of the rigid equilibrium, rad
  std::vector<LutPatch> patches;  // along the rail, gauge side first
};

// What the table was made from (attributes of the file).
struct ContactLutHeader {
  std::string wheel_profile, rail_profile;  // names or file names
  std::string track;                        // free text: inclination, gauge, radius
  std::string conforma_version, conforma_commit;
  ContactModel model = ContactModel::Hertz;
  Material material;
  double max_touching_contact_angle_rad = 1e300;  // elastic flange (WheelContactOptions)
  int kp_strips = 31;
  double candidate_strip_width_m = 0.1e-3, patch_combine_distance_m = 4e-3;
  bool conformal_variable_penetration = true;
  double match_distance_m = kDefaultLutMatchDistance_m;  // patches farther apart along the rail are different patches
  // Geometry fingerprint, checked at evaluation against the geometry passed: rail origin eta per side, nominal radius
  std::array<double, 2> rail_origin_eta_m{}, nominal_radius_m{};
  // FNV-1a (64 bit, hex) of GeometryFingerprint (geometry.hpp: every profile sample and the mounting) of the geometry
  // the table was built for; empty in tables written before it was recorded (then not checked)
  std::string geometry_digest;
  double generation_s = 0.0;  // wall time of BuildContactLut, s
  int threads = 0;            // OpenMP threads used
};

struct ContactLut {
  ContactLutHeader header;
  ContactLutGrid grid;
  std::array<std::vector<LutNode>, 2> nodes;  // [Left, Right], grid.index order
};

// ContactLutHeader::geometry_digest of a geometry.
std::string ContactLutGeometryDigest(const WheelsetTrackGeometry& geometry);
// InputError when the table records a geometry digest and `geometry` is not the geometry it was built for (other
// wheel or rail profiles, gauge, flange-back distance, inclination or radii): a table read from a file and paired with
// a geometry is checked once with this (CLI lut eval / check, dynamics --lut, the C API's
// conforma_model_create_with_lut, Python's ContactLut.evaluate).
void CheckContactLutGeometry(const ContactLut& lut, const WheelsetTrackGeometry& geometry);
// The same check against a geometry's ContactLutGeometryDigest computed beforehand (a caller that evaluates one
// geometry against tables many times hashes it once).
void CheckContactLutGeometryDigest(const ContactLut& lut, const std::string& geometry_digest);

struct ContactLutBuildOptions {
  ContactLutGrid grid;  // the axes (ContactLutGrid::validate)
  // model, material, elastic flange, KP strips, candidate options of every node (the load, load balance,
  // creepages and tangential switches are set by the build)
  WheelContactOptions contact;
  std::string wheel_profile, rail_profile, track;  // for the header
  double match_distance_m = kDefaultLutMatchDistance_m;  // ContactLutHeader::match_distance_m, > 0
  int threads = 0;                                 // OpenMP threads, 0: the OpenMP default
  // progress (progress.hpp), one unit per node and side (2 x grid.nodes(), "node <k>"); empty: none
  ProgressFunction on_progress;
  void validate() const;
};

// Every node solved independently (OpenMP over nodes, written into its slot): the same table for any thread
// count. InputError for bad options.
ContactLut BuildContactLut(const WheelsetTrackGeometry& geometry, const ContactLutBuildOptions& options);

// How the evaluation solves each patch's creep forces.
enum class LutCreepForce {
  Fastsim,  // FASTSIM on the stored ellipse (hertz) or on the tabulated stations (KP models), as described above
  Polach,   // Polach's closed form on the stored (Hertz or SDEC) ellipse, polach_creep_force.hpp: for fast dynamics
};
const char* to_string(LutCreepForce law);  // "fastsim", "polach"
LutCreepForce ParseLutCreepForce(const std::string& text);  // InputError naming the valid values

// Evaluation switches (not part of the table).
struct LutEvaluationOptions {
  // Polach: every patch's creep forces from Polach's method on its ellipse, with the creepages moved to the
  // ellipse's centre as FASTSIM's are (needs a constant friction coefficient: InputError otherwise); the spin
  // moment is 0 and the adhesion / slip areas are not computed (0), frictional_power_W is V times Polach's creep
  // power per speed. Tens of times cheaper than FASTSIM's 30 x 30 elements (docs/physics-reference.md §17.3).
  LutCreepForce creep_force = LutCreepForce::Fastsim;
};

// The location of a query in the table (which cell, whether its corners share one topology).
struct LutCellInfo {
  bool single_topology = false;  // the 8 corners all Ok with one topology
  // the corners' topologies differ and are all Ok: interpolated by patch tracks, a patch with zero force where a
  // corner lacks it (header comment)
  bool union_topology = false;
  size_t iy = 0, ipsi = 0, iq = 0;  // lower corner of the cell
};

// One wheel from the table (contract of SolveWheelContact; see the header comment). InputError: query outside the
// table (axis and value named), options or geometry that do not match the table, non-positive load, bad velocity.
WheelContactReport EvaluateContactLut(const ContactLut& lut, const WheelsetTrackGeometry& geometry, Side side,
                                      const WheelsetPose& pose, const WheelsetVelocity& velocity,
                                      const WheelContactOptions& options, LutCellInfo* info = nullptr,
                                      const LutEvaluationOptions& evaluation = {});

// The same signature as WheelContactFunction (kinematics_quasistatic.hpp): usable by the curving and the dynamics.
using LutContactFunction = std::function<WheelContactReport(const WheelsetTrackGeometry&, Side, const WheelsetPose&,
                                                            const WheelsetVelocity&, const WheelContactOptions&)>;
LutContactFunction MakeLutContactFunction(std::shared_ptr<const ContactLut> lut, LutEvaluationOptions evaluation = {});

// The rigid two-rail equilibrium at (y, psi) from the table (what EvaluateWheelsetContactForces needs before the
// contact): the nodes' roll interpolated bilinearly in (y, psi) (the rigid equilibrium does not depend on the load);
// vertical_m is the nodes' pose at the table's lowest load (pushed down by that load, not the rigid one: the
// table's contact does not use it). As the contact's interpolation, the nearest corner decides: NotConverged when
// the nearest corner node has no equilibrium (kLutNoEquilibrium), else Converged over the corners with one.
// InputError outside the table. Cost: a few nanoseconds, against tens of microseconds for the rigid solve.
EquilibriumResult EvaluateLutRigidPose(const ContactLut& lut, double y_m, double psi_rad);

// The same signature as RigidPoseFunction (wheelset_forces.hpp); InputError when the equilibrium options' elastic
// flange angle is not the table's.
using LutPoseFunction =
    std::function<EquilibriumResult(const WheelsetTrackGeometry&, double y_m, double psi_rad, const EquilibriumOptions&)>;
LutPoseFunction MakeLutPoseFunction(std::shared_ptr<const ContactLut> lut);

}  // namespace conforma
