#include <sstream>
#include "cli_setup.hpp"

#include <cmath>
#include <filesystem>

#include "conforma/error.hpp"
#include "conforma/profile_by_name.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma::cli {

double ParseInclination(const std::string& text) {
  if (text == "0" || text == "none") return 0.0;
  const auto colon = text.find_first_of(":/");
  try {
    if (colon != std::string::npos) {
      const double a = std::stod(text.substr(0, colon)), b = std::stod(text.substr(colon + 1));
      if (a >= 0 && b > 0) return std::atan(a / b);
    } else {
      size_t used = 0;
      const double v = std::stod(text, &used);
      if (used == text.size() && std::isfinite(v) && std::fabs(v) < 0.2) return v;
    }
  } catch (const std::exception&) {
  }
  throw InputError("option --inclination: cannot read '" + text + "' (expected 1:40, 1:20, 0 or radians)");
}

void TrackArgs::add_to(CLI::App* app) {
  app->add_option("--wheel", wheel, "wheel profile: S1002 or a file (.prw .whl .csv .txt)");
  app->add_option("--rail", rail, std::string("rail profile: ") + BuiltInRailNames() + " or a file (.prr .ban .csv .txt)");
  app->add_option("--inclination", inclination, "rail inclination applied by the track (1:40, 1:20, 0); "
                                                "default 1:40 for built-in rails, 0 for files (already canted)");
  app->add_option("--gauge-mm", gauge_mm, "track gauge");
  app->add_option("--gauge-height-mm", gauge_height_mm, "gauge measuring height below the rail top");
  app->add_option("--flange-back-mm", flange_back_mm, "flange-back distance");
  app->add_option("--flange-back-position-mm", flange_back_position_mm, "wheel-profile y of the flange back");
  app->add_option("--r0-mm", nominal_radius_mm, "nominal (taping-line) wheel radius");
  for (auto* side : {&wheel_file, &rail_file}) {
    const std::string k = side == &wheel_file ? "wheel" : "rail";
    app->add_flag("--" + k + "-mirror", side->mirror, k + " file stored mirrored in y: y := -y");
    app->add_flag("--" + k + "-z-down", side->z_down,
                  k + " file with z pointing the other way (" +
                      (k == "wheel" ? "flange tip at negative z" : "rail head upside down") + "): z := -z");
    app->add_option("--" + k + "-units", side->units, k + " plain column file: length unit")
        ->check(CLI::IsMember({"mm", "m"}));
    app->add_option("--" + k + "-smooth-mm", side->smooth_mm,
                    k + " file: smooth noisy points, RMS distance of the fit to the points [mm] (the noise level)");
    app->add_option("--" + k + "-format", side->format, k + " file format instead of the extension's")
        ->check(CLI::IsMember({"auto", "simpack", "miniprof", "columns"}));
  }
}

ProfileReadOptions TrackArgs::FileOptions::read_options() const {
  ProfileReadOptions o;
  o.mirror_y = mirror;
  o.mirror_z = z_down;
  if (units == "m") o.length_unit_m = 1.0;
  else if (units != "mm") throw InputError("profile units must be mm or m, got '" + units + "'");
  if (!(std::isfinite(smooth_mm) && smooth_mm >= 0 && smooth_mm <= 1.0))
    throw InputError("profile smoothing must be between 0 and 1 mm (the noise level of the points)");
  o.fit.smoothing_rms_m = smooth_mm * 1e-3;
  o.format = ParseProfileFormat(format);
  return o;
}

std::unique_ptr<WheelsetTrackGeometry> TrackArgs::make_geometry() const {
  const Profile wheel_profile = WheelProfileByNameOrFile(wheel, "option --wheel", {}, wheel_file.read_options());
  bool built_in = false;
  const Profile rail_profile = RailProfileByNameOrFile(rail, &built_in, "option --rail", {}, rail_file.read_options());
  // built-in rails are uninclined: the track cants them (1:40 by default); files are taken as measured (canted)
  const double incl = inclination.empty() ? (built_in ? rail_inclination_1in40() : 0.0) : ParseInclination(inclination);
  TrackSetup setup = MakeSymmetricTrack(wheel_profile, rail_profile, incl);
  setup.gauge_m = gauge_mm * 1e-3;
  setup.gauge_height_m = gauge_height_mm * 1e-3;
  setup.flange_back_distance_m = flange_back_mm * 1e-3;
  setup.flange_back_position_m = flange_back_position_mm * 1e-3;
  setup.nominal_radius_m = {nominal_radius_mm * 1e-3, nominal_radius_mm * 1e-3};
  setup.validate();
  return std::make_unique<WheelsetTrackGeometry>(std::move(setup));
}

void ContactArgs::add_to(CLI::App* app) {
  app->add_option("--model", model, "contact model: " + ContactModelNames());
  app->add_option("--load-N", load_N, "vertical load per wheel (load control); negative: use the pose as given");
  app->add_option("--speed", speed_m_s, "forward speed [m/s]");
  app->add_option("--mu", friction, "friction coefficient");
  app->add_option("--G-GPa", shear_modulus_GPa, "shear modulus of wheel and rail");
  app->add_option("--nu", poisson, "Poisson ratio");
  app->add_option("--grid", grid, "FASTSIM elements per strip");
  app->add_option("--penetration", penetration, "conformal model: virtual penetration rule, variable (KPEC) or "
                                                "constant (eps = 0.55)")
      ->check(CLI::IsMember({"variable", "constant"}));
}

WheelContactOptions ContactArgs::options() const {
  WheelContactOptions o;
  o.model = ParseContactModel(model);
  o.vertical_load_N = load_N;
  o.friction_coefficient = friction;
  o.material.shear_modulus_Pa = shear_modulus_GPa * 1e9;
  o.material.poisson_ratio = poisson;
  o.fastsim_elements = grid;
  o.conformal_variable_penetration = penetration == "variable";
  o.validate();
  return o;
}

std::vector<std::string> SplitCommaList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace conforma::cli
