// Track construction, the `conforma contact` sequence and track-frame conversion shared by the C API and the
// Python module (interop.hpp).
#include "interop.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "conforma/error.hpp"
#include "conforma/profile_by_name.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma::interop {

void CopyText(const std::string& text, char* buffer, size_t size) {
  if (!buffer || size == 0) return;
  const size_t n = text.size() < size - 1 ? text.size() : size - 1;
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\0';
}

std::unique_ptr<WheelsetTrackGeometry> MakeTrackGeometry(const Profile& wheel, const Profile& rail,
                                                         double inclination_rad, const TrackSpec& d) {
  require_non_negative(inclination_rad, "rail inclination");
  TrackSetup setup = MakeSymmetricTrack(wheel, rail, inclination_rad);
  setup.gauge_m = d.gauge_m;
  setup.gauge_height_m = d.gauge_height_m;
  setup.flange_back_distance_m = d.flange_back_distance_m;
  setup.flange_back_position_m = d.flange_back_position_m;
  setup.nominal_radius_m = {d.nominal_radius_m, d.nominal_radius_m};
  setup.validate();
  return std::make_unique<WheelsetTrackGeometry>(std::move(setup));
}

std::unique_ptr<WheelsetTrackGeometry> MakeTrackGeometry(const TrackSpec& spec) {
  const Profile wheel = WheelProfileByNameOrFile(spec.wheel);
  bool built_in = false;
  const Profile rail = RailProfileByNameOrFile(spec.rail, &built_in);
  const double inclination = spec.inclination_rad ? *spec.inclination_rad : built_in ? rail_inclination_1in40() : 0.0;
  return MakeTrackGeometry(wheel, rail, inclination, spec);
}

std::vector<WheelContactReport> SolveLikeCli(const WheelsetTrackGeometry& geometry, const CliContactInput& in,
                                             const WheelContactOptions& options) {
  options.validate();
  require_finite(in.lateral_m, "lateral position");
  RequireWheelsetYaw(in.yaw_rad, "yaw angle");
  if (in.roll_rad) require_finite(*in.roll_rad, "roll angle");
  RequireApproach(in.approach_m, "approach");
  const EquilibriumResult eq = geometry.SolveRigidEquilibrium(in.lateral_m, in.yaw_rad);
  if (eq.status == EquilibriumStatus::NoContact) {
    char text[200];
    std::snprintf(text, sizeof text, "no rigid contact at lateral position %g m, yaw %g rad: the wheels do not reach "
                  "the rails (check the position, the yaw, the gauge and the profiles)", in.lateral_m, in.yaw_rad);
    throw InputError(text);
  }
  WheelsetPose pose = eq.pose;
  if (in.roll_rad) pose.roll_rad = *in.roll_rad;
  if (options.vertical_load_N < 0.0) pose.vertical_m -= in.approach_m;  // approach mode
  const double r0 = geometry.setup().nominal_radius_m[0];
  const WheelsetVelocity velocity{in.speed_m_s, 0.0, 0.0, in.speed_m_s / r0};
  std::vector<WheelContactReport> out;
  for (Side s : in.sides) out.push_back(SolveWheelContact(geometry, s, pose, velocity, options));
  return out;
}

TrackFramePatch ToTrackFrame(const WheelsetTrackGeometry& geometry, Side side, const PatchReport& p) {
  const double sigma = side_sign(side);
  const Eigen::Vector3d mirror(1.0, sigma, 1.0);  // side frame (x, eta, z) -> track frame (x, y, z)
  // outward rail normal in the side frame: contact angle + towards the gauge side (-eta)
  const Eigen::Vector3d normal_side(0.0, -std::sin(p.contact_angle_rad), std::cos(p.contact_angle_rad));
  const Eigen::Vector3d force_side(p.fx_N, p.lateral_force_N, p.vertical_force_N);
  const Eigen::Vector3d point_side(p.lead_m, geometry.rail_origin_eta_m(side) + p.y_contact_rail_m, p.z_contact_rail_m);
  TrackFramePatch t;
  t.force_N = mirror.cwiseProduct(force_side);
  t.point_m = mirror.cwiseProduct(point_side);
  t.normal = mirror.cwiseProduct(normal_side);
  // an axial vector changes sign under the reflection eta -> -eta: M_track = det(T) T M_side
  t.spin_moment_Nm = sigma * mirror.cwiseProduct(p.mz_Nm * normal_side);
  return t;
}

Eigen::Vector3d WheelCentre(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose) {
  const WheelsetTrackGeometry::Frame f = geometry.SideFrame(side, pose);
  const Eigen::Vector3d centre_side = f.centre + f.rotation * Eigen::Vector3d(0.0, geometry.wheel_origin_eta_m(), 0.0);
  return Eigen::Vector3d(1.0, side_sign(side), 1.0).cwiseProduct(centre_side);
}

}  // namespace conforma::interop
