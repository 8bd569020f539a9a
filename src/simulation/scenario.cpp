// Scenario file reader (scenario.hpp): YAML -> Scenario, with unknown keys and bad values reported by name.
#include "conforma/scenario.hpp"

#include <filesystem>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "conforma/data_paths.hpp"
#include "conforma/error.hpp"
#include "conforma/profile_by_name.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wear_law.hpp"
#include "conforma/yaml_keys.hpp"

namespace conforma {

const char* to_string(KinematicsProvider provider) {
  switch (provider) {
    case KinematicsProvider::QuasiStatic: return "quasistatic";
    case KinematicsProvider::Centred: return "centred";
    case KinematicsProvider::Kinematic: return "kinematic";
    case KinematicsProvider::Dynamic: return "dynamic";
  }
  return "?";
}

namespace {

struct Reader {
  std::string source;
  std::string base_dir;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw InputError(source + ": " + where + ": " + what);
  }
  void check_keys(const YAML::Node& map, const std::string& where, const std::set<std::string>& allowed) const {
    CheckYamlKeys(map, source, where, allowed);
  }
  double number(const YAML::Node& n, const std::string& where) const {
    try {
      const double v = n.as<double>();
      if (!std::isfinite(v)) fail(where, "not a finite number");
      return v;
    } catch (const YAML::Exception&) {
      fail(where, "expected a number");
    }
  }
  int integer(const YAML::Node& n, const std::string& where) const {
    try {
      return n.as<int>();
    } catch (const YAML::Exception&) {
      fail(where, "expected an integer");
    }
  }
  bool boolean(const YAML::Node& n, const std::string& where) const {
    try {
      return n.as<bool>();
    } catch (const YAML::Exception&) {
      fail(where, "expected true or false");
    }
  }
  std::string text(const YAML::Node& n, const std::string& where) const {
    if (!n.IsScalar()) fail(where, "expected a text value");
    return n.as<std::string>();
  }
  std::string path(const std::string& p) const {
    static const std::string kDataPrefix = "$CONFORMA_DATA_DIR/";
    if (p.compare(0, kDataPrefix.size(), kDataPrefix) == 0) return SharedDataDir() + "/" + p.substr(kDataPrefix.size());
    if (p.empty() || p[0] == '/') return p;
    return base_dir + "/" + p;
  }
};

double ParseInclination(const Reader& r, const YAML::Node& n) {
  const std::string t = r.text(n, "track.rail_inclination");
  const auto colon = t.find(':');
  if (colon != std::string::npos) {
    double a = 0.0, b = 0.0;
    try {
      a = std::stod(t.substr(0, colon));
      b = std::stod(t.substr(colon + 1));
    } catch (const std::exception&) {
      r.fail("track.rail_inclination", "expected '1:N' or radians, got '" + t + "'");
    }
    if (!(a > 0 && b > 0)) r.fail("track.rail_inclination", "expected '1:N' with N > 0");
    return std::atan(a / b);
  }
  return r.number(n, "track.rail_inclination");
}

Profile BuiltInOrFileRail(const Reader& r, const std::string& name, const ProfileReadOptions& read) {
  return RailProfileByNameOrFile(name, nullptr, "rail profile", [&r](const std::string& f) { return r.path(f); }, read);
}

Profile BuiltInOrFileWheel(const Reader& r, const std::string& name, const ProfileReadOptions& read) {
  return WheelProfileByNameOrFile(name, "wheel profile", [&r](const std::string& f) { return r.path(f); }, read);
}

// profiles.<kind>_mirror, _z_down, _units (mm | m), _smoothing_mm, _format: how a profile file is read, as the
// command line's --wheel-mirror, --wheel-z-down, --wheel-units, --wheel-smooth-mm, --wheel-format.
ProfileReadOptions FileReadOptions(const Reader& r, const YAML::Node& p, const std::string& kind) {
  ProfileReadOptions o;
  if (!p) return o;
  const std::string k = "profiles." + kind;
  if (p[kind + "_mirror"]) o.mirror_y = r.boolean(p[kind + "_mirror"], k + "_mirror");
  if (p[kind + "_z_down"]) o.mirror_z = r.boolean(p[kind + "_z_down"], k + "_z_down");
  if (p[kind + "_units"]) {
    const std::string u = r.text(p[kind + "_units"], k + "_units");
    if (u == "m") o.length_unit_m = 1.0;
    else if (u != "mm") r.fail(k + "_units", "expected mm or m, got '" + u + "'");
  }
  if (p[kind + "_smoothing_mm"]) {
    const double v = r.number(p[kind + "_smoothing_mm"], k + "_smoothing_mm");
    if (!(v >= 0 && v <= 1.0)) r.fail(k + "_smoothing_mm", "must be between 0 and 1 mm (the noise level of the points)");
    o.fit.smoothing_rms_m = 1e-3 * v;
  }
  if (p[kind + "_format"]) {
    try {
      o.format = ParseProfileFormat(r.text(p[kind + "_format"], k + "_format"));
    } catch (const InputError& e) {
      r.fail(k + "_format", e.what());
    }
  }
  return o;
}

// Contact model by name (ParseContactModel), the error naming the key.
ContactModel ModelFromName(const Reader& r, const std::string& name, const std::string& where = "contact_model") {
  try {
    return ParseContactModel(name);
  } catch (const InputError& e) {
    r.fail(where, e.what());
  }
}

WearLaw LawFromName(const Reader& r, const std::string& name) {
  if (name == "usfd") return WearLaw{};
  const std::string path = r.path(name);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && name.find_first_of("./\\") == std::string::npos)
    throw InputError(path, 0, "no wear-law file; the built-in law is 'usfd', any other is a wear-law file (e.g. "
                              "profiles/wear_laws/archard_jendel.csv, format in include/conforma/wear_law.hpp)");
  return LoadWearLaw(path);
}

void ParseVehicle(const Reader& r, const YAML::Node& n, VehicleParameters* v) {
  if (!n.IsMap()) r.fail("vehicle", "expected a map");
  std::string base = "metro";
  if (n["base"]) base = r.text(n["base"], "vehicle.base");
  if (base == "metro") {
    *v = MetroVehicle();
  } else if (base == "minuetto" || base == "aln501") {
    *v = MinuettoVehicle();
  } else {
    r.fail("vehicle.base", "unknown vehicle '" + base + "' (metro, minuetto)");
  }
  const std::map<std::string, double*> fields = {
      {"wheelset_mass_kg", &v->wheelset_mass_kg},
      {"bogie_frame_mass_kg", &v->bogie_frame_mass_kg},
      {"carbody_mass_per_bogie_kg", &v->carbody_mass_per_bogie_kg},
      {"bogie_centre_distance_m", &v->bogie_centre_distance_m},
      {"wheelbase_m", &v->wheelbase_m},
      {"nominal_wheel_radius_m", &v->nominal_wheel_radius_m},
      {"primary_longitudinal_stiffness_N_m", &v->primary_longitudinal_stiffness_N_m},
      {"primary_lateral_stiffness_N_m", &v->primary_lateral_stiffness_N_m},
      {"lateral_axlebox_spacing_m", &v->lateral_axlebox_spacing_m},
      {"secondary_yaw_stiffness_Nm_rad", &v->secondary_yaw_stiffness_Nm_rad},
      {"secondary_lateral_stiffness_N_m", &v->secondary_lateral_stiffness_N_m},
      {"load_transfer_height_m", &v->load_transfer_height_m},
      {"contact_half_distance_m", &v->contact_half_distance_m}};
  std::set<std::string> seen;
  for (const auto& kv : n) {
    const std::string key = kv.first.as<std::string>();
    if (!seen.insert(key).second)
      r.fail("vehicle", "key '" + key + "' is given twice (line " + std::to_string(kv.first.Mark().line + 1) + ")");
    if (key == "base") continue;
    if (key == "name") {
      v->name = r.text(kv.second, "vehicle.name");
    } else if (key == "bogie_count") {
      v->bogie_count = r.integer(kv.second, "vehicle.bogie_count");
    } else if (fields.count(key)) {
      *fields.at(key) = r.number(kv.second, "vehicle." + key);
    } else {
      r.fail("vehicle", "unknown key '" + key + "'");
    }
  }
  try {
    v->validate();
  } catch (const InputError& e) {
    r.fail("vehicle", e.what());
  }
}

TrackClass ParseClass(const Reader& r, const YAML::Node& n, const std::string& where, double friction,
                      const VehicleParameters& vehicle) {
  r.check_keys(n, where,
               {"name", "radius_m", "cant_mm", "speed_kmh", "share", "friction", "acceleration_m_s2", "axle_torque_Nm"});
  TrackClass c;
  c.friction_coefficient = friction;
  if (n["name"]) c.name = r.text(n["name"], where + ".name");
  if (n["radius_m"]) c.curve_radius_m = r.number(n["radius_m"], where + ".radius_m");
  if (n["cant_mm"]) c.cant_m = 1e-3 * r.number(n["cant_mm"], where + ".cant_mm");
  if (!n["speed_kmh"]) r.fail(where, "missing speed_kmh");
  c.speed_m_s = r.number(n["speed_kmh"], where + ".speed_kmh") / 3.6;
  if (!n["share"]) r.fail(where, "missing share");
  c.share = r.number(n["share"], where + ".share");
  if (n["friction"]) c.friction_coefficient = r.number(n["friction"], where + ".friction");
  if (n["acceleration_m_s2"] && n["axle_torque_Nm"]) r.fail(where, "give acceleration_m_s2 or axle_torque_Nm, not both");
  if (n["axle_torque_Nm"]) c.axle_torque_Nm = r.number(n["axle_torque_Nm"], where + ".axle_torque_Nm");
  if (n["acceleration_m_s2"]) {
    // Every axle driven (braked) alike: the torque that accelerates the mass the axle carries, T = m a r0
    // (vehicle.hpp carried_mass_per_wheelset_kg, wheelset included; rotating inertia and running resistance
    // neglected; docs/physics-reference.md §12.3).
    const double a = r.number(n["acceleration_m_s2"], where + ".acceleration_m_s2");
    c.axle_torque_Nm = vehicle.carried_mass_per_wheelset_kg() * a * vehicle.nominal_wheel_radius_m;
  }
  if (c.name.empty()) c.name = c.curve_radius_m == 0.0 ? "tangent" : "R" + std::to_string(int(c.curve_radius_m));
  return c;
}

std::vector<TrackClass> ClassesFromCsv(const Reader& r, const YAML::Node& n, double friction) {
  r.check_keys(n, "track_classes_csv", {"file", "tangent_speed_kmh", "left_and_right"});
  if (!n["file"]) r.fail("track_classes_csv", "missing file");
  const std::string file = r.path(r.text(n["file"], "track_classes_csv.file"));
  double tangent_speed = 0.0;
  if (n["tangent_speed_kmh"]) tangent_speed = r.number(n["tangent_speed_kmh"], "track_classes_csv.tangent_speed_kmh") / 3.6;
  std::ifstream in(file);
  if (!in) throw InputError(file + ": cannot open track class file");
  std::vector<TrackClass> out;
  std::string line;
  int lineno = 0;
  bool header = false;
  double curve_share = 0.0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line.rfind("radius_m,cant_mm,speed_kmh,share_percent", 0) != 0)
        throw InputError(file + ":" + std::to_string(lineno) + ": expected header radius_m,cant_mm,speed_kmh,share_percent");
      header = true;
      continue;
    }
    std::stringstream ss(line);
    std::string f;
    std::vector<double> v;
    while (std::getline(ss, f, ',')) {
      try {
        v.push_back(std::stod(f));
      } catch (const std::exception&) {
        throw InputError(file + ":" + std::to_string(lineno) + ": non-numeric field '" + f + "'");
      }
    }
    if (v.size() != 4) throw InputError(file + ":" + std::to_string(lineno) + ": expected 4 fields");
    TrackClass c;
    c.curve_radius_m = v[0];
    c.cant_m = 1e-3 * v[1];
    c.speed_m_s = v[2] / 3.6;
    c.share = 0.01 * v[3];
    c.friction_coefficient = friction;
    c.name = "R" + std::to_string(int(v[0])) + "_h" + std::to_string(int(v[1])) + "_v" + std::to_string(int(v[2]));
    curve_share += c.share;
    out.push_back(c);
  }
  if (out.empty()) throw InputError(file + ": no track classes");
  if (curve_share < 1.0 - 1e-9) {
    if (!(tangent_speed > 0)) r.fail("track_classes_csv", "tangent_speed_kmh needed for the tangent remainder");
    TrackClass t;
    t.name = "tangent";
    t.speed_m_s = tangent_speed;
    t.share = 1.0 - curve_share;
    t.friction_coefficient = friction;
    out.insert(out.begin(), t);
  }
  return out;
}

// kinematics.dynamic (ScenarioDynamicKinematics); every bad value names its key.
void ParseDynamicKinematics(const Reader& r, const YAML::Node& n, ScenarioDynamicKinematics* d) {
  r.check_keys(n, "kinematics.dynamic",
               {"duration_s", "settle_s", "sample_interval_s", "stepper", "steps_per_s_max", "contact",
                "lut_creep", "stall_model", "irregularity"});
  if (n["duration_s"]) d->duration_s = r.number(n["duration_s"], "kinematics.dynamic.duration_s");
  if (!(d->duration_s > 0)) r.fail("kinematics.dynamic.duration_s", "must be > 0");
  if (n["settle_s"]) d->settle_s = r.number(n["settle_s"], "kinematics.dynamic.settle_s");
  if (!(d->settle_s >= 0)) r.fail("kinematics.dynamic.settle_s", "must be >= 0");
  if (n["sample_interval_s"]) d->sample_interval_s = r.number(n["sample_interval_s"], "kinematics.dynamic.sample_interval_s");
  if (!(d->sample_interval_s > 0 && d->sample_interval_s <= d->duration_s))
    r.fail("kinematics.dynamic.sample_interval_s", "must be > 0 and <= duration_s");
  if (n["stepper"]) d->stepper = r.text(n["stepper"], "kinematics.dynamic.stepper");
  if (d->stepper != "rosenbrock4" && d->stepper != "dopri5")
    r.fail("kinematics.dynamic.stepper", "unknown stepper '" + d->stepper + "' (rosenbrock4, dopri5)");
  if (n["steps_per_s_max"])
    d->steps_per_s_max = r.number(n["steps_per_s_max"], "kinematics.dynamic.steps_per_s_max");
  if (!(d->steps_per_s_max > 0 && std::isfinite(d->steps_per_s_max)))
    r.fail("kinematics.dynamic.steps_per_s_max", "must be > 0");
  if (n["contact"]) {
    const std::string c = r.text(n["contact"], "kinematics.dynamic.contact");
    if (c != "direct" && c != "lut") r.fail("kinematics.dynamic.contact", "unknown contact '" + c + "' (direct, lut)");
    d->lut_contact = c == "lut";
  }
  if (n["lut_creep"]) {
    if (!d->lut_contact) r.fail("kinematics.dynamic.lut_creep", "only with contact: lut");
    d->lut_creep = r.text(n["lut_creep"], "kinematics.dynamic.lut_creep");
    if (d->lut_creep != "polach" && d->lut_creep != "fastsim")
      r.fail("kinematics.dynamic.lut_creep", "unknown creep force '" + d->lut_creep + "' (polach, fastsim)");
  }
  if (n["stall_model"]) {
    if (!d->lut_contact) r.fail("kinematics.dynamic.stall_model", "only with contact: lut");
    d->stall_model = r.text(n["stall_model"], "kinematics.dynamic.stall_model");
    if (d->stall_model != "auto" && d->stall_model != "none")
      r.fail("kinematics.dynamic.stall_model", "unknown model '" + d->stall_model + "' (auto, none)");
  }
  if (const YAML::Node i = n["irregularity"]) {
    if (i.IsScalar()) {
      if (r.text(i, "kinematics.dynamic.irregularity") != "none")
        r.fail("kinematics.dynamic.irregularity", "expected `none` or a map {spectrum, seed, wavelength_min_m, wavelength_max_m}");
      d->irregularity = false;
      return;
    }
    r.check_keys(i, "kinematics.dynamic.irregularity", {"spectrum", "seed", "wavelength_min_m", "wavelength_max_m"});
    d->irregularity = true;
    if (i["spectrum"]) {
      try {
        d->spectrum = ParseIrregularitySpectrum(r.text(i["spectrum"], "kinematics.dynamic.irregularity.spectrum"));
      } catch (const InputError& e) {
        r.fail("kinematics.dynamic.irregularity.spectrum", e.what());
      }
    }
    if (i["seed"]) {
      long long seed = -1;
      try {
        seed = i["seed"].as<long long>();
      } catch (const YAML::Exception&) {
        r.fail("kinematics.dynamic.irregularity.seed", "expected a non-negative integer");
      }
      if (seed < 0) r.fail("kinematics.dynamic.irregularity.seed", "expected a non-negative integer");
      d->seed = static_cast<std::uint64_t>(seed);
    }
    if (i["wavelength_min_m"]) d->wavelength_min_m = r.number(i["wavelength_min_m"], "kinematics.dynamic.irregularity.wavelength_min_m");
    if (i["wavelength_max_m"]) d->wavelength_max_m = r.number(i["wavelength_max_m"], "kinematics.dynamic.irregularity.wavelength_max_m");
    if (!(d->wavelength_min_m > 0)) r.fail("kinematics.dynamic.irregularity.wavelength_min_m", "must be > 0");
    if (!(d->wavelength_max_m >= d->wavelength_min_m))
      r.fail("kinematics.dynamic.irregularity.wavelength_max_m", "must be >= wavelength_min_m");
  }
}

// ranges of a railway line, checked by Scenario::validate
constexpr double kMaxClassSpeed_m_s = 600.0 / 3.6;  // (the rail speed record: 575 km/h)
constexpr double kMaxCantPerGauge = 0.2;             // 287 mm on 1435 mm: above any line's cant
constexpr double kMaxClassAcceleration_m_s2 = 5.0;   // ~ mu g with mu = 0.5
constexpr double kMaxTangentAmplitude_m = 0.1;       // (flangeway clearance ~5-10 mm, flange ~30 mm high)
constexpr int kMaxTangentPhases = 1000;
constexpr int kMaxRailSteps = 1000;  // rail.steps (a typo of 1e9 ran a wheel sequence per rail step for ever)

}  // namespace

void Scenario::validate() const {
  const std::string where = source + ": ";
  vehicle.validate();
  material.validate();
  wear.wheel_law.validate();
  wear.rail_law.validate();
  if (classes.empty()) throw InputError(where + "no track classes");
  double sum = 0.0;
  for (const TrackClass& c : classes) {
    if (!(c.speed_m_s > 0)) throw InputError(where + "track class " + c.name + ": speed must be > 0");
    // ranges of a railway line (fuzzing, session 24: 1e6 km/h, 5 m of cant and 100 m/s^2 ran with exit 0 or 5)
    char text[260];
    if (c.speed_m_s > kMaxClassSpeed_m_s) {
      std::snprintf(text, sizeof text, "track class %s: speed_kmh = %g is beyond a railway's %g km/h (unit?)",
                    c.name.c_str(), c.speed_m_s * 3.6, kMaxClassSpeed_m_s * 3.6);
      throw InputError(where + text);
    }
    if (!(std::abs(c.cant_m) <= kMaxCantPerGauge * gauge_m)) {
      std::snprintf(text, sizeof text,
                    "track class %s: cant_mm = %g is more than %g of the %g mm gauge (track cant is at most ~180 mm "
                    "on standard gauge; unit?)",
                    c.name.c_str(), c.cant_m * 1e3, kMaxCantPerGauge, gauge_m * 1e3);
      throw InputError(where + text);
    }
    const double accel = c.axle_torque_Nm / (vehicle.carried_mass_per_wheelset_kg() * vehicle.nominal_wheel_radius_m);
    if (std::abs(accel) > kMaxClassAcceleration_m_s2) {
      std::snprintf(text, sizeof text,
                    "track class %s: the drive torque %g N m accelerates the vehicle by %g m/s^2, more than the %g "
                    "m/s^2 that adhesion (mu g) can give",
                    c.name.c_str(), c.axle_torque_Nm, accel, kMaxClassAcceleration_m_s2);
      throw InputError(where + text);
    }
    if (!(c.share >= 0)) throw InputError(where + "track class " + c.name + ": share must be >= 0");
    if (!(c.friction_coefficient > 0)) throw InputError(where + "track class " + c.name + ": friction must be > 0");
    if (!std::isfinite(c.axle_torque_Nm)) throw InputError(where + "track class " + c.name + ": axle torque not finite");
    if (c.axle_torque_Nm != 0.0 && (!kinematics.free_axle_rotation ||
                                    (kinematics.provider != KinematicsProvider::QuasiStatic &&
                                     kinematics.provider != KinematicsProvider::Dynamic)))
      throw InputError(where + "track class " + c.name +
                       ": a drive torque (acceleration_m_s2 / axle_torque_Nm) needs the quasistatic or dynamic "
                       "provider with free_axle_rotation (the others impose the axle speed)");
    sum += c.share;
  }
  if (std::abs(sum - 1.0) > 1e-9) throw InputError(where + "track class shares do not sum to 1");
  if (!(update.cap_m > 0)) throw InputError(where + "update.cap_mm must be > 0");
  if (!(update.smoothing_cutoff_m >= 0)) throw InputError(where + "update.smoothing_mm must be >= 0");
  if (update.steps < 1) throw InputError(where + "update.steps must be >= 1");
  if (update.substeps < 1 || update.substeps > 100)
    throw InputError(where + "update.substeps must lie in [1, 100], got " + std::to_string(update.substeps));
  if (!(update.total_km >= 0)) throw InputError(where + "update.total_km must be >= 0");
  if (!rail_steps.fixed && rail_steps.steps < 1) throw InputError(where + "rail.steps must be >= 1 when rail.fixed is false");
  // each rail step runs the whole wheel sequence from the new wheel (paper 003 Fig. 11: 10 rail steps)
  if (!rail_steps.fixed && rail_steps.steps > kMaxRailSteps)
    throw InputError(where + "rail.steps = " + std::to_string(rail_steps.steps) + ": at most " +
                     std::to_string(kMaxRailSteps) + " (each rail step runs the whole wheel sequence again)");
  if (!(rail_steps.cap_m > 0)) throw InputError(where + "rail.cap_mm must be > 0");
  if (!(rail_steps.output_spacing_m >= 0 && rail_steps.output_spacing_m <= 1e-3))
    throw InputError(where + "rail.spacing_mm must be in [0, 1] (0: the spacing of the rail before the step)");
  if (kinematics.tangent_phases < 1 || kinematics.tangent_phases > kMaxTangentPhases)  // (1e8 ran for days)
    throw InputError(where + "kinematics.tangent_phases must lie in [1, " + std::to_string(kMaxTangentPhases) + "]");
  if (!(kinematics.tangent_amplitude_m <= kMaxTangentAmplitude_m))
    throw InputError(where + "kinematics.tangent_amplitude_mm must be <= " + std::to_string(int(kMaxTangentAmplitude_m * 1e3)) +
                     " mm (the flangeway clearance is ~5-10 mm, a flange ~30 mm high; unit?)");
  if (!(gauge_m > 1.0 && gauge_m < 2.0)) throw InputError(where + "track.gauge_mm out of range");
  if (wheel.empty() || rail.empty()) throw InputError(where + "profiles missing");
  try {  // the track the run builds (wheel radius, gauge, profiles' kinds): check_scenario refuses what the run would
    MakeTrackSetup().validate();
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
}

TrackSetup Scenario::MakeTrackSetup() const {
  TrackSetup s = MakeSymmetricTrack(wheel, rail, rail_inclination_rad);
  s.gauge_m = gauge_m;
  s.nominal_radius_m = {vehicle.nominal_wheel_radius_m, vehicle.nominal_wheel_radius_m};
  return s;
}

namespace {

// `published` (published_study.hpp): the figures of a published study of the same case, for the compare report.
void ParsePublished(const Reader& r, const YAML::Node& n, PublishedStudy* p) {
  r.check_keys(n, "published", {"source", "steps", "models"});
  if (!n["source"]) r.fail("published", "source missing (where the figures are printed)");
  p->source = r.text(n["source"], "published.source");
  if (n["steps"]) p->steps = r.integer(n["steps"], "published.steps");
  if (p->steps < 0) r.fail("published.steps", "must be >= 0");
  const YAML::Node models = n["models"];
  if (!models || !models.IsMap() || models.size() == 0) r.fail("published.models", "expected a map: model -> figures");
  for (const auto& entry : models) {
    PublishedModelFigures f;
    f.model = entry.first.as<std::string>();
    const std::string where = "published.models." + f.model;
    ModelFromName(r, f.model, where);  // a model name --models accepts
    const YAML::Node v = entry.second;
    r.check_keys(v, where, {"km", "tread_wear_mm", "flange_wear_mm", "sd", "sh", "qr"});
    const auto positive = [&](const char* key, double scale) {
      if (!v[key]) return -1.0;
      const double x = r.number(v[key], where + "." + key);
      if (!(x > 0)) r.fail(where + "." + key, "must be > 0");
      return scale * x;
    };
    f.km = positive("km", 1.0);
    f.tread_wear_m = positive("tread_wear_mm", 1e-3);
    f.flange_wear_m = positive("flange_wear_mm", 1e-3);
    const auto trend = [&](const char* key) {
      if (!v[key]) return Trend::Unknown;
      try {
        return ParseTrend(r.text(v[key], where + "." + key));
      } catch (const InputError& e) {
        r.fail(where + "." + key, e.what());
      }
    };
    f.sd = trend("sd");
    f.sh = trend("sh");
    f.qr = trend("qr");
    if (p->find(f.model) != nullptr) r.fail(where, "given twice");
    p->models.push_back(f);
  }
}

}  // namespace

Scenario ParseScenario(const std::string& yaml_text, const std::string& source, const std::string& base_dir) {
  Reader r{source, base_dir};
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError(source + ": YAML: " + e.what());
  }
  r.check_keys(root, "top level",
               {"name", "vehicle", "kinematics", "track", "profiles", "material", "friction", "elastic_flange_deg",
                "load_tolerance", "load_balance", "kp_spin_about_centre", "kp_local_flexibilities", "load_acceptance", "wear_law",
                "rail_wear_law", "contact_model", "update", "rail", "track_classes", "track_classes_csv", "published"});
  Scenario s;
  s.source = source;
  s.vehicle = MetroVehicle();
  s.rail_inclination_rad = rail_inclination_1in20();
  s.name = root["name"] ? r.text(root["name"], "name") : "scenario";
  if (root["vehicle"]) ParseVehicle(r, root["vehicle"], &s.vehicle);
  if (const YAML::Node k = root["kinematics"]) {
    r.check_keys(k, "kinematics", {"provider", "tangent_amplitude_mm", "tangent_phases", "cant_base_m", "free_axle_rotation",
                                     "axle_torque_Nm", "contact_model", "dynamic"});
    if (k["provider"]) {
      const std::string p = r.text(k["provider"], "kinematics.provider");
      if (p == "quasistatic") s.kinematics.provider = KinematicsProvider::QuasiStatic;
      else if (p == "centred") s.kinematics.provider = KinematicsProvider::Centred;
      else if (p == "kinematic") s.kinematics.provider = KinematicsProvider::Kinematic;
      else if (p == "dynamic") s.kinematics.provider = KinematicsProvider::Dynamic;
      else r.fail("kinematics.provider", "unknown provider '" + p + "' (quasistatic, centred, kinematic, dynamic)");
    }
    if (k["tangent_amplitude_mm"]) s.kinematics.tangent_amplitude_m = 1e-3 * r.number(k["tangent_amplitude_mm"], "kinematics.tangent_amplitude_mm");
    if (k["tangent_phases"]) s.kinematics.tangent_phases = r.integer(k["tangent_phases"], "kinematics.tangent_phases");
    if (k["cant_base_m"]) s.kinematics.cant_base_m = r.number(k["cant_base_m"], "kinematics.cant_base_m");
    if (k["free_axle_rotation"]) s.kinematics.free_axle_rotation = r.boolean(k["free_axle_rotation"], "kinematics.free_axle_rotation");
    if (k["axle_torque_Nm"]) s.kinematics.axle_torque_Nm = r.number(k["axle_torque_Nm"], "kinematics.axle_torque_Nm");
    if (k["contact_model"]) {
      const std::string m = r.text(k["contact_model"], "kinematics.contact_model");
      s.kinematics.contact_model = ModelFromName(r, m, "kinematics.contact_model");
      s.kinematics.contact_model_set = true;
    }
    if (k["dynamic"]) ParseDynamicKinematics(r, k["dynamic"], &s.kinematics.dynamic);
  }
  if (const YAML::Node t = root["track"]) {
    r.check_keys(t, "track", {"gauge_mm", "rail_inclination"});
    if (t["gauge_mm"]) s.gauge_m = 1e-3 * r.number(t["gauge_mm"], "track.gauge_mm");
    if (t["rail_inclination"]) s.rail_inclination_rad = ParseInclination(r, t["rail_inclination"]);
  }
  s.wheel_name = "S1002";
  s.rail_name = "60E1";
  if (const YAML::Node p = root["profiles"]) {
    r.check_keys(p, "profiles", {"wheel", "rail", "wheel_radius_mm", "wheel_mirror", "wheel_z_down", "wheel_units",
                                 "wheel_smoothing_mm", "wheel_format", "rail_mirror", "rail_z_down", "rail_units",
                                 "rail_smoothing_mm", "rail_format"});
    if (p["wheel"]) s.wheel_name = r.text(p["wheel"], "profiles.wheel");
    if (p["rail"]) s.rail_name = r.text(p["rail"], "profiles.rail");
    if (p["wheel_radius_mm"]) s.vehicle.nominal_wheel_radius_m = 1e-3 * r.number(p["wheel_radius_mm"], "profiles.wheel_radius_mm");
  }
  const ProfileReadOptions wheel_read = FileReadOptions(r, root["profiles"], "wheel");
  const ProfileReadOptions rail_read = FileReadOptions(r, root["profiles"], "rail");
  try {
    s.wheel = BuiltInOrFileWheel(r, s.wheel_name, wheel_read);
  } catch (const InputError& e) {
    r.fail("profiles.wheel", e.what());
  }
  try {
    s.rail = BuiltInOrFileRail(r, s.rail_name, rail_read);
  } catch (const InputError& e) {
    r.fail("profiles.rail", e.what());
  }
  if (const YAML::Node m = root["material"]) {
    r.check_keys(m, "material", {"shear_modulus_Pa", "poisson_ratio", "density_kg_m3"});
    if (m["shear_modulus_Pa"]) s.material.shear_modulus_Pa = r.number(m["shear_modulus_Pa"], "material.shear_modulus_Pa");
    if (m["poisson_ratio"]) s.material.poisson_ratio = r.number(m["poisson_ratio"], "material.poisson_ratio");
    if (m["density_kg_m3"]) s.material.density_kg_m3 = r.number(m["density_kg_m3"], "material.density_kg_m3");
  }
  s.wear.wheel_material = s.material;
  s.wear.rail_material = s.material;
  if (root["friction"]) s.friction_coefficient = r.number(root["friction"], "friction");
  if (root["elastic_flange_deg"]) {
    const double deg = r.number(root["elastic_flange_deg"], "elastic_flange_deg");
    if (!(deg > 0.0 && deg < 90.0)) r.fail("elastic_flange_deg", "must be between 0 and 90 degrees");
    s.elastic_flange_angle_rad = deg * M_PI / 180.0;
  }
  if (root["load_tolerance"]) {
    s.load_tolerance = r.number(root["load_tolerance"], "load_tolerance");
    if (!(s.load_tolerance > 0.0 && s.load_tolerance < 1.0)) r.fail("load_tolerance", "must lie in (0, 1)");
  }
  if (root["load_balance"]) {
    try {
      s.load_balance = ParseLoadBalance(r.text(root["load_balance"], "load_balance"));
    } catch (const InputError& e) {
      r.fail("load_balance", e.what());
    }
  }
  if (root["kp_spin_about_centre"])
    s.kp_spin_about_patch_centre = r.boolean(root["kp_spin_about_centre"], "kp_spin_about_centre");
  if (root["kp_local_flexibilities"])
    s.kp_local_flexibilities = r.boolean(root["kp_local_flexibilities"], "kp_local_flexibilities");
  if (root["load_acceptance"]) {
    s.load_acceptance = r.number(root["load_acceptance"], "load_acceptance");
    if (!(s.load_acceptance >= 0.0 && s.load_acceptance < 1.0)) r.fail("load_acceptance", "must lie in [0, 1)");
  }
  try {
    if (root["wear_law"]) {
      s.wear.wheel_law = LawFromName(r, r.text(root["wear_law"], "wear_law"));
      s.wear.rail_law = s.wear.wheel_law;
    }
    if (root["rail_wear_law"]) s.wear.rail_law = LawFromName(r, r.text(root["rail_wear_law"], "rail_wear_law"));
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (msg.rfind(source, 0) == 0) throw;
    r.fail("wear_law", msg);
  }
  if (root["contact_model"]) s.model = ModelFromName(r, r.text(root["contact_model"], "contact_model"));
  if (const YAML::Node u = root["update"]) {
    r.check_keys(u, "update", {"cap_mm", "smoothing_mm", "steps", "substeps", "total_km", "max_curvature_1_m",
                                 "overhang_cut"});
    if (u["cap_mm"]) s.update.cap_m = 1e-3 * r.number(u["cap_mm"], "update.cap_mm");
    if (u["smoothing_mm"]) s.update.smoothing_cutoff_m = 1e-3 * r.number(u["smoothing_mm"], "update.smoothing_mm");
    if (u["steps"]) s.update.steps = r.integer(u["steps"], "update.steps");
    if (u["substeps"]) s.update.substeps = r.integer(u["substeps"], "update.substeps");
    if (u["total_km"]) s.update.total_km = r.number(u["total_km"], "update.total_km");
    if (u["max_curvature_1_m"]) s.update.max_curvature_1_m = r.number(u["max_curvature_1_m"], "update.max_curvature_1_m");
    if (u["overhang_cut"]) {
      const std::string v = r.text(u["overhang_cut"], "update.overhang_cut");
      if (v != "conserve_area" && v != "wear_off")
        r.fail("update.overhang_cut", "must be conserve_area (the face keeps the step's wear area) or wear_off (the "
                                      "lip is cut on top of the wear), not '" + v + "'");
      s.update.overhang_cut_conserves_area = v == "conserve_area";
    }
  }
  if (const YAML::Node pub = root["published"]) ParsePublished(r, pub, &s.published);
  if (const YAML::Node rs = root["rail"]) {
    r.check_keys(rs, "rail", {"fixed", "steps", "cap_mm", "spacing_mm"});
    if (rs["fixed"]) s.rail_steps.fixed = r.boolean(rs["fixed"], "rail.fixed");
    if (rs["steps"]) s.rail_steps.steps = r.integer(rs["steps"], "rail.steps");
    if (rs["cap_mm"]) s.rail_steps.cap_m = 1e-3 * r.number(rs["cap_mm"], "rail.cap_mm");
    if (rs["spacing_mm"]) s.rail_steps.output_spacing_m = 1e-3 * r.number(rs["spacing_mm"], "rail.spacing_mm");
  }
  if (root["track_classes"] && root["track_classes_csv"]) r.fail("top level", "give track_classes or track_classes_csv, not both");
  if (const YAML::Node tc = root["track_classes"]) {
    if (!tc.IsSequence()) r.fail("track_classes", "expected a list");
    for (size_t i = 0; i < tc.size(); ++i)
      s.classes.push_back(ParseClass(r, tc[i], "track_classes[" + std::to_string(i) + "]", s.friction_coefficient,
                                      s.vehicle));
  } else if (const YAML::Node csv = root["track_classes_csv"]) {
    s.classes = ClassesFromCsv(r, csv, s.friction_coefficient);
  }
  // normalise the shares (fractions or percent)
  double sum = 0.0;
  for (const TrackClass& c : s.classes) {
    if (!(c.share >= 0)) r.fail("track_classes", "share of " + c.name + " must be >= 0");
    sum += c.share;
  }
  if (!s.classes.empty()) {
    if (!(sum > 0)) r.fail("track_classes", "shares sum to 0");
    for (TrackClass& c : s.classes) c.share /= sum;
  }
  try {
    s.validate();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (msg.rfind(source, 0) == 0) throw;
    throw InputError(source + ": " + msg);
  }
  return s;
}

void ApplyScenarioContact(const Scenario& scenario, WheelContactOptions* options) {
  options->material = scenario.material;
  options->max_touching_contact_angle_rad = scenario.elastic_flange_angle_rad;
  options->load_tolerance = scenario.load_tolerance;
  options->load_balance = scenario.load_balance;
  options->kp_spin_about_patch_centre = scenario.kp_spin_about_patch_centre;
  options->kp_local_flexibilities = scenario.kp_local_flexibilities;
}

Scenario LoadScenario(const std::string& path) { return LoadScenario(path, {}); }

}  // namespace conforma
