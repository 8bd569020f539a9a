#pragma once
// Wheelset kinematics from / to an external multibody code (Simpack, GENSYS, VAMPIRE, ...): CSV with named columns.
//
// FORMAT (one file = one KinematicsSeries, e.g. one track class):
//   * Lines starting with '#' and empty lines are ignored anywhere in the file.
//   * The first other line is the header: comma-separated column names (surrounding blanks are trimmed). The
//     column order is free and unknown columns are ignored (an MBS export may carry more).
//   * Every further line is one sample of one wheelset: comma-separated decimal numbers (C locale, '.' as the
//     decimal mark, exponent allowed), as many cells as header names.
//   Required columns (SI units, frames of geometry.hpp: track x forward, y towards the LEFT rail, z up):
//     time_s        time of the sample
//     wheelset      wheelset index within the vehicle, 0 = leading (integer >= 0)
//     y_m           lateral shift of the wheelset centre (+ towards the left rail)
//     z_m           vertical position of the axle centre above rail-top level + nominal radius (any value:
//                   the wear loop pushes the wheels down under load control from here)
//     roll_rad      roll about +x (+ raises the LEFT wheel)
//     yaw_rad       yaw about +z relative to the local track tangent (+ turns the heading to the left)
//     dy_m_s        lateral velocity dy/dt
//     dyaw_rad_s    yaw rate d(yaw)/dt INCLUDING the curve's V/R (absolute yaw rate in the curve)
//     speed_m_s     forward speed V (> 0 for creepages)
//     omega_rad_s   axle angular velocity about the axle, + rolling forwards (V / r0 for pure rolling)
//     load_left_N   vertical load on the left wheel  (>= 0)
//     load_right_N  vertical load on the right wheel (>= 0)
//   Optional columns:
//     weight            weight of the sample within its wheelset (default: 1 / number of samples of that
//                       wheelset, i.e. samples equally spaced in time)
//     curvature_per_m   track curvature 1/R at the sample (+ turning left; default 0)
//   Example:
//     time_s,wheelset,y_m,z_m,roll_rad,yaw_rad,dy_m_s,dyaw_rad_s,speed_m_s,omega_rad_s,load_left_N,load_right_N,curvature_per_m
//     0,0,-0.0062,0,0.0021,-0.0048,0,0.05,15,42.19,39784,51939,0.00333
// Errors: unreadable file, missing required column (named, with the file), a non-numeric or non-finite cell,
// a wrong cell count, a negative load or wheelset index -> InputError "<file>:<line>: ...".
#include <string>

#include "conforma/kinematics.hpp"

namespace conforma {

KinematicsSeries ImportKinematicsCsv(const std::string& path);

// Writes all columns above (weight and curvature_per_m included) with %.17g, so that
// ImportKinematicsCsv(ExportKinematicsCsv(series)) reproduces every double bit for bit. Throws InputError if the
// file cannot be written. The series' source is written as a '#' comment line.
void ExportKinematicsCsv(const KinematicsSeries& series, const std::string& path);

}  // namespace conforma
