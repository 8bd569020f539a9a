// Python binding of the wear loop (wear_simulation.hpp): wear(scenario, model) returning the steps table, and the
// scenario as a dict (the YAML layout of scenario.hpp, so a dict can be edited and run again).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>

#include <yaml-cpp/yaml.h>

#include <regex>
#include <string>
#include <vector>

#include "conforma/dynamic_kinematics.hpp"
#include "conforma/error.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"
#include "module_parts.hpp"

namespace py = pybind11;

namespace conforma::python {

namespace {

// YAML node -> Python object: maps to dicts, sequences to lists, scalars to bool / int / float / str (in that order
// of preference, as YAML 1.2 core schema would read them).
py::object FromYaml(const YAML::Node& n) {
  if (n.IsMap()) {
    py::dict d;
    for (const auto& kv : n) d[py::str(kv.first.as<std::string>())] = FromYaml(kv.second);
    return std::move(d);
  }
  if (n.IsSequence()) {
    py::list l;
    for (const auto& item : n) l.append(FromYaml(item));
    return std::move(l);
  }
  if (n.IsNull() || !n.IsDefined()) return py::none();
  const std::string text = n.Scalar();
  if (n.Tag() != "!") {  // unquoted scalars: booleans and numbers as YAML 1.1 reads them (a float needs a '.',
                         // so rail names such as 50E4 stay strings); the scenario reader converts on demand anyway
    static const std::regex integer("[-+]?[0-9]+");
    static const std::regex decimal("[-+]?([0-9]+\\.[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?");
    if (text == "true" || text == "True") return py::bool_(true);
    if (text == "false" || text == "False") return py::bool_(false);
    if (std::regex_match(text, integer)) return py::int_(std::stoll(text));
    if (std::regex_match(text, decimal)) return py::float_(std::stod(text));
  }
  return py::str(text);
}

Scenario ScenarioFrom(const py::object& scenario, const std::string& base_dir) {
  if (py::isinstance<py::str>(scenario)) return LoadScenario(scenario.cast<std::string>());
  if (py::isinstance<py::dict>(scenario)) {
    // JSON is valid YAML (flow style): the scenario reader parses the dict exactly as it would the file
    const std::string text = py::module_::import("json").attr("dumps")(scenario).cast<std::string>();
    return ParseScenario(text, "<dict>", base_dir);
  }
  throw InputError("scenario must be a YAML file path or a dict (the YAML layout of scenario.hpp)");
}

py::dict RunWear(const py::object& scenario, const std::string& model, int steps, double total_km,
                 const std::string& base_dir) {
  if (std::isnan(total_km)) throw InputError("total_km is NaN (negative: the scenario's)");  // (was the scenario's)
  const Scenario sc = ScenarioFrom(scenario, base_dir);
  WearSimulationOptions o;
  o.contact.model = model.empty() ? sc.model : ParseContactModel(model);
  o.steps = steps;
  o.total_km = total_km;
  o.kinematics_factory = &MakeWearKinematics;  // every provider of the scenario, `dynamic` included
  WearSimulationResult r;
  {
    py::gil_scoped_release release;
    r = RunWearSimulation(sc, o);
  }
  // the steps table, with the initial profile as row 0 (km = 0)
  const size_t n = r.steps.size() + 1;
  std::vector<double> rail_step(n), step(n), km(n), step_km(n), depth(n), sd(n), sh(n), qr(n), tread(n), flange(n),
      samples(n), failed(n), kinematics_fallbacks(n);
  sd[0] = r.initial_dimensions.sd_m * 1e3, sh[0] = r.initial_dimensions.sh_m * 1e3, qr[0] = r.initial_dimensions.qr_m * 1e3;
  py::list profiles;
  profiles.append(r.initial_wheel);
  for (size_t i = 1; i < n; ++i) {
    const WearStepRecord& s = r.steps[i - 1];
    rail_step[i] = s.rail_step, step[i] = s.step, km[i] = s.km, step_km[i] = s.step_km;
    depth[i] = s.max_depth_m * 1e3;
    sd[i] = s.dimensions.sd_m * 1e3, sh[i] = s.dimensions.sh_m * 1e3, qr[i] = s.dimensions.qr_m * 1e3;
    tread[i] = s.tread_wear_m * 1e3, flange[i] = s.flange_wear_m * 1e3;
    samples[i] = s.samples, failed[i] = s.failed_contacts, kinematics_fallbacks[i] = s.kinematics_fallbacks;
    profiles.append(s.wheel);
  }
  py::dict table;
  table["rail_step"] = Column(rail_step), table["step"] = Column(step), table["km"] = Column(km);
  table["step_km"] = Column(step_km), table["max_depth_mm"] = Column(depth);
  table["sd_mm"] = Column(sd), table["sh_mm"] = Column(sh), table["qr_mm"] = Column(qr);
  table["tread_wear_mm"] = Column(tread), table["flange_wear_mm"] = Column(flange);
  table["samples"] = Column(samples), table["failed_contacts"] = Column(failed);
  table["kinematics_fallbacks"] = Column(kinematics_fallbacks);
  py::dict out;
  out["scenario"] = sc.name;
  out["model"] = to_string(o.contact.model);
  out["status"] = to_string(r.status);
  out["message"] = r.message;
  out["steps"] = table;
  out["wheel_profiles"] = profiles;
  return out;
}

}  // namespace

void BindWear(py::module_& m) {
  m.attr("has_wear") = true;
  m.def(
      "load_scenario",
      [](const std::string& path) {
        LoadScenario(path);  // validates (InputError naming the key and the file)
        try {
          return FromYaml(YAML::LoadFile(path));
        } catch (const YAML::Exception& e) {
          throw InputError(path, e.mark.line + 1, e.msg);
        }
      },
      py::arg("path"),
      "The scenario file as a dict in the YAML layout of include/conforma/scenario.hpp (validated first); edit it "
      "and pass it to wear().");
  m.def(
      "check_scenario",
      [](const py::object& scenario, const std::string& base_dir) {
        const Scenario s = ScenarioFrom(scenario, base_dir);
        py::dict d;
        d["name"] = s.name, d["wheel"] = s.wheel_name, d["rail"] = s.rail_name;
        d["contact_model"] = to_string(s.model), d["gauge_m"] = s.gauge_m;
        d["rail_inclination_rad"] = s.rail_inclination_rad, d["friction"] = s.friction_coefficient;
        d["cap_m"] = s.update.cap_m, d["steps"] = s.update.steps, d["total_km"] = s.update.total_km;
        py::list classes;
        for (const TrackClass& c : s.classes) {
          py::dict k;
          k["name"] = c.name, k["curve_radius_m"] = c.curve_radius_m, k["cant_m"] = c.cant_m;
          k["speed_m_s"] = c.speed_m_s, k["share"] = c.share, k["friction"] = c.friction_coefficient;
          classes.append(k);
        }
        d["track_classes"] = classes;
        return d;
      },
      py::arg("scenario"), py::arg("base_dir") = ".",
      "Parse and validate a scenario (path or dict); returns the values as the wear loop will use them (SI units, "
      "class shares normalised to 1).");
  m.def("wear", &RunWear, py::arg("scenario"), py::arg("model") = "", py::arg("steps") = -1,
        py::arg("total_km") = -1.0, py::arg("base_dir") = ".",
        R"doc(Run the wear loop of a scenario (YAML path or dict in the file's layout; relative paths in a dict are
resolved against base_dir). model: 'hertz', 'kp', 'kpec', 'conformal', 'auto' ('' = the scenario's); steps / total_km < 0:
the scenario's.

Returns a dict: scenario, model, status, message, 'steps' -- NumPy columns with row 0 the initial wheel (km = 0):
rail_step, step, km, step_km, max_depth_mm, sd_mm, sh_mm, qr_mm, tread_wear_mm, flange_wear_mm, samples,
failed_contacts (wheels without a solution: no wear taken from them), kinematics_fallbacks (track classes whose
quasi-static curving was replaced by the kinematic estimate) -- and 'wheel_profiles' (Profile of every row).)doc");
}

}  // namespace conforma::python
