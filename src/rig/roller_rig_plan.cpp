// Roller-rig scenario file and wear test plan (roller_rig_plan.hpp; paper 000 §4, Tables 1 and 5).
#include "conforma/roller_rig_plan.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <set>
#include <string>
#include <utility>

#include "conforma/contact_model.hpp"
#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "conforma/profile_update.hpp"
#include "conforma/wheel_contact_options.hpp"
#include "conforma/yaml_keys.hpp"

namespace conforma {

namespace {

constexpr double kPi = 3.14159265358979323846;

template <class T>
void Read(const YAML::Node& node, const char* key, T* value, const std::string& where) {
  if (!node || !node[key]) return;
  try {
    *value = node[key].as<T>();
  } catch (const YAML::Exception& e) {
    throw InputError(where + ": " + key + ": " + e.what());
  }
}

std::string ResolveFile(const std::string& name, const std::string& scenario) {
  if (name == "conical" || name == "s1002" || name == "uic60_1in20") return name;
  const std::filesystem::path p(name);
  if (p.is_absolute()) return name;
  return (std::filesystem::path(scenario).parent_path() / p).string();
}

// One plan step of duration sample.duration_s in sub-steps that keep the stability rule of the explicit wear update
// (RollerRigSampleOptions::max_depth_per_approach): a sub-step that breaks it is discarded and repeated at half the
// length, down to options.min_substep_s (accepted there and counted as a violation); after an accepted sub-step the
// next one may double, up to what is left of the step. Returns the last sub-step's result (failed: that one).
RollerRigSampleResult AdaptiveStep(const RollerRigSampleOptions& o, RollerRigState* state,
                                   const RollerRigSample& sample, const RollerRigPlanOptions& po,
                                   RollerRigTestResult* r) {
  double left = sample.duration_s, h = sample.duration_s;
  RollerRigSampleResult res;
  while (left > 1e-12 * sample.duration_s) {
    h = std::min(h, left);
    RollerRigSample sub = sample;
    sub.duration_s = h;
    sub.time_s = state->time_s;
    RollerRigState trial = *state;
    res = ProcessRigSample(o, &trial, sub);
    if (res.status != RollerRigSampleStatus::Ok) return res;  // the state keeps what was accepted so far
    if (res.stability_rule_violated && h > po.min_substep_s) {
      ++r->rejected_substeps;
      h = std::max(0.5 * h, po.min_substep_s);
      continue;
    }
    if (res.stability_rule_violated) ++r->stability_violations;
    r->max_depth_per_approach = std::max(r->max_depth_per_approach, res.depth_per_approach);
    r->min_substep_s = r->substeps == 0 ? h : std::min(r->min_substep_s, h);
    ++r->substeps;
    *state = std::move(trial);
    left -= h;
    h *= 2.0;
  }
  return res;
}

}  // namespace

const char* to_string(RollerRigTestStatus status) {
  return status == RollerRigTestStatus::Ok ? "ok" : "samples_failed";
}

RollerRigScenario LoadRollerRigScenario(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw InputError(path + ": " + e.what());
  }
  RollerRigScenario sc;
  sc.source = path;
  // every key read below, and only those: a misspelt key is an error, not a silent default
  CheckYamlKeys(root, path, "top level", {"rig", "contact", "wear", "wheelset_speed", "gravity_m_s2", "plan"});
  for (const auto& [key, allowed] : std::initializer_list<std::pair<const char*, std::set<std::string>>>{
           {"rig",
            {"roller_radius_m", "wheel_radius_m", "wheelset_mass_kg", "inertia_kg_m2", "length_factor",
             "longitudinal_stiffness_N_per_m", "spring_half_spacing_m", "wheel_profile", "wheel_conicity_rad",
             "wheel_width_field_m", "roller_profile"}},
           {"contact", {"model", "friction_coefficient", "fastsim_elements"}},
           {"wear", {"law", "step_s", "filter_window_m", "strip_mean_elements", "filter_interval_s", "grid_spacing_m"}}})
    if (root[key]) CheckYamlKeys(root[key], path, key, allowed);
  RollerRigSetup setup;
  const YAML::Node rig = root["rig"];
  const std::string wr = path + ": rig";
  Read(rig, "roller_radius_m", &setup.roller_radius_m, wr);
  Read(rig, "wheel_radius_m", &setup.wheel_radius_m, wr);
  Read(rig, "wheelset_mass_kg", &setup.wheelset_mass_kg, wr);
  if (rig && rig["inertia_kg_m2"]) {
    std::vector<double> I;
    Read(rig, "inertia_kg_m2", &I, wr);
    if (I.size() != 3) throw InputError(wr + ": inertia_kg_m2 must be [Ix, Iy, Iz]");
    setup.inertia_x_kg_m2 = I[0], setup.inertia_y_kg_m2 = I[1], setup.inertia_z_kg_m2 = I[2];
  }
  Read(rig, "length_factor", &setup.length_factor, wr);
  Read(rig, "longitudinal_stiffness_N_per_m", &setup.longitudinal_stiffness_N_per_m, wr);
  Read(rig, "spring_half_spacing_m", &setup.spring_half_spacing_m, wr);
  Read(rig, "wheel_profile", &setup.wheel_profile, wr);
  Read(rig, "wheel_conicity_rad", &setup.wheel_conicity_rad, wr);
  Read(rig, "wheel_width_field_m", &setup.wheel_width_field_m, wr);
  Read(rig, "roller_profile", &setup.roller_profile, wr);
  setup.wheel_profile = ResolveFile(setup.wheel_profile, path);
  setup.roller_profile = ResolveFile(setup.roller_profile, path);
  try {
    setup.validate();
  } catch (const InputError& e) {
    throw InputError(wr + ": " + e.what());
  }
  sc.options = RollerRigSampleOptions::Defaults(setup);
  const YAML::Node contact = root["contact"];
  const std::string wc = path + ": contact";
  std::string model = to_string(sc.options.kinematics.contact.model);
  Read(contact, "model", &model, wc);
  try {
    sc.options.kinematics.contact.model = ParseContactModel(model);
  } catch (const InputError& e) {
    throw InputError(wc + ": model: " + e.what());
  }
  Read(contact, "friction_coefficient", &sc.options.kinematics.contact.friction_coefficient, wc);
  Read(contact, "fastsim_elements", &sc.options.kinematics.contact.fastsim_elements, wc);
  const YAML::Node wear = root["wear"];
  const std::string ww = path + ": wear";
  std::string law = to_string(sc.options.wear_law);
  Read(wear, "law", &law, ww);
  sc.options.wear_law = RollerRigWearLawFromName(law);
  Read(wear, "step_s", &sc.step_s, ww);
  Read(wear, "filter_window_m", &sc.options.filter_window_m, ww);
  Read(wear, "strip_mean_elements", &sc.options.strip_mean_elements, ww);
  Read(wear, "filter_interval_s", &sc.filter_interval_s, ww);
  Read(wear, "grid_spacing_m", &sc.options.wear_grid_spacing_m, ww);
  std::string speed = "balance";
  Read(root, "wheelset_speed", &speed, path);
  if (speed != "balance" && speed != "eq2") throw InputError(path + ": wheelset_speed must be balance or eq2");
  sc.options.kinematics.eq2_wheelset_speed = speed == "eq2";
  Read(root, "gravity_m_s2", &sc.gravity_m_s2, path);
  require_positive(sc.step_s, "wear.step_s");
  require_positive(sc.filter_interval_s, "wear.filter_interval_s");
  require_positive(sc.gravity_m_s2, "gravity_m_s2");
  sc.options.filter_every_steps = std::max(1, static_cast<int>(std::lround(sc.filter_interval_s / sc.step_s)));
  try {
    sc.options.validate();
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  const YAML::Node plan = root["plan"];
  if (!plan || !plan.IsSequence() || plan.size() == 0) throw InputError(path + ": plan: a non-empty list of tests is required");
  for (size_t i = 0; i < plan.size(); ++i) {
    const std::string wp = path + ": plan[" + std::to_string(i) + "]";
    CheckYamlKeys(plan[i], path, "plan[" + std::to_string(i) + "]",
                  {"test", "creep", "reference_speed_rpm", "wheel_load_kg", "distance_km", "time_min"});
    RollerRigWearTestCase t;
    t.test = static_cast<int>(i + 1);
    Read(plan[i], "test", &t.test, wp);
    Read(plan[i], "creep", &t.creep, wp);
    Read(plan[i], "reference_speed_rpm", &t.reference_speed_rpm, wp);
    Read(plan[i], "wheel_load_kg", &t.wheel_load_kg, wp);
    Read(plan[i], "distance_km", &t.distance_km, wp);
    Read(plan[i], "time_min", &t.time_min, wp);
    if (!(t.creep >= 0.0 && t.creep < 1.0)) throw InputError(wp + ": creep must be in [0, 1)");
    if (!(t.reference_speed_rpm > 0.0) || !(t.wheel_load_kg > 0.0) || !(t.distance_km > 0.0))
      throw InputError(wp + ": reference_speed_rpm, wheel_load_kg and distance_km must be > 0");
    // a roller rig's range (paper 000: 1000 rpm, 37 kg per wheel); beyond it a unit or key mistake
    if (t.reference_speed_rpm > kMaxRollerRigSpeedRpm)
      throw InputError(wp + ": reference_speed_rpm " + MessageNumber(t.reference_speed_rpm) + " is beyond a roller "
                       "rig's " + MessageNumber(kMaxRollerRigSpeedRpm) + " rpm");
    if (t.wheel_load_kg * sc.gravity_m_s2 > kMaxWheelLoadN)  // the wheel-load bound of RequireWheelLoad
      throw InputError(wp + ": wheel_load_kg " + MessageNumber(t.wheel_load_kg) + " is beyond a wheel's load (at most " +
                       MessageNumber(kMaxWheelLoadN / sc.gravity_m_s2) + " kg: " + MessageNumber(kMaxWheelLoadN) +
                       " N)");
    for (const RollerRigWearTestCase& other : sc.plan)
      if (other.test == t.test)
        throw InputError(wp + ": test " + std::to_string(t.test) + " is planned twice (test numbers name the "
                         "output rows)");
    sc.plan.push_back(t);
  }
  return sc;
}

ProfileWearSummary CompareProfiles(const Profile& before, const Profile& after) {
  ProfileWearSummary s;
  const double h = 2e-6;
  const double y0 = std::max(before.y_min(), after.y_min()), y1 = std::min(before.y_max(), after.y_max());
  for (double y = y0 + 0.5 * h; y < y1; y += h) {
    const std::optional<double> a = before.height_at(y), b = after.height_at(y);
    if (!a || !b) continue;
    const double d = *a - *b;
    s.max_depth_m = std::max(s.max_depth_m, d);
    if (d > 0.0) s.area_m2 += d * h;
  }
  return s;
}

namespace {
constexpr double kMaxPlanSamples = 1e7;
}  // namespace

std::vector<RollerRigTestResult> RunRollerRigPlan(const RollerRigScenario& sc, const RollerRigPlanOptions& po) {
  if (!(po.distance_fraction > 0.0 && po.distance_fraction <= 1.0))
    throw InputError("RollerRigPlanOptions.distance_fraction must be in (0, 1]");
  require_positive(po.min_substep_s, "RollerRigPlanOptions.min_substep_s");
  const double step = po.step_s > 0.0 ? po.step_s : sc.step_s;
  require_positive(step, "rig plan step_s");
  // the samples the plan asks for, before any is run (a step of 1e-9 s or a test of 1e12 km ran silently until
  // killed: fuzzing, session 25)
  double plan_samples = 0.0;
  for (size_t i = 0; i < (po.max_tests > 0 ? std::min<size_t>(po.max_tests, sc.plan.size()) : sc.plan.size()); ++i) {
    const RollerRigWearTestCase& t = sc.plan[i];
    plan_samples += po.distance_fraction * t.distance_km * 1e3 /
                    (t.reference_speed_rpm * 2.0 * kPi / 60.0 * sc.options.setup.roller_radius_m) / step;
  }
  if (!(plan_samples <= kMaxPlanSamples)) {
    char text[240];
    std::snprintf(text, sizeof text, "the rig plan asks for %.3g samples of %g s, more than %.0g: a larger step_s or a "
                  "shorter distance (distance_km, --distance-fraction)", plan_samples, step, kMaxPlanSamples);
    throw InputError(text);
  }
  RollerRigSampleOptions o = sc.options;
  o.filter_every_steps = std::max(1, static_cast<int>(std::lround(sc.filter_interval_s / step)));
  RollerRigState state = MakeRollerRigState(o);
  const std::array<Profile, 2> wheel0 = state.wheel_reference, roller0 = state.roller_reference;
  std::vector<RollerRigTestResult> out;
  const size_t n = po.max_tests > 0 ? std::min<size_t>(po.max_tests, sc.plan.size()) : sc.plan.size();
  for (size_t i = 0; i < n; ++i) {
    const RollerRigWearTestCase& t = sc.plan[i];
    const auto t0 = std::chrono::steady_clock::now();
    RollerRigTestResult r;
    r.test = t;
    const std::array<Profile, 2> wheel_start = state.wheel_reference, roller_start = state.roller_reference;
    const double w_ref = t.reference_speed_rpm * 2.0 * kPi / 60.0;
    const double duration = po.distance_fraction * t.distance_km * 1e3 / (w_ref * o.setup.roller_radius_m);
    const long samples = std::max(1L, static_cast<long>(std::ceil(duration / step - 1e-9)));
    RollerRigSample s;
    s.roller_speed_rad_s = {w_ref, w_ref * (1.0 - t.creep) / (1.0 + t.creep)};
    s.wheel_load_N = {t.wheel_load_kg * sc.gravity_m_s2, t.wheel_load_kg * sc.gravity_m_s2};
    for (long k = 0; k < samples; ++k) {
      s.duration_s = std::min(step, duration - k * step);
      if (!(s.duration_s > 0.0)) break;
      s.time_s = state.time_s;
      const RollerRigSampleResult res =
          po.adaptive_substeps ? AdaptiveStep(o, &state, s, po, &r) : ProcessRigSample(o, &state, s);
      if (!po.adaptive_substeps) {
        ++r.substeps;
        if (res.status == RollerRigSampleStatus::Ok && res.stability_rule_violated) ++r.stability_violations;
        if (res.status == RollerRigSampleStatus::Ok)
          r.max_depth_per_approach = std::max(r.max_depth_per_approach, res.depth_per_approach);
      }
      ++r.samples;
      r.simulated_time_s += s.duration_s;
      r.distance_m += w_ref * o.setup.roller_radius_m * s.duration_s;
      if (res.status != RollerRigSampleStatus::Ok) {
        if (r.failed_samples == 0) r.first_failure = res.message;
        ++r.failed_samples;
      } else {
        r.mean_wheelset_speed_rad_s += res.kinematics.wheelset_speed_rad_s;
        for (int j = 0; j < 2; ++j) {
          r.mean_creepage[j] += res.kinematics.contact[j].xi;
          r.mean_fx_N[j] += res.kinematics.contact[j].fx_N;
        }
      }
      if (po.progress) po.progress(static_cast<int>(i), k, samples);
    }
    // the last filter of the test: the pending wear becomes part of the reference profiles
    if (o.update_profiles) {
      for (int j = 0; j < 2; ++j) {
        const WearDistribution fw = SlidingMean(state.wheel_pending[j], o.filter_window_m);
        const WearDistribution fr = SlidingMean(state.roller_pending[j], o.filter_window_m);
        if (fw.max_depth_m() > 0.0) state.wheel_reference[j] = RemoveAlongNormal(state.wheel_reference[j], fw, 0.0, "rig wheel filter");
        if (fr.max_depth_m() > 0.0) state.roller_reference[j] = RemoveAlongNormal(state.roller_reference[j], fr, 0.0, "rig roller filter");
      }
      // fresh state on the filtered profiles: geometry, empty pending grids, counters restart
      state = MakeRollerRigState(o, state.wheel_reference, state.roller_reference);
    }
    const long ok = r.samples - r.failed_samples;
    if (ok > 0) {
      r.mean_wheelset_speed_rad_s /= ok;
      for (int j = 0; j < 2; ++j) r.mean_creepage[j] /= ok, r.mean_fx_N[j] /= ok;
    }
    r.status = r.failed_samples == 0 ? RollerRigTestStatus::Ok : RollerRigTestStatus::SamplesFailed;
    for (int j = 0; j < 2; ++j) {
      r.wheel[j] = state.wheel[j];
      r.roller[j] = state.roller[j];
      r.wheel_wear[j] = CompareProfiles(wheel_start[j], state.wheel[j]);
      r.roller_wear[j] = CompareProfiles(roller_start[j], state.roller[j]);
      r.wheel_wear_total[j] = CompareProfiles(wheel0[j], state.wheel[j]);
      r.roller_wear_total[j] = CompareProfiles(roller0[j], state.roller[j]);
    }
    r.run_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace conforma
