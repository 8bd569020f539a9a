// conforma compare --scenario F --out DIR [--models hertz,kp,conformal] [--steps N]: the wear loop with several
// contact models side by side; DIR/<model>/ as `conforma wear` writes it, DIR/report.md and PNG plots
// (scripts/plot_compare.py, matplotlib).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli_checks.hpp"
#include "cli_setup.hpp"
#include "exit_status.hpp"
#include "published_report.hpp"
#include "commands.hpp"
#include "conforma/error.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"
#include "wear_output.hpp"

namespace conforma::cli {

namespace {

struct ModelRun {
  std::string name;
  WearSimulationResult result;
  double wall_s = 0.0;
};

std::vector<PublishedCheck> WriteReport(const std::string& dir, const Scenario& sc, const std::vector<ModelRun>& runs,
                                        int steps, const std::string& plot_note) {
  std::ofstream md(dir + "/report.md");
  if (!md) throw InputError(dir + "/report.md: cannot write");
  md << "# Wear comparison: " << sc.name << "\n\n";
  md << "Scenario `" << sc.source << "`: wheel " << sc.wheel_name << " (r0 = " << sc.vehicle.nominal_wheel_radius_m * 1e3
     << " mm), rail " << sc.rail_name << " at " << sc.rail_inclination_rad << " rad, vehicle " << sc.vehicle.name << " ("
     << sc.vehicle.bogie_count << " bogies), kinematics " << to_string(sc.kinematics.provider) << ", "
     << sc.classes.size() << " track classes, cap " << sc.update.cap_m * 1e3 << " mm per step, smoothing "
     << sc.update.smoothing_cutoff_m * 1e3 << " mm, rail " << (sc.rail_steps.fixed ? "fixed" : "updated") << ", "
     << steps << " wheel steps per model.\n\n";
  // lost wheel contacts first, where nobody can miss them (issue 13: a run that lost contacts is not "completed")
  for (const ModelRun& r : runs) WriteLostContactWarnings(md, r.name, r.result);
  md << "| model | steps | km | km per step (mean) | run time s | Sd mm | Sh mm | qR mm | tread wear mm | flange wear mm | "
        "tread hollows | failed contacts | kinematics fallbacks | status |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char buf[512];
  for (const ModelRun& r : runs) {
    const auto& st = r.result.steps;
    const double km = st.empty() ? 0.0 : st.back().km;
    const WheelDimensions d = st.empty() ? r.result.initial_dimensions : st.back().dimensions;
    int fallbacks = 0;
    for (const WearStepRecord& s : st) fallbacks += s.kinematics_fallbacks;
    const int lost = LostContacts(r.result);
    const std::string status = std::string(to_string(r.result.status)) + (lost > 0 ? ", contacts lost" : "");
    // separate hollows of the tread after the last step (a measured worn tread has one)
    const int hollows = st.empty() ? 0 : st.back().tread_hollows;
    std::snprintf(buf, sizeof buf,
                  "| %s | %zu | %.0f | %.0f | %.1f | %.3f | %.3f | %.3f | %.3f | %.3f | %d | %d | %d | %s |\n",
                  r.name.c_str(), st.size(), km, st.empty() ? 0.0 : km / st.size(), r.wall_s, d.sd_m * 1e3, d.sh_m * 1e3,
                  d.qr_m * 1e3, st.empty() ? 0.0 : st.back().tread_wear_m * 1e3,
                  st.empty() ? 0.0 : st.back().flange_wear_m * 1e3, hollows, lost, fallbacks, status.c_str());
    md << buf;
  }
  for (const ModelRun& r : runs)
    if (!r.result.message.empty()) md << "\n" << r.name << " stopped: " << r.result.message << "\n";
  const WheelDimensions& d0 = runs.front().result.initial_dimensions;
  std::snprintf(buf, sizeof buf, "\nInitial profile: Sd %.3f mm, Sh %.3f mm, qR %.3f mm.\n", d0.sd_m * 1e3, d0.sh_m * 1e3,
                d0.qr_m * 1e3);
  md << buf;
  std::vector<RunFigures> figures;
  for (const ModelRun& r : runs) figures.push_back(RunFiguresAt(r.name, r.result, sc.published.steps));
  const std::vector<PublishedCheck> checks = WritePublishedSection(md, sc.published, figures);
  md << "\n## Differences between the models (same step index)\n\n";
  md << "Largest distance between the two worn wheel profiles along the first one's normals (tread / flange), and the "
        "ratio of the distances travelled.\n\n| models | step | km ratio | tread mm | flange mm |\n|---|---|---|---|---|\n";
  for (size_t a = 0; a < runs.size(); ++a)
    for (size_t b = a + 1; b < runs.size(); ++b) {
      const auto& sa = runs[a].result.steps;
      const auto& sb = runs[b].result.steps;
      const size_t n = std::min(sa.size(), sb.size());
      for (size_t i = 0; i < n; ++i) {
        const WheelWearDepths ab = MeasureWheelWear(sa[i].wheel, sb[i].wheel);
        const WheelWearDepths ba = MeasureWheelWear(sb[i].wheel, sa[i].wheel);
        std::snprintf(buf, sizeof buf, "| %s vs %s | %zu | %.3f | %.3f | %.3f |\n", runs[b].name.c_str(),
                      runs[a].name.c_str(), i + 1, sb[i].km / sa[i].km, std::max(ab.tread_m, ba.tread_m) * 1e3,
                      std::max(ab.flange_m, ba.flange_m) * 1e3);
        md << buf;
      }
    }
  md << "\n## Plots\n\n";
  if (plot_note.empty()) {
    for (const char* p : {"profiles", "tread_zoom", "flange_zoom", "dimensions", "model_difference", "wear_rate"})
      md << "![" << p << "](" << p << ".png)\n\n";
  } else {
    md << "**(plots not produced: " << plot_note << ")**\n";
  }
  md << "\nPer-model outputs (steps.csv, profiles of every step .prw/.csv, wear distributions) are in the model "
        "folders.\n";
  return checks;
}

}  // namespace

void RegisterCompareCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("compare", "wear evolution with several contact models, Markdown + PNG report");
  struct Args {
    std::vector<std::string> scenario_overrides;  // --set
    std::string scenario, out = "compare_out", models = "hertz,conformal";
    int steps = 7;
    std::string python;  // empty: PythonOr's default
    bool plot = true;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--scenario", a->scenario, "scenario YAML file")->required();
  sub->add_option("--out", a->out, "output folder");
  AddScenarioOverrides(sub, &a->scenario_overrides);
  sub->add_option("--models", a->models, WearModelHelp("comma-separated contact models"));
  sub->add_option("--steps", a->steps, "wheel steps per model");
  sub->add_option("--python", a->python, kPythonHelp);
  sub->add_flag("!--no-plot", a->plot, "no plots (no python needed)");
  sub->callback([a, sub]() {
    const Scenario sc = LoadScenario(a->scenario, a->scenario_overrides);
    WarnImplausibleFriction(sc);
    // every check before the minutes of computing: models, output folder, plotting interpreter
    const std::vector<std::string> models = ParseWearModelList(a->models, "--models");
    if (a->steps < 1) throw InputError("option --steps: must be >= 1");
    EnsureOutputFolder(a->out, "--out");
    const std::string python = PythonOr(a->python);
    if (a->plot) RequirePlotPython(python, "--python");
    std::vector<ModelRun> runs;
    BeginWearOutput(a->out);
    for (const std::string& m : models) {
      ModelRun run;
      run.name = m;
      WearSimulationOptions o;
      o.contact.model = ParseWearModel(m, "--models");
      o.steps = a->steps;
      o.total_km = 0.0;  // compare on the number of steps (each removes the cap)
      run.result = RunWearWithOutput(sc, o, a->out + "/" + m, m, a->steps, &run.wall_s, ProgressModeOf(sub));
      const double km = run.result.steps.empty() ? 0.0 : run.result.steps.back().km;
      std::printf("%s: %zu steps, %.1f km, %.1f s, %s\n", m.c_str(), run.result.steps.size(), km, run.wall_s,
                  to_string(run.result.status));
      PrintRunWarnings(m, run.result);
      std::fflush(stdout);
      runs.push_back(std::move(run));
    }
    bool plots_ok = false;
    if (a->plot) {
      std::string list;
      for (const std::string& m : models) list += (list.empty() ? "" : ",") + m;
      const std::string cmd = "'" + python + "' '" + PlotScript("plot_compare.py") + "' '" + a->out + "' " + list;
      plots_ok = std::system(cmd.c_str()) == 0;
    }
    const std::vector<PublishedCheck> checks =
        WriteReport(a->out, sc, runs, a->steps, plots_ok ? "" : a->plot ? "scripts/plot_compare.py failed" : "--no-plot");
    for (const PublishedCheck& c : checks)
      std::printf("published %s: ours %s, published %s: %s\n", c.what.c_str(), c.ours.c_str(), c.published.c_str(),
                  c.agrees ? "agrees" : "DIFFERS");
    std::printf("report: %s/report.md\n", a->out.c_str());
    std::vector<std::pair<std::string, const WearSimulationResult*>> done;
    for (const ModelRun& r : runs) done.emplace_back(r.name, &r.result);
    ThrowIfIncomplete(done);
    if (a->plot && !plots_ok)
      throw IncompleteResult(ExitCode::PartialResult, "the plots were not produced (scripts/plot_compare.py failed)");
  });
}

}  // namespace conforma::cli
