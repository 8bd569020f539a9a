#pragma once
// Local rigid slip on a curved (conformal) contact patch (docs/physics-reference.md §5, paper 003 §4.2). Across a
// conformal patch the rolling radius r(s^r) and the normal n(s^r) change, so the creepages differ from strip to
// strip; in particular a rotation about an axis in the tangent plane at the reference point (the wheel's rolling
// about its axle) becomes spin where the normal has turned.
//
// Local frame of a strip (all vectors in the track frame): n = the outward RAIL normal at the strip (pointing
// into the wheel); e1 = the track x axis projected on the tangent plane (rolling direction); e2 = the strip's
// lateral tangent (direction of increasing s^r) made orthogonal to n and e1. Rigid slip of the wheel (body 1)
// relative to the rail (body 2, fixed), divided by the rolling speed V:
//     w = (v + omega x (P - O)) / V,    slip_x = w . e1,   slip_s = w . e2,   spin = omega . (e1 x e2) / V
// (spin about e1 x e2, so that the rigid-slip field around P is (slip_x - spin dy, slip_s + spin dx) in the
// (e1, e2) coordinates whatever the handedness of the frame: the form FASTSIM uses, docs/physics-reference.md §2.4).
//
// Per-strip creepages for the curved FASTSIM (curved_fastsim.hpp) are "creepages at the spin origin in the strip
// frame": the core builds the rigid slip (xi_j - phi_j y L1/L3, eta_j + phi_j x L2/L3) with y = s_j - s_o,
// x measured from x_o. From the rigid slip at the strip point (x_P, s_j):
//     xi_j = slip_x + phi_j (s_j - s_o),   eta_j = slip_s - phi_j (x_P - x_o)
// which makes the rigid slip exact when L1 = L2 = L3 and keeps FASTSIM's split into creepage and spin parts.
#include <vector>

#include <Eigen/Core>

#include "conforma/fastsim.hpp"
#include "conforma/kik_piotrowski.hpp"

namespace conforma {

struct RigidBodyMotion {  // wheel relative to the (fixed) rail, track frame
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();  // velocity of the point `origin_m`
  Eigen::Vector3d angular_velocity_rad_per_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();  // e.g. the wheelset centre
  double rolling_speed_m_per_s = 0.0;                  // V > 0
};

struct SurfaceFrame {  // track frame
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();           // outward rail normal (unit)
  Eigen::Vector3d lateral_tangent = Eigen::Vector3d::UnitY();  // direction of increasing s^r
};

struct LocalRigidSlip {
  double slip_x = 0.0;       // along e1 [-]
  double slip_s = 0.0;       // along e2 [-]
  double spin_per_m = 0.0;   // [1/m]
};

// Throws InputError for V <= 0, NaN, a degenerate frame (normal along x, lateral tangent along the normal).
LocalRigidSlip RigidSlipAt(const RigidBodyMotion& motion, const SurfaceFrame& frame);

// The local frame (point, normal, lateral tangent) of strip `strip` of a solved KP patch, at x = x_m along the
// strip, given the patch reference frame in the track frame: reference point, unit longitudinal axis x_axis
// (rolling direction), t0 (reference tangent, +s) and n0 (reference outward rail normal). Uses KpStrip.position_m
// (t0, n0 components) and alpha: n = cos(alpha) n0 + sin(alpha) t0, t = cos(alpha) t0 - sin(alpha) n0 (patch.hpp).
struct PatchReferenceFrame {
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d tangent = Eigen::Vector3d::UnitY();  // t0
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // n0
};
SurfaceFrame StripSurfaceFrame(const PatchReferenceFrame& reference, const KpStrip& strip, double x_m);

// FASTSIM per-strip creepages (see the header comment) from the rigid slip at the strip point (x_P, s_j).
FastsimCreepages CreepagesAtSpinOrigin(const LocalRigidSlip& slip, double x_point_m, double s_point_m,
                                       double spin_origin_x_m, double spin_origin_s_m);

// Mode 1, full kinematics: every strip's creepages from the rigid-body motion, evaluated at (x_centre_j, s_j).
std::vector<FastsimCreepages> StripCreepagesFromKinematics(const RigidBodyMotion& motion,
                                                           const PatchReferenceFrame& reference,
                                                           const KpResult& normal, double spin_origin_x_m = 0.0,
                                                           double spin_origin_s_m = 0.0);

// Mode 2, reference creepages plus the geometric variation (no 3-D frames needed). At the reference point
// (s = 0) the local creepages are xi0, eta0, phi0; the wheel turns about its axle with Omega = (1 - xi0) V / r0,
// plus any other rotation summarised by its component along t0:
//   slip_x(s_j) = 1 - (1 - xi0) r_j / r0                 (rolling radius r(s), PatchGeometry::wheel_radius_m)
//   slip_s(s_j) = eta0 cos(alpha_j)                      (the reference slip velocity is tangent: v . n0 = 0)
//   spin(s_j)   = phi0 cos(alpha_j) + omega_t sin(alpha_j)    (omega . (e1 x e2_j), n_j = cos a n0 + sin a t0)
// omega_t = omega . (n0 x e1) / V [1/m] (= omega . t0 / V when (e1, t0, n0) is right-handed) is the tangent-plane
// rotation that the normal turn converts into spin (for a wheel rolling about its axle at contact angle delta,
// |omega_t| = (1 - xi0) cos(delta) / r0); phi0 = omega . (e1 x t0) / V in the same convention. Translational slip
// variation from yaw/roll rates across the patch is neglected in this mode. r_j and alpha_j are interpolated linearly
// from the PatchGeometry strips at s_j.
struct ReferenceCreepages {
  double xi = 0.0, eta = 0.0, phi_per_m = 0.0;  // at the reference point, local frame
  double reference_radius_m = 0.0;             // r0 (> 0)
  double tangent_rotation_per_m = 0.0;         // omega_t
};
std::vector<FastsimCreepages> StripCreepagesFromReference(const ReferenceCreepages& reference,
                                                          const PatchGeometry& geometry, const KpResult& normal,
                                                          double spin_origin_x_m = 0.0, double spin_origin_s_m = 0.0);
// omega_t = omega . (n0 x e1) / V of a rigid-body motion (for mode 2 from the same kinematics as mode 1).
double ReferenceTangentialRotation(const RigidBodyMotion& motion, const PatchReferenceFrame& reference);

}  // namespace conforma
