#pragma once
// A contact patch candidate described in curvilinear rail coordinates: the common currency between the
// wheel-rail geometry (which produces it) and every normal / tangential solver (which consume it).
//
// Coordinates: x^r along the track (rolling direction), s^r the arc length along the rail profile measured
// from the patch's reference point (s = 0), n^r the local outward rail normal. The patch is a set of
// lateral strips of width ds centred at s_m[j]; along each strip the undeformed separation of wheel and
// rail, measured along the local rail normal n^r(s_j), is
//     h(x, s_j) = gap_m[j] + x^2 * longitudinal_curvature_per_m[j]        (x measured from the strip's
//                                                                          own lowest point x_offset_m[j])
// gap_m is >= 0 for the rigid (undeformed) position; an approach delta gives the interpenetration
// delta - h. All lengths in metres.
#include <Eigen/Core>
#include <vector>

namespace conforma {

struct PatchGeometry {
  double ds_m = 0.0;                 // strip width along s^r
  std::vector<double> s_m;           // strip centres, relative to the reference point
  std::vector<double> gap_m;         // undeformed separation along the local rail normal at the strip's lowest point
  // A(s) in h = gap + A x^2: half the curvature of the wheel surface in the normal section along x at the
  // strip, cos(delta(s)) / (2 r(s)) for a wheel of rolling radius r at contact angle delta (rail straight); on a
  // roller plus cos(delta(s)) / (2 R_r(s)) (LongitudinalRelativeCurvature, geometry.hpp).
  std::vector<double> longitudinal_curvature_per_m;
  std::vector<double> wheel_radius_m;   // in-situ wheel rolling radius r(s) at the strip
  // Wheel on roller (geometry.hpp): the roller's rolling radius R_r(s) = R_r + z_r(s) at the strip (its curvature is
  // included in longitudinal_curvature_per_m); empty for a rail
  std::vector<double> roller_radius_m;
  std::vector<double> alpha_rad;        // angle of the local rail normal from the reference normal, + towards +s
  std::vector<double> x_offset_m;       // longitudinal position of the strip's lowest gap point (yaw lead)

  // Reference point and frame of the patch in the rail-profile frame of this wheel's rail (y towards the
  // field side, z up, origin at the top of the rail as mounted, i.e. including the inclination).
  Eigen::Vector2d reference_point_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d reference_normal = Eigen::Vector2d(0.0, 1.0);  // unit, outward from the rail
  double reference_s_on_rail_m = 0.0;   // arc length of the reference point on the rail profile
  double contact_angle_rad = 0.0;       // angle of reference_normal from the track vertical, + towards the
                                        // track centre (gauge side; flange ~ +1.1 rad), see geometry.hpp
  // Added by the geometry: the approach along the reference normal that reproduces the rigid
  // interpenetration of this region at the pose (= -min of the local gaps before they were shifted to
  // min gap_m = 0). 0 when the patch was built for a touching pose.
  double rigid_approach_m = 0.0;

  size_t strips() const { return s_m.size(); }
};

}  // namespace conforma
