#pragma once
// Shared by the C API (conforma_c.cpp) and the Python module (python/conforma_module.cpp): building the track
// from profile names/files as the command line does (src/app/cli_setup.cpp), the `conforma contact` evaluation
// sequence, and the conversion of a wheel's patch forces from its side frame to the track frame.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conforma/geometry.hpp"
#include "conforma/profile_by_name.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma::interop {

// A C string into the caller's buffer of `size` bytes, cut to fit and always terminated (nothing when buffer is
// NULL or size is 0): the C API's error and warning texts.
void CopyText(const std::string& text, char* buffer, size_t size);

struct TrackSpec {
  std::string wheel = "S1002";
  std::string rail = "60E1";
  std::optional<double> inclination_rad;  // default: 1:40 for built-in rails, 0 for files (already canted)
  double gauge_m = 1.435, gauge_height_m = 0.014, flange_back_distance_m = 1.360, flange_back_position_m = -0.070;
  double nominal_radius_m = 0.46;
};
// Same construction as `conforma contact --wheel ... --rail ...` (TrackArgs::make_geometry). InputError on bad input.
std::unique_ptr<WheelsetTrackGeometry> MakeTrackGeometry(const TrackSpec& spec);
// As above with profiles already in memory (inclination applied to the rail profile as given).
std::unique_ptr<WheelsetTrackGeometry> MakeTrackGeometry(const Profile& wheel, const Profile& rail,
                                                         double inclination_rad, const TrackSpec& dimensions);

// The evaluation sequence of `conforma contact` (src/app/cmd_contact.cpp): rigid equilibrium at (y, yaw), the
// roll replaced when given, lowered by approach_m in approach mode (options.vertical_load_N < 0), forward speed
// V with pure rolling at the left nominal radius; the wheels of `sides` in order.
struct CliContactInput {
  double lateral_m = 0.0, yaw_rad = 0.0;
  std::optional<double> roll_rad;
  double approach_m = 0.05e-3;
  double speed_m_s = 2.0;
  std::vector<Side> sides{Side::Left, Side::Right};
};
std::vector<WheelContactReport> SolveLikeCli(const WheelsetTrackGeometry& geometry, const CliContactInput& input,
                                             const WheelContactOptions& options);

// One patch in the track frame (geometry.hpp: track y = sigma * side-frame eta; moments are axial vectors).
struct TrackFramePatch {
  Eigen::Vector3d force_N, spin_moment_Nm, point_m, normal;
};
TrackFramePatch ToTrackFrame(const WheelsetTrackGeometry& geometry, Side side, const PatchReport& patch);
// Centre of the wheel (axle point in the taping-line plane) in the track frame at `pose`.
Eigen::Vector3d WheelCentre(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose);

}  // namespace conforma::interop
