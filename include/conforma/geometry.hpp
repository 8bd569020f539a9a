#pragma once
// Wheel-rail contact geometry of a wheelset on straight track: frames, track set-up, wheelset pose, rigid
// contact search with yaw and roll, and the rigid two-rail equilibrium (z, roll) used for Delta r(y).
//
// FRAMES (tested against the Manchester reference in tests/test_manchester_geometry.cpp)
//   Track frame (right-handed): x along the track in the rolling direction, y lateral positive towards the
//     LEFT rail, z up. The top of the rails (highest point of each mounted rail) is at z = 0.
//   Side frame of wheel/rail `side` (Left, Right): (x, eta, z) with eta = sigma * y, sigma = +1 (left),
//     -1 (right): eta points to the FIELD side of that rail for both sides. Profiles are stored in the
//     right-side convention of profile.hpp (y towards the field side), so in the side frame a rail profile
//     point (y_r, z_r) sits at eta = rail_origin_eta + y_r, z = z_r, and both sides are handled by the same
//     code. The left side is the mirror image (left-handed for the left rail, as CONTACT reports it).
//   Wheelset pose: lateral shift y (+ towards the left rail), vertical position z of the axle centre
//     above (rail-top level + mean nominal radius), roll phi about +x (+ raises the LEFT wheel), yaw psi
//     about +z (+ turns the heading towards the left: the left wheel moves backwards, -b sin psi).
//     The rotation is R = Rz(psi) Rx(phi); in the side frame of side sigma it is Rz(sigma psi) Rx(sigma phi).
//   Wheel placement: flange back at wheel-profile y = flange_back_position (S1002: -70 mm) and the two flange
//     backs flange_back_distance apart, so the wheel-profile origin (taping line) is at body eta
//     b = flange_back_distance / 2 - flange_back_position (750 mm for 1360 / -70 mm).
//   Rail placement: each rail is mounted with its inclination (cant towards the track centre, applied to the
//     uninclined profile; 0 when the file is already canted), re-referenced to its highest point, and placed
//     so that the gauge-side point gauge_height below the top is at eta = gauge / 2.
//   Contact angle delta: angle of the outward RAIL normal from the track vertical, POSITIVE when the normal
//     leans towards the track centre (gauge side): flange contact about +1.1 rad. CONTACT's delta_cp for the
//     left rail (its left-handed frame) has the opposite sign: delta_cp = -delta.
//   Lead: longitudinal position (track x, + ahead) of a contact point relative to the vertical diametral
//     plane of its wheel, r (R00 sin(theta) - R02 cos(theta)); for yaw alone r cos(psi) sin(theta).
//
// RIGID CONTACT SEARCH (paper 001 eqs. 4-6): the wheel surface point whose outward normal has no component
// along the track x axis lies on the wheel's silhouette seen along x. For a wheel-profile point (y_w, r, r')
// its angle theta about the axle solves R00 sin(theta) - R02 cos(theta) = R01 r' (closed form); for yaw
// alone sin(theta) = -tan(psi) r'. The silhouette points form a plane curve in the side frame (eta, z) and,
// the rail being a prism along x, wheel and rail touch where this curve touches the rail profile. Candidates
// are the local minima of the vertical separation (found on a coarse scan and refined by Brent's method),
// each then refined to the minimum of the gap along the local rail normal (exactly the rigid gap; at
// contact both minima coincide).
//
// WHEEL ON ROLLER (TrackSetup::roller_radius_m > 0 on a side; docs/physics-reference.md §1.7): the "rail" is a
// surface of revolution about an axis parallel to the track y axis at (x = 0, z = -R_r) in the side frame; its
// meridian profile is the mounted rail profile, so a profile point (eta, z_r) lies at the distance
// R_r(eta) = R_r + z_r(eta) from the axis (the roller's rolling radius there). The search is the same 2-D search in
// the roller's MERIDIAN coordinates (eta, zeta), zeta = |P - axis| - R_r (= z on the roller's top line x = 0): the
// roller is the profile curve zeta = z_r(eta) there, and the wheel silhouette becomes the set of wheel points whose
// outward normal is orthogonal to the roller's circumferential direction e_phi(P) ~ (z + R_r, 0, -x) (Newton from
// the rail's closed form). Distances in the meridian half-plane are exact 3-D distances to the roller, so
// NormalGap is the exact rigid gap; SilhouettePoint, VerticalGapAt, NormalGap and VerticalGapMinima return
// (x, eta, zeta) for such a side. MinimumVerticalGap stays the vertical lowering that makes the wheel touch (the
// meridian gap shrinks by dz cos(phi) per dz: iterated to convergence). R_r -> infinity gives the rail.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "conforma/profile.hpp"

namespace conforma {

// Left: the wheel/rail on the +y side of the track (side sign +1, index 0); Right: on the -y side (-1, index 1).
enum class Side { Left = 0, Right = 1 };
inline double side_sign(Side side) { return side == Side::Left ? 1.0 : -1.0; }
inline int side_index(Side side) { return static_cast<int>(side); }
const char* to_string(Side side);  // "left", "right"

// Range of a wheel's taping-line radius accepted by TrackSetup::validate (a 1:10 scaled rig ~46 mm, locomotives ~0.63 m)
constexpr double kMinWheelRadius_m = 0.02;
constexpr double kMaxWheelRadius_m = 2.0;
// Largest roller speed of a roller rig accepted in its input files (the wear plan, the adhesion table): rigs run
// below ~3000 rpm (paper 000: 1000 rpm); beyond it a unit or column mistake
constexpr double kMaxRollerRigSpeedRpm = 10000.0;
// Largest wheelset yaw relative to the track a contact entry point accepts (rad; angles of attack reach ~50 mrad on
// a 20 m tram curve); beyond it the command line and table builds refuse the pose instead of solving it
constexpr double kMaxWheelsetYaw_rad = 0.2;
// InputError naming `name` unless yaw_rad is finite and within kMaxWheelsetYaw_rad (the message in mrad). For the
// entry points (command line, Python, C API); the solvers themselves do not limit the yaw (a derailing wheelset in
// the time domain is a result, not an input error).
void RequireWheelsetYaw(double yaw_rad, const std::string& name);

// The wheelset and track (see WHEEL / RAIL PLACEMENT above); validate() checks the ranges given.
struct TrackSetup {
  double gauge_m = 1.435;                    // m, > 0, measured gauge_height_m below the top of the rails
  double gauge_height_m = 0.014;             // m, >= 0: depth below the rail top at which the gauge is measured
  double flange_back_distance_m = 1.360;     // m, > 0: distance between the two wheels' flange backs
  double flange_back_position_m = -0.070;    // wheel-profile y of the flange back, m (S1002: -70 mm)
  std::array<double, 2> nominal_radius_m{0.46, 0.46};  // [Left, Right], m, kMin/kMaxWheelRadius_m: taping-line r0
  // rad, |.| <= 0.2: applied to both (uninclined) rail profiles (0 for profiles already canted); 1:40 = 0.025
  double rail_inclination_rad = 0.0;
  std::array<Profile, 2> wheel;              // [Left, Right], each in the right-side convention; wheel profiles
  std::array<Profile, 2> rail;               // [Left, Right], each in the right-side convention; rail profiles
  // Roller rig (issue 18, paper 000): [Left, Right] nominal radius R_r of the roller that replaces each rail, m;
  // 0 (default): a rail, straight along x. > 0: the "rail" profile is the roller's profile (same convention and
  // placement as a rail, its top at z = 0) turned about an axis parallel to the track y axis, R_r below the top, so
  // the surface drops by about x^2 / (2 R_r(y)) along x, with R_r(y) = R_r + z_r(y) the roller's rolling radius.
  std::array<double, 2> roller_radius_m{0.0, 0.0};
  void validate() const;                     // throws InputError naming the parameter
};
// Half the longitudinal relative curvature, A in h = gap + A x^2 (docs/physics-reference.md §1.1, §1.7): the wheel's
// rolling curvature in the plane of the contact normal, cos(alpha_w) / r (alpha_w = atan(wheel_slope), r its rolling
// radius), plus on a roller (roller_rolling_radius_m > 0; 0: a rail, straight along x) the roller's, cos(delta) /
// R_r(y) (delta = atan(rail_slope), Meusnier), halved. The one place the patch geometry and the Hertz A are built.
inline double LongitudinalRelativeCurvature(double wheel_slope, double wheel_radius_m, double rail_slope,
                                            double roller_rolling_radius_m) {
  double A = std::cos(std::atan(wheel_slope)) / (2.0 * wheel_radius_m);
  // Johnson (1985) §4.2 eq. 4.1: A = (1/R'_1 + 1/R'_2) / 2 over both bodies' curvatures along x
  if (roller_rolling_radius_m > 0.0) A += std::cos(std::atan(rail_slope)) / (2.0 * roller_rolling_radius_m);
  return A;
}

// Same wheel and rail profile on both sides.
TrackSetup MakeSymmetricTrack(const Profile& wheel, const Profile& rail, double rail_inclination_rad = 0.0);

// Wheelset pose in the track frame (see FRAMES above).
struct WheelsetPose {
  double lateral_m = 0.0;   // lateral shift y, m, + towards the left rail
  double vertical_m = 0.0;  // axle centre height above (rail-top level + mean nominal radius), m
  double roll_rad = 0.0;    // roll about +x, rad, + raises the left wheel
  double yaw_rad = 0.0;     // yaw about +z, rad, + turns the heading towards the left rail
};

// Resolution of the rigid contact search; InputError (WheelsetTrackGeometry constructor) outside the ranges given.
struct GeometryOptions {
  double table_spacing_m = 0.1e-3;   // m, > 0: uniform y tables of wheel and rail (cubic Hermite between nodes)
  double scan_spacing_m = 0.5e-3;    // m, > 0: coarse silhouette scan along the wheel profile (multiple of the above)
  double max_slope = 12.0;           // |dz/dy| beyond which profile parts are left out (85 deg), > 0
  double candidate_window_m = 2e-3;  // m, >= 0: local minima up to this much above the smallest gap are reported
  double contact_tolerance_m = 1e-6; // m, >= 0: minima within this of the smallest gap count as contact points
  // An uninclined rail (TrackSetup::rail_inclination_rad 0) whose highest point is off z = 0 is mounted by refitting
  // its translated samples (true, Profile::FromPoints) or by translating it exactly (false, no resampling). The refit
  // changes the curvature of fine worn features (0.3 % for a 2 um bell 1 mm wide on the 1:5 roller's top); the real-time
  // rig updates translate (roller_rig_sample.cpp), the rest keeps the refit so that existing results stay as they are.
  bool refit_uninclined_rail = true;
};

// Ok: at least one rigid contact point (gap minimum) found; NoOverlap: the silhouette does not face the rail head.
enum class ContactStatus { Ok, NoOverlap /* silhouette does not face the rail head */ };
const char* to_string(ContactStatus status);  // "ok", "no_overlap"

struct RigidContactPoint {
  double gap_m = 0.0;               // rigid gap along the rail normal (< 0: interpenetration)
  double vertical_gap_m = 0.0;      // vertical separation at the vertical-gap minimum
  Eigen::Vector3d wheel_point_m = Eigen::Vector3d::Zero();  // track frame
  Eigen::Vector3d rail_point_m = Eigen::Vector3d::Zero();   // track frame (x = lead of the wheel point)
  Eigen::Vector2d rail_profile_m = Eigen::Vector2d::Zero(); // mounted rail-profile (y, z), origin at its top
  double rail_s_m = 0.0;            // arc length on the mounted rail profile
  Eigen::Vector2d wheel_profile_m = Eigen::Vector2d::Zero();// wheel-profile (y_w, z_w)
  double contact_angle_rad = 0.0;   // rail normal from vertical, + towards the gauge side
  double rolling_radius_m = 0.0;    // r0 + z_w(y_w)
  double lead_m = 0.0;              // longitudinal position relative to the wheel's diametral plane
  double wheel_theta_rad = 0.0;     // angle about the axle of the silhouette point (+ ahead)
  double wheel_lateral_curvature_per_m = 0.0;  // convex > 0
  double rail_lateral_curvature_per_m = 0.0;   // convex > 0
  // cos(alpha_w) / (2 r)  (alpha_w: wheel profile slope angle), + cos(delta) / (2 R_r(y)) on a roller (§1.7)
  double hertz_A_per_m = 0.0;
  // Roller (roller_radius_m > 0): the roller's rolling radius R_r(y) = R_r + z_r at the contact point (distance of
  // rail_point_m from the roller axis), m; 0 for a rail. Positions on a roller: wheel_point_m is the wheel's
  // silhouette point, rail_point_m its nearest point on the roller (in the meridian plane through the wheel point,
  // so its x is (R_r(y) / |P - axis|) times the wheel point's x); contact_angle_rad is measured in that plane.
  double roller_rolling_radius_m = 0.0;
  double hertz_B_per_m = 0.0;       // (kappa_wheel + kappa_rail) / 2
  // Roller: the angle phi of the contact point about the roller axis from its top line, + ahead (rail_point_m.x =
  // R_r(y) sin(phi)); the contact normal leans by phi along x. 0 for a rail.
  double roller_angle_rad = 0.0;
};

// Cosine of the angle between a contact point's normal and the vertical: cos(delta) on a rail, cos(delta) cos(phi) on a
// roller (the normal also leans by phi along x). The rigid normal approach per unit of vertical lowering, and the
// vertical share of a normal force.
inline double NormalVerticalCosine(const RigidContactPoint& p) {
  const double c = std::cos(p.contact_angle_rad);
  return p.roller_rolling_radius_m > 0.0 ? c * std::cos(p.roller_angle_rad) : c;
}

// The rigid contact of one wheel at a pose (RigidContact).
struct WheelContactResult {
  ContactStatus status = ContactStatus::NoOverlap;  // see ContactStatus
  std::vector<RigidContactPoint> points;  // local gap minima within candidate_window_m, smallest gap first
  int contact_count = 0;                  // points within contact_tolerance_m of the smallest gap (>= 1 when Ok)
};

struct WheelsetContactResult {
  std::array<WheelContactResult, 2> wheel;  // [Left, Right]
};

// InputError for tolerance_m <= 0.
struct EquilibriumOptions {
  double tolerance_m = 1e-10;  // m, > 0: the right wheel's smallest vertical gap must be below this at convergence
  int max_iterations = 60;     // root-finder evaluations of the roll (bracket expansion and Illinois steps together)
  // false: the roll stays at guess.roll_rad and each wheel is lowered onto its own rail independently
  // (both touch, each at its own vertical position; the reported pose has the left wheel touching). Used
  // for the EN 15302 benchmark Delta r (tests/test_conicity_en15302.cpp). true: the rigid wheelset rolls
  // about the axle centre, so the contact-level lateral shift differs from lateral_m by about r0 * roll.
  bool include_roll = true;
  // Elastic flange (MinimumVerticalGap): the wheels touch where the rail's contact angle is at most this; a
  // steeper flange contact may interpenetrate. Default: every contact point counts (rigid flange).
  double max_touching_contact_angle_rad = 1e300;
};
// Converged: both wheels touch within tolerance_m; NotConverged: no roll bracket or tolerance not met in
// max_iterations (the last iterate is returned); NoContact: a wheel does not face its rail (no gap minimum).
enum class EquilibriumStatus { Converged, NotConverged, NoContact };
const char* to_string(EquilibriumStatus status);  // "converged", "not_converged", "no_contact"

struct EquilibriumResult {
  EquilibriumStatus status = EquilibriumStatus::NoContact;  // see EquilibriumStatus
  // lateral and yaw as given; vertical and roll solved (include_roll false: roll as guessed, left wheel touching)
  WheelsetPose pose;
  WheelsetContactResult contact;       // at the solved pose (include_roll false: each wheel lowered onto its rail)
  // r_left - r_right at the smallest-gap contact points, m; 0 unless both wheels have a contact point
  double rolling_radius_difference_m = 0.0;
  int iterations = 0;                  // root-finder evaluations of the roll; 0 with include_roll false
};

// Everything that depends only on the track set-up (mounted rails, uniform tables) is prepared once; the
// pose evaluations are const and thread-safe.
// Closed interval [lo_m, hi_m] of a profile's own lateral coordinate y; empty when lo_m > hi_m.
struct LateralInterval {
  double lo_m = 1.0, hi_m = -1.0;
  bool empty() const { return lo_m > hi_m; }
};

class WheelsetTrackGeometry {
 public:
  explicit WheelsetTrackGeometry(TrackSetup setup, const GeometryOptions& options = {});
  // The geometry of worn profiles from the geometry of the profiles they were worn from, for real-time updates
  // (roller rig, docs/physics-reference.md §18.3): `worn` is previous.setup() with new profiles that coincide with
  // the previous ones outside the lateral intervals changed_wheel[side] / changed_rail[side] (profile y; empty:
  // unchanged profile; the interval must cover every spline segment whose values changed). The table nodes before
  // an interval are taken from `previous`; from the interval on they are solved on the new profile as the full
  // constructor does (Newton continued from node to node), up to the first node beyond it whose arc length comes out
  // bit for bit as before, after which `previous`'s nodes are those the full constructor would solve. A side whose
  // rail is refitted by its mounting (inclined, or GeometryOptions::refit_uninclined_rail with the top off z = 0
  // before or after) or whose top moved (every node changes in rounding), whose interval reaches a table end or whose
  // new nodes are no longer function-like is built as the full constructor does; so is everything when `worn`
  // differs from previous.setup() in more than its profiles. The result is WheelsetTrackGeometry(worn,
  // previous.options()) bit for bit (tests/test_geometry_worn_update.cpp).
  WheelsetTrackGeometry(const WheelsetTrackGeometry& previous, TrackSetup worn,
                        const std::array<LateralInterval, 2>& changed_wheel,
                        const std::array<LateralInterval, 2>& changed_rail);

  const TrackSetup& setup() const { return setup_; }
  const GeometryOptions& options() const { return options_; }
  // Mounted rail profile of a side (inclined, origin at its highest point), right-side convention.
  const Profile& mounted_rail(Side side) const { return sides_[side_index(side)].mounted_rail; }
  // eta of the mounted rail-profile origin in the side frame.
  double rail_origin_eta_m(Side side) const { return sides_[side_index(side)].rail_origin_eta; }
  double wheel_origin_eta_m() const { return wheel_origin_eta_; }
  // Roller radius R_r of a side (TrackSetup::roller_radius_m; 0: a rail) and the roller's rolling radius
  // R_r + z_r(eta) at side-frame eta of its profile (0 for a rail or outside the table).
  double RollerRadius(Side side) const { return sides_[side_index(side)].roller_radius; }
  double RollerRollingRadius(Side side, double eta) const;

  WheelContactResult RigidContact(Side side, const WheelsetPose& pose) const;
  WheelsetContactResult RigidContacts(const WheelsetPose& pose) const;
  // Smallest vertical separation of one wheel (cheap: coarse scan + Brent), and the track-frame y of that
  // point. Returns false when the wheel does not face the rail head.
  // max_contact_angle_rad (elastic flange): only local minima where the rail's contact angle is at most this
  // count (all of them when none does), so a flange pressed against the rail may interpenetrate; the elastic
  // contact then carries its force instead of the wheel climbing rigidly onto it.
  bool MinimumVerticalGap(Side side, const WheelsetPose& pose, double* gap_m, double* track_y_m,
                          double max_contact_angle_rad = kAllContactAngles) const;
  static constexpr double kAllContactAngles = 1e300;
  struct Frame;
  // Vertical gap where the rail's gauge corner reaches contact angle `angle` (elastic-flange boundary).
  bool LimitAngleGap(Side side, const Frame& frame, double angle, double* gap, double* y_w, double* eta) const;
  // Vertical position and roll so that both wheels touch their rails (rigid), for a given lateral shift and
  // yaw. `guess` supplies starting values of vertical_m and roll_rad (continuation along a sweep).
  EquilibriumResult SolveRigidEquilibrium(double lateral_m, double yaw_rad, const WheelsetPose& guess = {},
                                          const EquilibriumOptions& options = {}) const;

  // ---- lower-level access used by the candidate and creepage modules ----
  struct Frame {               // pose in the side frame of one side
    Eigen::Matrix3d rotation;  // Rz(sigma psi) Rx(sigma phi)
    Eigen::Vector3d centre;    // (0, sigma y, mean r0 + z)
    double sin_beta = 0.0, cos_beta = 1.0, rho = 1.0;  // silhouette closed-form constants
  };
  Frame SideFrame(Side side, const WheelsetPose& pose) const;
  // Silhouette point of the wheel at wheel-profile y_w (side frame); false outside the wheel table or when
  // the silhouette condition has no solution. theta, radius, slope r' optional outputs.
  // On a roller: the point in meridian coordinates (x, eta, zeta) (WHEEL ON ROLLER above).
  bool SilhouettePoint(Side side, const Frame& frame, double y_w, Eigen::Vector3d* point, double* theta = nullptr,
                       double* radius = nullptr, double* slope = nullptr) const;
  // The same silhouette point in the side frame (x, eta, z) (identical to SilhouettePoint for a rail).
  bool SilhouettePointInSideFrame(Side side, const Frame& frame, double y_w, Eigen::Vector3d* point,
                                  double* theta = nullptr, double* radius = nullptr, double* slope = nullptr) const;
  // Rail height and slope at side-frame eta; false outside the rail table.
  bool RailHeight(Side side, double eta, double* z, double* slope) const;
  // State carried through a run of NormalGap calls on one side and frame (the strips of a patch), each started from
  // the previous one's solution y_w: the last successful call's silhouette point there, so that the next call's Newton
  // start is not evaluated again (the same point bit for bit: the silhouette depends only on side, frame and y_w), and
  // what that call evaluated at its solution which the caller would otherwise evaluate again: the silhouette's radius
  // r0 + z_w and profile slope at the returned y_w, the rail's height and slope at eta. Default-constructed per frame.
  struct NormalGapWork {
    bool has_sample = false;  // the fields below hold the last successful call's solution
    double y_w = 0.0;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  // SilhouettePoint at y_w (the returned wheel_point)
    double wheel_radius_m = 0.0, wheel_slope = 0.0;   // SilhouettePoint's radius and slope at y_w
    double rail_z_m = 0.0, rail_slope = 0.0;          // RailHeight at the call's eta
  };
  // Rigid gap along the local rail normal at side-frame eta of the rail surface: the signed distance from
  // the rail point along its outward normal to the wheel silhouette (< 0: interpenetration). y_w_guess is
  // the starting wheel-profile y (updated to the solution). False if no intersection was found.
  // work (optional, one per side and frame): see NormalGapWork.
  bool NormalGap(Side side, const Frame& frame, double eta, double* y_w_guess, double* gap_m,
                 Eigen::Vector3d* wheel_point = nullptr, NormalGapWork* work = nullptr) const;
  // Arc length on the mounted rail at side-frame eta (rail table), and the inverse. node_hint (optional): the rail-table node
  // the inverse's search starts from (0: a binary search), updated; a run of nearby s (the strips of a patch) then
  // takes a step or two instead of a binary search each, with the same result.
  double RailArcLength(Side side, double eta) const;
  double RailEtaAtArcLength(Side side, double s, size_t* node_hint = nullptr) const;
  // Wheel profile quantities at y_w: radial height z_w, slope, curvature (convex > 0).
  bool WheelProfileAt(Side side, double y_w, double* z_w, double* slope, double* curvature) const;
  double WheelTableBegin(Side side) const { return sides_[side_index(side)].wheel.y0; }
  double WheelTableEnd(Side side) const { return sides_[side_index(side)].wheel.y_end(); }
  double RailTableBegin(Side side) const { return sides_[side_index(side)].rail.y0; }
  double RailTableEnd(Side side) const { return sides_[side_index(side)].rail.y_end(); }
  // Local minima of the vertical separation along the wheel silhouette (coarse scan + Brent).
  struct VerticalGapMinimum {
    double y_w = 0.0, gap_m = 0.0, eta = 0.0;
  };
  std::vector<VerticalGapMinimum> VerticalGapMinima(Side side, const Frame& frame) const;
  // Vertical separation at wheel-profile y_w (silhouette point minus rail below it); +inf outside.
  double VerticalGapAt(Side side, const Frame& frame, double y_w, double* eta = nullptr) const;
  // Fills the derived quantities of a contact point from (y_w, eta_rail) in the side frame.
  RigidContactPoint MakeContactPoint(Side side, const Frame& frame, const WheelsetPose& pose, double y_w,
                                     double eta_rail, double gap_m, double vertical_gap_m) const;

  // Uniform table z(y) of a function-like profile part, cubic Hermite between nodes.
  struct GraphTable;
  const GraphTable& WheelTable(Side side) const { return sides_[side_index(side)].wheel; }
  const GraphTable& RailTable(Side side) const { return sides_[side_index(side)].rail; }
  double NominalRadius(Side side) const { return sides_[side_index(side)].nominal_radius; }
  struct GraphTable {
    double y0 = 0.0, h = 1e-4;
    std::vector<double> z, dz, kappa, s;  // value, slope, signed curvature (convex > 0), arc length
    std::vector<double> arc_slope;         // ds/dy = sqrt(1 + dz^2) at the nodes (the arc length's Hermite slopes)
    double s_first = 0.0, s_last = 0.0;   // arc-length range of the tabulated part of the profile (Newton's bounds)
    size_t size() const { return z.size(); }
    double y_end() const { return z.empty() ? y0 : y0 + h * static_cast<double>(z.size() - 1); }
    inline bool eval(double y, double* value, double* slope) const;  // (defined below: inlined in the hot loops)
  };

 private:
  // One evaluation of the smallest (meridian, on a roller) gap minimum: MinimumVerticalGap on a rail.
  bool MinimumGapOnce(Side side, const WheelsetPose& pose, double* gap_m, double* track_y_m,
                      double max_contact_angle_rad) const;
  struct SideData {
    Profile mounted_rail;
    Eigen::Vector2d mount_shift = Eigen::Vector2d::Zero();  // subtracted from the inclined rail's samples
    double rail_origin_eta = 0.0;
    double rail_table_y0 = 0.0;  // the rail table's first node in the mounted profile's y (rail.y0 - rail_origin_eta)
    GraphTable rail;   // in side-frame eta
    GraphTable wheel;  // in wheel-profile y_w (z = radial height z_w)
    double nominal_radius = 0.46;
    double roller_radius = 0.0;  // R_r; 0: a rail
  };
  void BuildSide(int k);  // sides_[k] from setup_ (the full constructor's work for one side)
  void BuildRail(int k);  // its mounted rail, rail origin and rail table
  TrackSetup setup_;
  GeometryOptions options_;
  std::array<SideData, 2> sides_;
  double wheel_origin_eta_ = 0.75;
  double mean_radius_ = 0.46;
};

// Cubic Hermite table value and slope at y; false outside the table.
inline bool WheelsetTrackGeometry::GraphTable::eval(double y, double* value, double* slope) const {
  if (z.size() < 2) return false;
  const double u = (y - y0) / h;
  if (!(u >= 0.0) || u > static_cast<double>(z.size() - 1)) return false;
  const size_t i = std::min(static_cast<size_t>(u), z.size() - 2);
  const double t = u - static_cast<double>(i), t2 = t * t, t3 = t2 * t;
  // cubic Hermite on [i, i+1] with node values and slopes
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  if (value) *value = h00 * z[i] + h10 * h * dz[i] + h01 * z[i + 1] + h11 * h * dz[i + 1];
  if (slope) {
    const double d00 = (6 * t2 - 6 * t) / h, d10 = 3 * t2 - 4 * t + 1, d01 = (-6 * t2 + 6 * t) / h, d11 = 3 * t2 - 2 * t;
    *slope = d00 * z[i] + d10 * dz[i] + d01 * z[i + 1] + d11 * dz[i + 1];
  }
  return true;
}

// Lateral shift at which the wheel on the outer side (c > 0: right, y < 0) reaches flange contact: the last shift
// (0.1 mm scan, up to 20 mm) before the smallest-gap rigid contact jumps to the flange (contact angle >
// flange_angle_rad); signed (negative for c > 0).
double FlangeContactShift(const WheelsetTrackGeometry& geometry, double curvature_sign, double flange_angle_rad = 0.5);

// Every number that defines the geometry: the mounting (gauge, gauge height, flange-back distance and position,
// nominal radii, inclination, roller radii) and every profile sample of both wheels and rails. Equal fingerprints,
// equal geometry (the dynamic provider's table cache; a contact LUT's digest, contact_lut.hpp).
std::vector<double> GeometryFingerprint(const WheelsetTrackGeometry& geometry);

}  // namespace conforma
