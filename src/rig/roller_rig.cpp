// Roller-rig set-up, profiles and track (roller_rig.hpp; paper 000 §2.1, §4, Table 1).
#include "conforma/roller_rig.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/similitude.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma {

namespace {
constexpr double kMaxRollerRadius_m = 10.0;
}  // namespace

void RollerRigSetup::validate() const {
  require_positive(roller_radius_m, "RollerRigSetup.roller_radius_m");
  if (roller_radius_m > kMaxRollerRadius_m)  // (1e300 gave a wear depth of 4e288 m: fuzzing, session 25)
    throw InputError("RollerRigSetup.roller_radius_m = " + MessageNumber(roller_radius_m) +
                     " m is beyond 10 m: not a rig's roller (unit?)");
  require_positive(wheel_radius_m, "RollerRigSetup.wheel_radius_m");
  require_positive(wheelset_mass_kg, "RollerRigSetup.wheelset_mass_kg");
  require_positive(inertia_x_kg_m2, "RollerRigSetup.inertia_x_kg_m2");
  require_positive(inertia_y_kg_m2, "RollerRigSetup.inertia_y_kg_m2");
  require_positive(inertia_z_kg_m2, "RollerRigSetup.inertia_z_kg_m2");
  require_positive(length_factor, "RollerRigSetup.length_factor");
  require_positive(longitudinal_stiffness_N_per_m, "RollerRigSetup.longitudinal_stiffness_N_per_m");
  require_positive(spring_half_spacing_m, "RollerRigSetup.spring_half_spacing_m");
  require_non_negative(wheel_conicity_rad, "RollerRigSetup.wheel_conicity_rad");
  if (wheel_conicity_rad > 0.2) throw InputError("RollerRigSetup.wheel_conicity_rad must be <= 0.2 rad");
  require_positive(wheel_width_field_m, "RollerRigSetup.wheel_width_field_m");
  if (wheel_profile.empty()) throw InputError("RollerRigSetup.wheel_profile is empty");
  if (roller_profile.empty()) throw InputError("RollerRigSetup.roller_profile is empty");
  wheel_material.validate();
  roller_material.validate();
}

namespace {

SimilitudeOptions LengthScale(const RollerRigSetup& s) {
  SimilitudeOptions o;
  o.length_factor = s.length_factor;
  return o;
}

// Every point of a full-scale profile times the length factor (similitude.hpp, Length), refitted at the scaled spacing.
Profile ScaledProfile(const Profile& full, ProfileKind kind, const RollerRigSetup& s, const std::string& source) {
  const SimilitudeOptions o = LengthScale(s);
  std::vector<Eigen::Vector2d> pts = full.samples();
  for (Eigen::Vector2d& p : pts)
    p = Eigen::Vector2d(ScaleToModel(p.x(), SimilitudeQuantity::Length, o), ScaleToModel(p.y(), SimilitudeQuantity::Length, o));
  ProfileFitOptions fit;
  fit.sample_spacing_m = full.spacing() * s.length_factor;
  fit.function_of_y = false;
  return Profile::FromPoints(std::move(pts), kind, fit, source);
}

ProfileFitOptions RigFit(const RollerRigSetup& s) {
  ProfileFitOptions fit;
  fit.sample_spacing_m = 0.1e-3 * s.length_factor;
  return fit;
}

}  // namespace

Profile MakeRollerRigWheelProfile(const RollerRigSetup& s) {
  s.validate();
  if (s.wheel_profile == "conical") {
    // paper 000 §4: conical wear-test wheel, conicity 0.036 rad; radius decreasing towards the field side
    const double y0 = -0.070 * s.length_factor, y1 = s.wheel_width_field_m;
    const double t = std::tan(s.wheel_conicity_rad);
    const int n = static_cast<int>(std::ceil((y1 - y0) / (0.1e-3 * s.length_factor)));
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i <= n; ++i) {
      const double y = y0 + (y1 - y0) * i / n;
      pts.emplace_back(y, -t * y);
    }
    return Profile::FromPoints(std::move(pts), ProfileKind::Wheel, RigFit(s), "conical wheel (paper 000 §4)");
  }
  if (s.wheel_profile == "s1002") return ScaledProfile(MakeS1002(), ProfileKind::Wheel, s, "S1002 scaled");
  ProfileReadOptions read;
  read.kind = ProfileKind::Wheel;
  read.fit = RigFit(s);
  return LoadProfile(s.wheel_profile, read);
}

Profile MakeRollerRigRollerProfile(const RollerRigSetup& s) {
  s.validate();
  if (s.roller_profile == "uic60_1in20")
    return ScaledProfile(MakeRail(RailSection::R60E1, rail_inclination_1in20()), ProfileKind::Rail, s,
                         "60E1 1:20 scaled");
  ProfileReadOptions read;
  read.kind = ProfileKind::Rail;
  read.fit = RigFit(s);
  return LoadProfile(s.roller_profile, read);
}

TrackSetup MakeRollerRigTrack(const RollerRigSetup& s, std::array<Profile, 2> wheel, std::array<Profile, 2> roller) {
  s.validate();
  const SimilitudeOptions o = LengthScale(s);
  auto L = [&](double full) { return ScaleToModel(full, SimilitudeQuantity::Length, o); };
  TrackSetup t;
  t.gauge_m = L(1.435);
  t.gauge_height_m = L(0.014);
  t.flange_back_distance_m = L(1.360);
  t.flange_back_position_m = L(-0.070);
  t.nominal_radius_m = {s.wheel_radius_m, s.wheel_radius_m};
  t.rail_inclination_rad = 0.0;  // the roller profile is canted already
  t.wheel = std::move(wheel);
  t.rail = std::move(roller);
  t.roller_radius_m = {s.roller_radius_m, s.roller_radius_m};
  t.validate();
  return t;
}

GeometryOptions RollerRigGeometryOptions(const RollerRigSetup& s) {
  GeometryOptions g;
  g.table_spacing_m *= s.length_factor;
  g.scan_spacing_m *= s.length_factor;
  g.candidate_window_m *= s.length_factor;
  return g;
}

}  // namespace conforma
