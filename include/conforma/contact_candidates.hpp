#pragma once
// Elastic contact candidates of one wheel: every separate interpenetration region of the wheel silhouette
// and the rail at a pose (or at the pose pushed down so that Hertz contacts carry a vertical load), each
// as a PatchGeometry in curvilinear rail coordinates (patch.hpp) for the normal solvers.
//
// Region: an interval [s_a, s_b] of rail arc length between two intersections of the wheel silhouette with
// the rail (exact intersections, so the same for vertical or normal gaps). Reference point = CENTRE of the
// region on the rail, s_ref = (s_a + s_b) / 2 (as CONTACT defines its contact reference point); reference
// normal = rail normal there. Strips of width ds, uniform in s, cover the region plus a margin on each side.
// Per strip: gap along the local rail normal (shifted so that its minimum over the patch is 0; the shift is
// PatchGeometry::rigid_approach_m), A(s) = cos(alpha_w) / (2 r) (alpha_w: wheel profile slope angle at the
// silhouette point facing the strip; docs/physics-reference.md §1.1; on a roller + cos(delta) / (2 R_r(s)), §1.7),
// wheel radius r(s), alpha(s) = angle of the
// local rail normal from the reference normal (+ towards +s), x_offset(s) = lead of the silhouette point
// relative to the wheel's vertical diametral plane (geometry.hpp).
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/hertz.hpp"
#include "conforma/material.hpp"
#include "conforma/patch.hpp"

namespace conforma {

// Default combine distance of CandidateOptions::combine_distance_m: 4 mm, CONTACT's D_COMB (its wheel-rail examples
// and manual default), below which CONTACT merges two patches completely.
inline constexpr double kDefaultCombineDistanceM = 4e-3;

// InputError outside the ranges given.
struct CandidateOptions {
  double strip_width_m = 0.1e-3;  // strip width ds of the patches, m, > 0 (default 0.1 mm)
  double margin_fraction = 0.25;  // margin on each side, as a fraction of the region width, >= 0
  int min_margin_strips = 3;      // ... but at least this many strips (margin = max of the two)
  // Load-given mode: the bisection of the Hertz push-down dz stops when its bracket is narrower than this times
  // |dz| (relative; a tolerance on dz, not on the load)
  double load_tolerance = 1e-6;
  // Load-given mode: the regions are taken at this fraction of the Hertz push-down. 1 = the rigid
  // interpenetration at the Hertz approach (the bare definition); Kik-Piotrowski's virtual penetration
  // epsilon = 0.55 (docs/physics-reference.md §3.1) gives regions the size of the elastic contact area.
  double penetration_factor = 1.0;  // > 0 (checked in the load-given mode only)
  // Patch grouping: neighbouring interpenetration regions separated along the rail profile by less than this arc
  // length are solved as ONE curved patch (CONTACT's D_COMB, 4 mm in its wheel-rail examples): its strips span both
  // regions and the gap between them, with the local normals alpha(s) turning across it, and its reference point is
  // the centre of the combined interval. 0 keeps every interpenetration region separate. docs/physics-reference.md
  // §1.6.1. Default kDefaultCombineDistanceM.
  double combine_distance_m = kDefaultCombineDistanceM;  // m, >= 0
  // Load-given mode, elastic flange: the wheel's reference (touching) position ignores gap minima steeper than
  // this (WheelsetTrackGeometry::MinimumVerticalGap), so a flange pressed against the rail interpenetrates
  // and the load control finds the vertical position with the flange force included. Default: all count.
  double max_touching_contact_angle_rad = 1e300;  // rad
  // false: each patch's strips stop at its second reachable one (the condition for a region to yield a patch is
  // the same, checked on the same strips); patch.rigid_approach_m is then NaN and the strips are not the region's.
  // For a caller that reads only the regions, their reference points and the rigid contact points (the multi-Hertz
  // model with the total-force balance, wheel_normal_stage.cpp): the strip geometry is most of the search's cost.
  bool strip_geometry = true;
};

// Ok: at least one candidate; NoContact: the wheel faces the rail but does not interpenetrate it (or no region
// yields a patch); NoOverlap: the wheel silhouette does not face the rail head.
enum class CandidateStatus { Ok, NoContact /* no interpenetration */, NoOverlap /* wheel not over the rail */ };
const char* to_string(CandidateStatus status);  // "ok", "no_contact", "no_overlap"

struct ContactCandidate {
  PatchGeometry patch;          // the region's strips (at least 2), reference point at the region's centre
  RigidContactPoint reference;  // quantities at the reference point (rolling radius, wheel point, Hertz A, B)
  double region_start_s_m = 0.0, region_end_s_m = 0.0;  // interpenetration region on the rail (arc length), m
  // Sum of the Hertz estimates (N) of the rigid contact points inside the region (load-given mode only; 0 otherwise)
  double normal_force_estimate_N = 0.0;
};

struct CandidateResult {
  CandidateStatus status = CandidateStatus::NoOverlap;  // see CandidateStatus
  WheelsetPose pose;                         // the pose the regions were taken at
  std::vector<ContactCandidate> candidates;  // ordered along the rail (gauge side first); empty unless Ok
  // Load-given mode only (has_touching): the wheel at first touch, where the Hertz push-down starts, and its
  // rigid contact points there.
  bool has_touching = false;
  WheelsetPose touching_pose;                // (has_touching only)
  WheelContactResult touching_contact;       // (has_touching only)
};

// Regions at the given pose (interpenetration of the rigid profiles).
CandidateResult FindContactCandidates(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                      const CandidateOptions& options = {});

// Load-given: the wheel is first lowered (roll, yaw and lateral fixed) until it touches, then pushed down by
// dz such that the Hertz contacts at the rigid contact points (SolveHertzForApproach with approach
// (dz - vertical gap) cos(delta)) carry the vertical load, sum N_i cos(delta_i) = load; regions are taken at
// that pose (times options.penetration_factor). Throws InputError for a negative or non-finite load.
CandidateResult FindContactCandidatesForLoad(const WheelsetTrackGeometry& geometry, Side side,
                                             const WheelsetPose& pose, double vertical_load_N,
                                             const Material& material, const CandidateOptions& options = {});

}  // namespace conforma
