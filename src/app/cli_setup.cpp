#include <algorithm>
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
    app->add_option("--" + k + "-z-shift-mm", side->z_shift_mm,
                    k + " file: add this to every z [mm] (wheel: put z = 0 at the taping line, as the "
                        "nominal_radius warning measures it)");
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
  if (!std::isfinite(z_shift_mm)) throw InputError("option --wheel-z-shift-mm / --rail-z-shift-mm must be finite");
  o.z_shift_m = z_shift_mm * 1e-3;
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
  app->add_option("--exact-element-mm", exact_element_mm,
                  "exact model: BEM element size along x and along the rail profile (as CONTACT's 0.2 mm grid); the "
                  "grid may hold at most " + std::to_string(WheelContactOptions{}.exact_max_elements) + " elements");
  app->add_option("--combine-mm", combine_mm,
                  "patch grouping: interpenetration regions closer than this along the rail profile are solved as "
                  "one curved patch (CONTACT's D_COMB); 0 keeps every region a separate patch");
  app->add_option("--penetration", penetration, "conformal model: virtual penetration rule, variable (KPEC) or "
                                                "constant (eps = 0.55)")
      ->check(CLI::IsMember({"variable", "constant"}));
  app->add_option("--load-balance", load_balance,
                  "load control: balance the load with the wheel's total vertical force, pressure and creep forces "
                  "(total, default), or with the pressure forces alone (pressure, the creep forces solved afterwards), or "
                  "total with the patches found for the load the pressure forces carry (total-consistent, a fixed point; "
                  "docs/physics-reference.md §3.6.1)")
      ->check(CLI::IsMember({"total", "pressure", "total-consistent"}));
  app->add_option("--friction-law", friction_law,
                  "slip-dependent friction law mu(gamma), gamma = slip / rolling speed (paper 002): constant (mu); "
                  "exponential (f1a: mu [r + (1 - r) exp(-decay gamma)]); piecewise-linear (f1b: from mu down to "
                  "--mu-dynamic at --critical-slip); static-dynamic (f2: mu exp(-decay gamma) + mu_d (1 - exp(-rise "
                  "gamma))). --mu is the static value mu(0)");
  app->add_option("--mu-dynamic", mu_dynamic, "friction law: dynamic (sliding) friction coefficient mu_d "
                                              "(piecewise-linear, static-dynamic)");
  app->add_option("--mu-ratio", mu_ratio, "friction law exponential: ratio r = mu(infinite slip) / mu, in [0, 1]");
  app->add_option("--slip-decay", slip_decay, "friction law exponential, static-dynamic: decay rate of the static "
                                              "part per unit slip");
  app->add_option("--slip-rise", slip_rise, "friction law static-dynamic: rise rate of the dynamic part per unit slip");
  app->add_option("--critical-slip", critical_slip, "friction law piecewise-linear: slip gamma_c (> 0) where mu "
                                                    "reaches --mu-dynamic");
}

FrictionLaw ContactArgs::friction_law_from_options() const {
  struct LawName {
    const char* name;
    const char* paper_name;
    FrictionLawKind kind;
  };
  static const LawName kLaws[] = {{"constant", "constant", FrictionLawKind::Constant},
                                  {"exponential", "f1a", FrictionLawKind::F1aExponential},
                                  {"piecewise-linear", "f1b", FrictionLawKind::F1bPiecewise},
                                  {"static-dynamic", "f2", FrictionLawKind::F2}};
  const LawName* law = nullptr;
  for (const LawName& l : kLaws)
    if (friction_law == l.name || friction_law == l.paper_name) law = &l;
  if (law == nullptr)
    throw InputError("option --friction-law: unknown law '" + friction_law +
                     "' (expected constant, exponential, piecewise-linear or static-dynamic)");
  // the parameters of each law, in the order of FrictionLaw::parameters (friction_law.hpp)
  struct Parameter {
    const char* option;
    const std::optional<double>* value;
  };
  const double mu = friction;
  std::vector<Parameter> needed;
  needed.reserve(3);  // (also keeps GCC 12's -Wnonnull false positive on assigning to an empty vector away)
  switch (law->kind) {
    case FrictionLawKind::Constant: break;
    case FrictionLawKind::F1aExponential: needed = {{"--mu-ratio", &mu_ratio}, {"--slip-decay", &slip_decay}}; break;
    case FrictionLawKind::F1bPiecewise: needed = {{"--mu-dynamic", &mu_dynamic}, {"--critical-slip", &critical_slip}}; break;
    case FrictionLawKind::F2:
      needed = {{"--slip-decay", &slip_decay}, {"--mu-dynamic", &mu_dynamic}, {"--slip-rise", &slip_rise}};
      break;
  }
  const Parameter all[] = {{"--mu-dynamic", &mu_dynamic}, {"--mu-ratio", &mu_ratio}, {"--slip-decay", &slip_decay},
                           {"--slip-rise", &slip_rise}, {"--critical-slip", &critical_slip}};
  std::string list = "--mu";
  for (const Parameter& p : needed) list += std::string(", ") + p.option;
  for (const Parameter& p : all) {
    bool used = false;
    for (const Parameter& q : needed) used |= q.value == p.value;
    if (p.value->has_value() && !used)
      throw InputError(std::string("option ") + p.option + " is not a parameter of --friction-law " + law->name +
                       " (its parameters: " + list + ")");
  }
  for (const Parameter& p : needed) {
    if (!p.value->has_value())
      throw InputError(std::string("--friction-law ") + law->name + " needs " + p.option + " (its parameters: " +
                       list + ")");
    require_non_negative(**p.value, p.option);
  }
  require_non_negative(mu, "--mu");
  FrictionLaw out;
  switch (law->kind) {
    case FrictionLawKind::Constant: out = FrictionLaw::Constant(mu); break;
    case FrictionLawKind::F1aExponential:
      if (*mu_ratio > 1.0)
        throw InputError("option --mu-ratio must be in [0, 1] (got " + MessageNumber(*mu_ratio) + ")");
      out = FrictionLaw::F1a(mu, *mu_ratio, *slip_decay);
      break;
    case FrictionLawKind::F1bPiecewise:
      require_positive(*critical_slip, "--critical-slip");
      out = FrictionLaw::F1b(mu, *mu_dynamic, *critical_slip);
      break;
    case FrictionLawKind::F2: out = FrictionLaw::F2(mu, *slip_decay, *mu_dynamic, *slip_rise); break;
  }
  out.validate();
  return out;
}

WheelContactOptions ContactArgs::options() const {
  require_positive(speed_m_s, "--speed");  // (before any output: the creepages divide by it)
  WheelContactOptions o;
  o.model = ParseContactModel(model);
  if (load_N == 0.0)  // (the library's unloaded wheel: no contact to report; fuzzing, session 24)
    throw InputError("option --load-N 0: an unloaded wheel has no contact; give a load > 0 N, or a negative value "
                     "for the pose as given (approach mode, --approach-mm)");
  o.vertical_load_N = load_N;
  o.friction_coefficient = friction;
  o.friction_law = friction_law_from_options();  // constant: friction_coefficient applies
  o.material.shear_modulus_Pa = shear_modulus_GPa * 1e9;
  o.material.poisson_ratio = poisson;
  o.fastsim_elements = grid;
  o.exact_element_size_m = exact_element_mm * 1e-3;
  o.conformal_variable_penetration = penetration == "variable";
  o.patch_combine_distance_m = combine_mm * 1e-3;
  o.load_balance = ParseLoadBalance(load_balance);
  o.validate();
  return o;
}

std::vector<std::string> SplitCommaList(const std::string& text, const std::string& option) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  std::stringstream ss(text + ",");  // (a trailing "," is an empty last item)
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) throw InputError("option " + option + ": an empty name in the list '" + text + "'");
    if (std::find(out.begin(), out.end(), item) != out.end())  // (run twice before: fuzzing, session 25)
      throw InputError("option " + option + ": '" + item + "' is given twice in '" + text + "'");
    out.push_back(item);
  }
  return out;
}

}  // namespace conforma::cli
