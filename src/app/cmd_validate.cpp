// conforma validate --scenario F --measured FILE [--measured FILE2 ...] [--measured-profile FILE@KM ...]
//                   --models hertz,conformal --out DIR [--km K] [--steps N]
// Runs the wear loop of the scenario with each model (DIR/<model>/ as `conforma wear` writes it) and compares the
// simulated wheel with measured wheels (measured_validation.hpp): Sd, Sh, qR against km (interpolated between the
// wear steps) and profile normal distances over the worn zone. Writes DIR/validate.csv, DIR/validate_profiles.csv
// (when profiles are given), DIR/validate.json, DIR/report.md and PNG plots (scripts/plot_validate.py).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "cli_setup.hpp"
#include "exit_status.hpp"
#include "commands.hpp"
#include "conforma/error.hpp"
#include "conforma/validation/measured_validation.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"
#include "wear_output.hpp"

namespace conforma::cli {

namespace {

struct MeasuredProfileSpec {
  std::string path;
  double km = 0.0;
  Profile profile;
};

MeasuredProfileSpec ParseProfileSpec(const std::string& spec) {
  const size_t at = spec.rfind('@');
  if (at == std::string::npos || at == 0 || at + 1 == spec.size())
    throw InputError("--measured-profile '" + spec + "': expected FILE@KM");
  MeasuredProfileSpec m;
  m.path = spec.substr(0, at);
  const std::string km = spec.substr(at + 1);
  char* end = nullptr;
  m.km = std::strtod(km.c_str(), &end);
  if (end == km.c_str() || *end != '\0' || !std::isfinite(m.km) || m.km < 0.0)
    throw InputError("--measured-profile '" + spec + "': km '" + km + "' is not a finite number >= 0");
  ProfileReadOptions ro;
  ro.kind = ProfileKind::Wheel;
  m.profile = LoadProfile(m.path, ro);
  return m;
}

std::string FileLabel(const std::string& path) { return std::filesystem::path(path).stem().string(); }

struct ModelValidation {
  std::string name;
  WearSimulationResult result;
  double wall_s = 0.0;
  std::vector<DimensionComparison> dimensions;  // per measured file
  std::vector<DimensionComparisonPoint> pooled;
  std::vector<SimulatedProfile> simulated_profiles;  // per measured profile
  std::vector<ProfileDistanceResult> distances;
};

std::string Mm(double m, int digits = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, m * 1e3);
  return b;
}

void WriteCsv(const std::string& dir, const std::vector<ModelValidation>& runs,
              const std::vector<MeasuredDimensions>& files) {
  std::ofstream out(dir + "/validate.csv");
  if (!out) throw InputError(dir + "/validate.csv: cannot write");
  out << "model,km,dimension,simulated_mm,measured_mm,error_mm,measured_file,line,step_before,step_after,status\n";
  out << std::setprecision(8);
  for (const ModelValidation& r : runs)
    for (size_t f = 0; f < files.size(); ++f)
      for (const DimensionComparisonPoint& p : r.dimensions[f].points) {
        const bool ok = p.bracket.status == InterpolationStatus::Interpolated;
        out << r.name << "," << p.km << "," << to_string(p.dimension) << ",";
        if (ok) out << p.simulated_m * 1e3;
        out << "," << p.measured_m * 1e3 << ",";
        if (ok) out << p.error_m * 1e3;
        out << "," << FileLabel(files[f].source) << "," << p.line << "," << p.step_before << "," << p.step_after << ","
            << to_string(p.bracket.status) << "\n";
      }
}

void WriteProfileCsv(const std::string& dir, const std::vector<ModelValidation>& runs,
                     const std::vector<MeasuredProfileSpec>& profiles) {
  std::ofstream out(dir + "/validate_profiles.csv");
  if (!out) throw InputError(dir + "/validate_profiles.csv: cannot write");
  out << "model,km,measured_file,status,rms_mm,max_mm,mean_signed_mm,y_at_max_mm,zone_y_min_mm,zone_y_max_mm,points,"
         "outside_measurement,alignment_shift_mm,interpolation,step_before,step_after,km_before,km_after\n";
  out << std::setprecision(8);
  for (const ModelValidation& r : runs)
    for (size_t i = 0; i < profiles.size(); ++i) {
      const SimulatedProfile& sp = r.simulated_profiles[i];
      const ProfileDistanceResult& d = r.distances[i];
      const bool beyond = sp.bracket.status == InterpolationStatus::BeyondSimulation;
      out << r.name << "," << profiles[i].km << "," << profiles[i].path << ","
          << (beyond ? "beyond_simulation" : to_string(d.status)) << "," << d.rms_m * 1e3 << "," << d.max_m * 1e3 << ","
          << d.mean_signed_m * 1e3 << "," << d.y_at_max_m * 1e3 << "," << d.zone_y_min_m * 1e3 << ","
          << d.zone_y_max_m * 1e3 << "," << d.points << "," << d.outside_measurement << ","
          << d.alignment_shift_m * 1e3 << "," << to_string(sp.mode) << "," << sp.step_before << "," << sp.step_after
          << "," << sp.km_before << "," << sp.km_after << "\n";
    }
}

nlohmann::json SummaryJson(const DimensionErrorSummary& s) {
  return {{"points", s.points},
          {"beyond_simulation", s.beyond_simulation},
          {"rms_error_mm", s.rms_error_m * 1e3},
          {"max_abs_error_mm", s.max_abs_error_m * 1e3},
          {"mean_error_mm", s.mean_error_m * 1e3}};
}

nlohmann::json MakeJson(const Scenario& sc, double target_km, const std::vector<ModelValidation>& runs,
                        const std::vector<MeasuredDimensions>& files, const std::vector<MeasuredProfileSpec>& profiles) {
  nlohmann::json j;
  j["scenario"] = sc.source;
  j["target_km"] = target_km;
  j["cap_mm"] = sc.update.cap_m * 1e3;
  j["interpolation"] = "linear in km between the wear steps bracketing each measured km; no extrapolation";
  j["measured_files"] = nlohmann::json::array();
  for (const MeasuredDimensions& f : files) j["measured_files"].push_back(f.source);
  for (const ModelValidation& r : runs) {
    nlohmann::json m;
    m["run_time_s"] = r.wall_s;
    m["status"] = to_string(r.result.status);
    m["message"] = r.result.message;
    m["steps"] = r.result.steps.size();
    m["final_km"] = r.result.steps.empty() ? 0.0 : r.result.steps.back().km;
    double max_abs = 0.0;
    for (ReferenceDimension d : kReferenceDimensions) {
      const DimensionErrorSummary s = SummariseDimensionErrors(r.pooled, d);
      if (s.points + s.beyond_simulation == 0) continue;
      m["dimensions"][to_string(d)] = SummaryJson(s);
      max_abs = std::max(max_abs, s.max_abs_error_m);
    }
    m["max_abs_error_mm"] = max_abs * 1e3;
    for (size_t f = 0; f < files.size(); ++f)
      for (ReferenceDimension d : kReferenceDimensions)
        if (files[f].has[static_cast<int>(d)])
          m["per_file"][FileLabel(files[f].source)][to_string(d)] =
              SummaryJson(r.dimensions[f].summary[static_cast<int>(d)]);
    for (size_t i = 0; i < profiles.size(); ++i) {
      const ProfileDistanceResult& d = r.distances[i];
      const SimulatedProfile& sp = r.simulated_profiles[i];
      m["profiles"].push_back(
          {{"file", profiles[i].path},
           {"km", profiles[i].km},
           {"status", sp.bracket.status == InterpolationStatus::BeyondSimulation ? "beyond_simulation"
                                                                                 : to_string(d.status)},
           {"rms_mm", d.rms_m * 1e3},
           {"max_mm", d.max_m * 1e3},
           {"mean_signed_mm", d.mean_signed_m * 1e3},
           {"zone_y_mm", {d.zone_y_min_m * 1e3, d.zone_y_max_m * 1e3}},
           {"points", d.points},
           {"interpolation", to_string(sp.mode)},
           {"steps", {sp.step_before, sp.step_after}}});
    }
    j["models"][r.name] = m;
  }
  return j;
}

struct ReportSettings {
  double target_km = 0.0;
  ProfileDistanceOptions distance;
  ProfileInterpolation interpolation = ProfileInterpolation::Linear;
  std::string plot_note;  // empty: plots made
};

void WriteReport(const std::string& dir, const Scenario& sc, const std::vector<ModelValidation>& runs,
                 const std::vector<MeasuredDimensions>& files, const std::vector<MeasuredProfileSpec>& profiles,
                 const ReportSettings& rs) {
  std::ofstream md(dir + "/report.md");
  if (!md) throw InputError(dir + "/report.md: cannot write");
  md << "# Validation against measured wheels: " << sc.name << "\n\n";
  md << "Scenario `" << sc.source << "`: wheel " << sc.wheel_name << ", rail " << sc.rail_name << ", kinematics "
     << to_string(sc.kinematics.provider) << ", " << sc.classes.size() << " track classes; simulated up to "
     << rs.target_km << " km.\n\n";
  md << "**How simulated values are obtained.** Each wear step ends where the largest removed depth reaches the cap ("
     << sc.update.cap_m * 1e3
     << " mm), so the km at the end of each step is set by the cap, not by the measurement. A simulated Sd/Sh/qR at a "
        "measured km is the linear interpolation in km between the two steps that bracket it (step 0 = the initial "
        "profile at 0 km); a measured km beyond the last step is not extrapolated and not counted. error = simulated "
        "- measured.\n\n";
  md << "## Summary (RMS / max |error| over all measured points, km 0 included; mm)\n\n";
  md << "| model | steps | km | run time s | Sd RMS | Sh RMS | qR RMS | Sd max | Sh max | qR max | points beyond | status |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char buf[512];
  for (const ModelValidation& r : runs) {
    std::array<DimensionErrorSummary, 3> s;
    int beyond = 0;
    for (ReferenceDimension d : kReferenceDimensions) {
      s[static_cast<int>(d)] = SummariseDimensionErrors(r.pooled, d);
      beyond += s[static_cast<int>(d)].beyond_simulation;
    }
    auto cell = [&](int k, bool rms) {
      if (s[k].points < 2) return std::string("-");  // km 0 alone is no comparison
      return Mm(rms ? s[k].rms_error_m : s[k].max_abs_error_m);
    };
    std::snprintf(buf, sizeof buf, "| %s | %zu | %.0f | %.1f | %s | %s | %s | %s | %s | %s | %d | %s |\n",
                  r.name.c_str(), r.result.steps.size(), r.result.steps.empty() ? 0.0 : r.result.steps.back().km,
                  r.wall_s, cell(0, true).c_str(), cell(1, true).c_str(), cell(2, true).c_str(), cell(0, false).c_str(),
                  cell(1, false).c_str(), cell(2, false).c_str(), beyond, to_string(r.result.status));
    md << buf;
  }
  for (const ModelValidation& r : runs)
    if (!r.result.message.empty()) md << "\n" << r.name << " stopped: " << r.result.message << "\n";
  md << "\n";
  for (const ModelValidation& r : runs) WriteLostContactWarnings(md, r.name, r.result);
  md << "\n(\"-\": fewer than 2 measured points within the simulated distance -- the km-0 point alone is no "
        "result.)\n";
  const WheelDimensions& d0 = runs.front().result.initial_dimensions;
  md << "\nInitial simulated profile: Sd " << Mm(d0.sd_m) << ", Sh " << Mm(d0.sh_m) << ", qR " << Mm(d0.qr_m)
     << " mm (the error at 0 km is the difference between this profile and the measured start).\n";
  for (size_t f = 0; f < files.size(); ++f) {
    md << "\n## Per point: `" << files[f].source << "`\n\n";
    md << "| km | dimension | measured mm |";
    for (const ModelValidation& r : runs)
      md << " " << r.name << " simulated | " << r.name << " error | " << r.name << " steps |";
    md << "\n|---|---|---|";
    for (size_t i = 0; i < runs.size(); ++i) md << "---|---|---|";
    md << "\n";
    const auto& pts = runs.front().dimensions[f].points;
    for (size_t i = 0; i < pts.size(); ++i) {
      md << "| " << pts[i].km << " | " << to_string(pts[i].dimension) << " | " << Mm(pts[i].measured_m) << " |";
      for (const ModelValidation& r : runs) {
        const DimensionComparisonPoint& p = r.dimensions[f].points[i];
        if (p.bracket.status == InterpolationStatus::Interpolated) {
          const std::string e = Mm(p.error_m);
          md << " " << Mm(p.simulated_m) << " | " << (e == "-0.000" ? "0.000" : (p.error_m > 0 && e != "0.000" ? "+" + e : e))
             << " |";
        } else {
          md << " beyond last step | - |";
        }
        md << " " << p.step_before << "-" << p.step_after << " |";
      }
      md << "\n";
    }
  }
  if (!profiles.empty()) {
    md << "\n## Profile distance over the worn zone\n\n";
    md << "Normal distance from each sample of the simulated profile (every " << rs.distance.spacing_m * 1e3
       << " mm of arc length) to the measured curve; worn zone: ";
    if (rs.distance.lateral_range_m)
      md << "y in [" << (*rs.distance.lateral_range_m)[0] * 1e3 << ", " << (*rs.distance.lateral_range_m)[1] * 1e3
         << "] mm";
    else
      md << "where the simulated profile lies more than " << rs.distance.worn_zone_min_depth_m * 1e3
         << " mm inside the initial one";
    md << ". Simulated profile at the measured km: "
       << (rs.interpolation == ProfileInterpolation::Linear ? "blend of the two bracketing step profiles"
                                                            : "the nearest step profile")
       << "; measured profile " << (rs.distance.align_taping_line ? "shifted in z to the simulated taping-line height"
                                                                   : "as read (no alignment)")
       << ". Signed mean > 0: the simulation removed more material than measured.\n\n";
    md << "| model | km | file | RMS mm | max mm | signed mean mm | zone y mm | points | steps |\n";
    md << "|---|---|---|---|---|---|---|---|---|\n";
    for (const ModelValidation& r : runs)
      for (size_t i = 0; i < profiles.size(); ++i) {
        const ProfileDistanceResult& d = r.distances[i];
        const SimulatedProfile& sp = r.simulated_profiles[i];
        md << "| " << r.name << " | " << profiles[i].km << " | `" << profiles[i].path << "` | ";
        if (sp.bracket.status == InterpolationStatus::BeyondSimulation)
          md << "beyond last step | - | - | - | - | - |\n";
        else if (d.status == ProfileDistanceStatus::EmptyZone)
          md << "empty worn zone | - | - | - | 0 | " << sp.step_before << "-" << sp.step_after << " |\n";
        else
          md << Mm(d.rms_m, 4) << " | " << Mm(d.max_m, 4) << " | " << Mm(d.mean_signed_m, 4) << " | "
             << Mm(d.zone_y_min_m, 1) << " .. " << Mm(d.zone_y_max_m, 1) << " | " << d.points << " | "
             << sp.step_before << "-" << sp.step_after << " |\n";
      }
  }
  md << "\n## Plots\n\n";
  if (rs.plot_note.empty()) {
    md << "![dimensions](validate_dimensions.png)\n\n![errors](validate_errors.png)\n\n";
    if (!profiles.empty()) md << "![profiles](validate_profiles.png)\n\n";
  } else {
    md << "(plots not produced: " << rs.plot_note << ")\n";
  }
  md << "\nFiles: validate.csv (per point), validate.json (per model RMS, max |error|), "
     << (profiles.empty() ? "" : "validate_profiles.csv, ") << "<model>/ (steps.csv, step profiles).\n";
}

}  // namespace

void RegisterValidateCommand(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("validate", "wear simulation against measured Sd/Sh/qR and profiles: errors, report, plots");
  struct Args {
    std::string scenario, models = "hertz,conformal", out = "validate_out";
    std::vector<std::string> measured, measured_profiles;
    double km = -1.0;
    int steps = -1;
    std::string interpolation = "linear";
    double worn_zone_depth_mm = 0.01;
    std::vector<double> lateral_range_mm;
    bool align_taping_line = false;
    std::string python;  // empty: PythonOr's default
    bool plot = true;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--scenario", a->scenario, "scenario YAML file")->required();
  sub->add_option("--measured", a->measured, "measured Sd/Sh/qR against km (CSV: km,QR_mm,FH_mm,FT_mm); repeatable");
  sub->add_option("--measured-profile", a->measured_profiles,
                  "measured wheel profile at a distance, FILE@KM (.prw, .whl/.ban MiniProf, or y,z mm columns); "
                  "repeatable");
  sub->add_option("--models", a->models, WearModelHelp("comma-separated contact models"));
  sub->add_option("--out", a->out, "output folder");
  sub->add_option("--km", a->km,
                  "simulate up to this distance (default: the scenario's total_km, or the largest measured km when "
                  "the scenario has none)");
  sub->add_option("--steps", a->steps, "largest number of wheel steps (default: the scenario's)");
  sub->add_option("--profile-interpolation", a->interpolation,
                  "simulated profile at a measured km: linear (blend of the bracketing steps) or nearest (step)");
  sub->add_option("--worn-zone-depth-mm", a->worn_zone_depth_mm,
                  "worn zone of the profile distance: simulated profile deeper than this below the initial one");
  sub->add_option("--lateral-range-mm", a->lateral_range_mm, "worn zone as a lateral range instead: Y_MIN Y_MAX [mm]")
      ->expected(2);
  sub->add_flag("--align-taping-line", a->align_taping_line,
                "shift measured profiles in z to the simulated height at the taping line (profiles without an "
                "absolute radius, e.g. MiniProf)");
  sub->add_option("--python", a->python, kPythonHelp);
  sub->add_flag("!--no-plot", a->plot, "no plots (no python needed)");
  sub->callback([a, sub]() {
    CheckRunLimits(sub->count("--steps") > 0, a->steps, sub->count("--km") > 0, a->km);
    const Scenario sc = LoadScenario(a->scenario);
    WarnImplausibleFriction(sc);
    const std::vector<std::string> models = ParseWearModelList(a->models, "--models");
    if (a->measured.empty() && a->measured_profiles.empty())
      throw InputError("validate: give at least one --measured FILE or --measured-profile FILE@KM");
    std::vector<MeasuredDimensions> files;
    for (const std::string& f : a->measured) files.push_back(ReadMeasuredDimensions(f));
    std::vector<MeasuredProfileSpec> profiles;
    for (const std::string& p : a->measured_profiles) profiles.push_back(ParseProfileSpec(p));
    ProfileInterpolation interpolation;
    if (a->interpolation == "linear")
      interpolation = ProfileInterpolation::Linear;
    else if (a->interpolation == "nearest")
      interpolation = ProfileInterpolation::Nearest;
    else
      throw InputError("--profile-interpolation: '" + a->interpolation + "' (expected linear or nearest)");
    ProfileDistanceOptions dopt;
    dopt.worn_zone_min_depth_m = a->worn_zone_depth_mm * 1e-3;
    if (!a->lateral_range_mm.empty())
      dopt.lateral_range_m = std::array<double, 2>{a->lateral_range_mm[0] * 1e-3, a->lateral_range_mm[1] * 1e-3};
    dopt.align_taping_line = a->align_taping_line;
    dopt.validate();

    double largest_measured_km = 0.0;
    for (const MeasuredDimensions& f : files) largest_measured_km = std::max(largest_measured_km, f.points.back().km);
    for (const MeasuredProfileSpec& p : profiles) largest_measured_km = std::max(largest_measured_km, p.km);
    double target_km = a->km >= 0.0 ? a->km : sc.update.total_km;
    if (!(target_km > 0.0)) target_km = largest_measured_km;
    if (!(target_km > 0.0)) throw InputError("validate: nothing to simulate (target distance 0 km)");
    const int steps = a->steps >= 0 ? a->steps : sc.update.steps;
    std::printf("validate %s: up to %.0f km (at most %d steps of %.2f mm cap), largest measured km %.0f\n",
                sc.name.c_str(), target_km, steps, sc.update.cap_m * 1e3, largest_measured_km);
    std::fflush(stdout);

    EnsureOutputFolder(a->out, "--out");
    const std::string python = PythonOr(a->python);
    if (a->plot) RequirePlotPython(python, "--python");
    BeginWearOutput(a->out);
    std::vector<ModelValidation> runs;
    std::vector<std::string> too_short;  // dimensions with only the km-0 point inside the simulated distance
    std::vector<std::string> unmatched;  // measured profiles beyond the simulation or without compared points
    for (const std::string& m : models) {
      ModelValidation run;
      run.name = m;
      WearSimulationOptions o;
      o.contact.model = ParseWearModel(m, "--models");
      o.steps = steps;
      o.total_km = target_km;
      const std::string dir = a->out + "/" + m;
      run.result = RunWearWithOutput(sc, o, dir, m, steps, &run.wall_s, ProgressModeOf(sub));
      const SimulatedDimensionSeries series = DimensionSeriesOf(run.result);
      for (const MeasuredDimensions& f : files) {
        run.dimensions.push_back(CompareDimensions(series, f));
        run.pooled.insert(run.pooled.end(), run.dimensions.back().points.begin(), run.dimensions.back().points.end());
      }
      for (size_t i = 0; i < profiles.size(); ++i) {
        run.simulated_profiles.push_back(SimulatedProfileAt(run.result, profiles[i].km, interpolation));
        const SimulatedProfile& sp = run.simulated_profiles.back();
        if (sp.bracket.status == InterpolationStatus::BeyondSimulation) {
          run.distances.emplace_back();
          continue;
        }
        run.distances.push_back(MeasureProfileDistance(sp.profile, profiles[i].profile, run.result.initial_wheel, dopt));
        SaveProfileCsv(sp.profile, dir + "/simulated_profile_" + std::to_string(i + 1) + ".csv");
        std::ofstream dist(dir + "/profile_distance_" + std::to_string(i + 1) + ".csv");
        dist << "# normal distance from the simulated profile at " << profiles[i].km << " km to " << profiles[i].path
             << " over the worn zone; > 0: measured outside (the simulation removed more)\ny_mm,signed_distance_mm\n"
             << std::setprecision(8);
        const ProfileDistanceResult& d = run.distances.back();
        for (size_t k = 0; k < d.sample_y_m.size(); ++k)
          dist << d.sample_y_m[k] * 1e3 << "," << d.sample_signed_distance_m[k] * 1e3 << "\n";
      }
      const double km = run.result.steps.empty() ? 0.0 : run.result.steps.back().km;
      std::printf("%s: %zu steps, %.1f km, %.1f s, %s\n", m.c_str(), run.result.steps.size(), km, run.wall_s,
                  to_string(run.result.status));
      for (ReferenceDimension d : kReferenceDimensions) {
        const DimensionErrorSummary s = SummariseDimensionErrors(run.pooled, d);
        if (s.points + s.beyond_simulation == 0) continue;
        if (s.points < 2) {  // the km-0 point alone compares the initial profiles, not the wear
          std::printf("  %-2s NO RESULT: %d measured point(s) within the simulated %.0f km (%d beyond the simulation); "
                      "simulate further (--km, --steps)\n",
                      to_string(d), s.points, km, s.beyond_simulation);
          too_short.push_back(m + " " + to_string(d));
          continue;
        }
        std::printf("  %-2s RMS error %.3f mm, max |error| %.3f mm over %d points (%d beyond the simulation)\n",
                    to_string(d), s.rms_error_m * 1e3, s.max_abs_error_m * 1e3, s.points, s.beyond_simulation);
      }
      PrintRunWarnings(m, run.result);
      for (size_t i = 0; i < profiles.size(); ++i)  // (RMS 0 over 0 points exited 0: fuzzing, session 25)
        if (run.simulated_profiles[i].bracket.status == InterpolationStatus::BeyondSimulation ||
            run.distances[i].points == 0)
          unmatched.push_back(m + " " + profiles[i].path + " @ " + std::to_string(static_cast<long>(profiles[i].km)) +
                              " km");
      for (size_t i = 0; i < profiles.size(); ++i)
        std::printf("  profile %s @ %.0f km: RMS %.4f mm, max %.4f mm (%s, %d points)\n", profiles[i].path.c_str(),
                    profiles[i].km, run.distances[i].rms_m * 1e3, run.distances[i].max_m * 1e3,
                    run.simulated_profiles[i].bracket.status == InterpolationStatus::BeyondSimulation
                        ? "beyond_simulation"
                        : to_string(run.distances[i].status),
                    run.distances[i].points);
      std::fflush(stdout);
      runs.push_back(std::move(run));
    }
    for (size_t i = 0; i < profiles.size(); ++i)
      SaveProfileCsv(profiles[i].profile, a->out + "/measured_profile_" + std::to_string(i + 1) + ".csv");
    WriteCsv(a->out, runs, files);
    if (!profiles.empty()) WriteProfileCsv(a->out, runs, profiles);
    {
      std::ofstream js(a->out + "/validate.json");
      if (!js) throw InputError(a->out + "/validate.json: cannot write");
      js << MakeJson(sc, target_km, runs, files, profiles).dump(2) << "\n";
    }
    ReportSettings rs;
    rs.target_km = target_km;
    rs.distance = dopt;
    rs.interpolation = interpolation;
    const std::string script = PlotScript("plot_validate.py");
    std::string model_list;
    for (const std::string& m : models) model_list += (model_list.empty() ? "" : ",") + m;
    if (!a->plot) {
      rs.plot_note = "--no-plot";
    } else {
      const std::string cmd = "'" + python + "' '" + script + "' '" + a->out + "' " + model_list;
      const int rc = std::system(cmd.c_str());
      if (rc != 0) rs.plot_note = "scripts/plot_validate.py failed (exit " + std::to_string(rc) + "; is matplotlib installed?)";
    }
    if (!rs.plot_note.empty() && a->plot)
      std::fprintf(stderr, "conforma validate: WARNING: plots not produced: %s\n", rs.plot_note.c_str());
    WriteReport(a->out, sc, runs, files, profiles, rs);
    std::printf("report: %s/report.md, %s/validate.csv, %s/validate.json\n", a->out.c_str(), a->out.c_str(),
                a->out.c_str());
    std::vector<std::pair<std::string, const WearSimulationResult*>> done;
    for (const ModelValidation& r : runs) done.emplace_back(r.name, &r.result);
    ThrowIfIncomplete(done);
    if (!too_short.empty()) {
      std::string what;
      for (const std::string& t : too_short) what += (what.empty() ? "" : ", ") + t;
      throw IncompleteResult(ExitCode::PartialResult,
                             "no measured point beyond km 0 within the simulated distance for: " + what +
                                 " (simulate further: --km, --steps)");
    }
    if (!unmatched.empty()) {
      std::string what;
      for (const std::string& t : unmatched) what += (what.empty() ? "" : ", ") + t;
      throw IncompleteResult(ExitCode::PartialResult,
                             "measured profiles not compared (beyond the simulated distance or no point in the worn "
                             "zone): " + what);
    }
    if (a->plot && !rs.plot_note.empty())
      throw IncompleteResult(ExitCode::PartialResult, "the plots were not produced: " + rs.plot_note);
  });
}

}  // namespace conforma::cli
