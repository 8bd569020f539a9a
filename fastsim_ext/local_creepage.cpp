// Local rigid slip on a curved patch (local_creepage.hpp; docs/physics-reference.md §5; paper 003 §4.2).
#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "conforma/error.hpp"
#include "conforma/local_creepage.hpp"

namespace conforma {

namespace {

void RequireFinite(const Eigen::Vector3d& v, const char* name) {
  if (!v.allFinite()) throw InputError(std::string(name) + " must be finite");
}

// e1 = track x projected on the tangent plane, e2 = lateral tangent orthogonalised (Gram-Schmidt).
void LocalAxes(const SurfaceFrame& frame, Eigen::Vector3d* e1, Eigen::Vector3d* e2, Eigen::Vector3d* n) {
  RequireFinite(frame.point_m, "SurfaceFrame.point_m");
  RequireFinite(frame.normal, "SurfaceFrame.normal");
  RequireFinite(frame.lateral_tangent, "SurfaceFrame.lateral_tangent");
  if (!(frame.normal.norm() > 0.0)) throw InputError("SurfaceFrame.normal must not be zero");
  *n = frame.normal.normalized();
  Eigen::Vector3d x = Eigen::Vector3d::UnitX() - n->x() * *n;
  if (x.norm() < 1e-9) throw InputError("SurfaceFrame.normal must not be along the track x axis");
  *e1 = x.normalized();
  Eigen::Vector3d t = frame.lateral_tangent - frame.lateral_tangent.dot(*n) * *n;
  t -= t.dot(*e1) * *e1;
  if (t.norm() < 1e-9) throw InputError("SurfaceFrame.lateral_tangent must not lie along the normal or x");
  *e2 = t.normalized();
}

double Interpolate(const std::vector<double>& s, const std::vector<double>& v, double at) {
  if (s.size() == 1) return v[0];
  const auto it = std::upper_bound(s.begin(), s.end(), at);
  size_t i = it == s.begin() ? 0 : static_cast<size_t>(it - s.begin()) - 1;
  i = std::min(i, s.size() - 2);
  const double t = (at - s[i]) / (s[i + 1] - s[i]);
  return v[i] + t * (v[i + 1] - v[i]);  // linear, extrapolated beyond the ends
}

}  // namespace

LocalRigidSlip RigidSlipAt(const RigidBodyMotion& motion, const SurfaceFrame& frame) {
  require_positive(motion.rolling_speed_m_per_s, "rolling_speed_m_per_s");
  RequireFinite(motion.velocity_m_per_s, "RigidBodyMotion.velocity_m_per_s");
  RequireFinite(motion.angular_velocity_rad_per_s, "RigidBodyMotion.angular_velocity_rad_per_s");
  RequireFinite(motion.origin_m, "RigidBodyMotion.origin_m");
  Eigen::Vector3d e1, e2, n;
  LocalAxes(frame, &e1, &e2, &n);
  const double inv_V = 1.0 / motion.rolling_speed_m_per_s;
  const Eigen::Vector3d w =
      (motion.velocity_m_per_s + motion.angular_velocity_rad_per_s.cross(frame.point_m - motion.origin_m)) * inv_V;
  LocalRigidSlip slip;
  slip.slip_x = w.dot(e1);
  slip.slip_s = w.dot(e2);
  slip.spin_per_m = motion.angular_velocity_rad_per_s.dot(e1.cross(e2)) * inv_V;
  return slip;
}

SurfaceFrame StripSurfaceFrame(const PatchReferenceFrame& reference, const KpStrip& strip, double x_m) {
  const double c = std::cos(strip.alpha_rad), s = std::sin(strip.alpha_rad);
  SurfaceFrame f;
  f.point_m = reference.point_m + x_m * reference.x_axis + strip.position_m.x() * reference.tangent +
              strip.position_m.y() * reference.normal;
  f.normal = c * reference.normal + s * reference.tangent;  // patch.hpp: alpha + towards +s
  f.lateral_tangent = c * reference.tangent - s * reference.normal;
  return f;
}

FastsimCreepages CreepagesAtSpinOrigin(const LocalRigidSlip& slip, double x_point_m, double s_point_m,
                                       double spin_origin_x_m, double spin_origin_s_m) {
  FastsimCreepages c;
  c.phi_per_m = slip.spin_per_m;
  c.xi = slip.slip_x + slip.spin_per_m * (s_point_m - spin_origin_s_m);
  c.eta = slip.slip_s - slip.spin_per_m * (x_point_m - spin_origin_x_m);
  return c;
}

std::vector<FastsimCreepages> StripCreepagesFromKinematics(const RigidBodyMotion& motion,
                                                           const PatchReferenceFrame& reference,
                                                           const KpResult& normal, double spin_origin_x_m,
                                                           double spin_origin_s_m) {
  std::vector<FastsimCreepages> out;
  out.reserve(normal.strips.size());
  for (const KpStrip& strip : normal.strips) {
    const LocalRigidSlip slip = RigidSlipAt(motion, StripSurfaceFrame(reference, strip, strip.x_centre_m));
    out.push_back(CreepagesAtSpinOrigin(slip, strip.x_centre_m, strip.s_m, spin_origin_x_m, spin_origin_s_m));
  }
  return out;
}

double ReferenceTangentialRotation(const RigidBodyMotion& motion, const PatchReferenceFrame& reference) {
  require_positive(motion.rolling_speed_m_per_s, "rolling_speed_m_per_s");
  return motion.angular_velocity_rad_per_s.dot(reference.normal.cross(reference.x_axis)) / motion.rolling_speed_m_per_s;
}

std::vector<FastsimCreepages> StripCreepagesFromReference(const ReferenceCreepages& reference,
                                                          const PatchGeometry& geometry, const KpResult& normal,
                                                          double spin_origin_x_m, double spin_origin_s_m) {
  require_finite(reference.xi, "xi");
  require_finite(reference.eta, "eta");
  require_finite(reference.phi_per_m, "phi_per_m");
  require_finite(reference.tangent_rotation_per_m, "tangent_rotation_per_m");
  require_positive(reference.reference_radius_m, "reference_radius_m");
  const size_t n = geometry.s_m.size();
  if (n == 0 || geometry.wheel_radius_m.size() != n || geometry.alpha_rad.size() != n)
    throw InputError("StripCreepagesFromReference: PatchGeometry needs s_m, wheel_radius_m, alpha_rad of equal size");
  std::vector<FastsimCreepages> out;
  out.reserve(normal.strips.size());
  for (const KpStrip& strip : normal.strips) {
    const double r = Interpolate(geometry.s_m, geometry.wheel_radius_m, strip.s_m);
    const double alpha = strip.alpha_rad;
    LocalRigidSlip slip;
    slip.slip_x = 1.0 - (1.0 - reference.xi) * r / reference.reference_radius_m;
    slip.slip_s = reference.eta * std::cos(alpha);
    slip.spin_per_m = reference.phi_per_m * std::cos(alpha) + reference.tangent_rotation_per_m * std::sin(alpha);
    out.push_back(CreepagesAtSpinOrigin(slip, strip.x_centre_m, strip.s_m, spin_origin_x_m, spin_origin_s_m));
  }
  return out;
}

}  // namespace conforma
