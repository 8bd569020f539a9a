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

#include "cli_setup.hpp"
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

void WriteReport(const std::string& dir, const Scenario& sc, const std::vector<ModelRun>& runs, int steps,
                 bool plots_ok) {
  std::ofstream md(dir + "/report.md");
  if (!md) throw InputError(dir + "/report.md: cannot write");
  md << "# Wear comparison: " << sc.name << "\n\n";
  md << "Scenario `" << sc.source << "`: wheel " << sc.wheel_name << " (r0 = " << sc.vehicle.nominal_wheel_radius_m * 1e3
     << " mm), rail " << sc.rail_name << " at " << sc.rail_inclination_rad << " rad, vehicle " << sc.vehicle.name << " ("
     << sc.vehicle.bogie_count << " bogies), kinematics " << to_string(sc.kinematics.provider) << ", "
     << sc.classes.size() << " track classes, cap " << sc.update.cap_m * 1e3 << " mm per step, smoothing "
     << sc.update.smoothing_cutoff_m * 1e3 << " mm, rail " << (sc.rail_steps.fixed ? "fixed" : "updated") << ", "
     << steps << " wheel steps per model.\n\n";
  md << "| model | steps | km | km per step (mean) | run time s | Sd mm | Sh mm | qR mm | tread wear mm | flange wear mm | status |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  char buf[512];
  for (const ModelRun& r : runs) {
    const auto& st = r.result.steps;
    const double km = st.empty() ? 0.0 : st.back().km;
    const WheelDimensions d = st.empty() ? r.result.initial_dimensions : st.back().dimensions;
    std::snprintf(buf, sizeof buf, "| %s | %zu | %.0f | %.0f | %.1f | %.3f | %.3f | %.3f | %.3f | %.3f | %s |\n",
                  r.name.c_str(), st.size(), km, st.empty() ? 0.0 : km / st.size(), r.wall_s, d.sd_m * 1e3, d.sh_m * 1e3,
                  d.qr_m * 1e3, st.empty() ? 0.0 : st.back().tread_wear_m * 1e3,
                  st.empty() ? 0.0 : st.back().flange_wear_m * 1e3, to_string(r.result.status));
    md << buf;
  }
  for (const ModelRun& r : runs)
    if (!r.result.message.empty()) md << "\n" << r.name << " stopped: " << r.result.message << "\n";
  const WheelDimensions& d0 = runs.front().result.initial_dimensions;
  std::snprintf(buf, sizeof buf, "\nInitial profile: Sd %.3f mm, Sh %.3f mm, qR %.3f mm.\n", d0.sd_m * 1e3, d0.sh_m * 1e3,
                d0.qr_m * 1e3);
  md << buf;
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
  if (plots_ok) {
    for (const char* p : {"profiles", "tread_zoom", "flange_zoom", "dimensions", "model_difference", "wear_rate"})
      md << "![" << p << "](" << p << ".png)\n\n";
  } else {
    md << "(plots not produced: scripts/plot_compare.py failed or matplotlib is missing)\n";
  }
  md << "\nPer-model outputs (steps.csv, profiles of every step .prw/.csv, wear distributions) are in the model "
        "folders.\n";
}

}  // namespace

void RegisterCompareCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("compare", "wear evolution with several contact models, Markdown + PNG report");
  struct Args {
    std::string scenario, out = "compare_out", models = "hertz,conformal";
    int steps = 7;
    std::string python;  // empty: PythonOr's default
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--scenario", a->scenario, "scenario YAML file")->required();
  sub->add_option("--out", a->out, "output folder");
  sub->add_option("--models", a->models, "comma-separated contact models (" + ContactModelNames() + ")");
  sub->add_option("--steps", a->steps, "wheel steps per model");
  sub->add_option("--python", a->python, kPythonHelp);
  sub->callback([a]() {
    const Scenario sc = LoadScenario(a->scenario);
    std::vector<ModelRun> runs;
    BeginWearOutput(a->out);
    for (const std::string& m : SplitCommaList(a->models)) {
      ModelRun run;
      run.name = m;
      WearSimulationOptions o;
      o.contact.model = ParseContactModel(m);
      o.steps = a->steps;
      o.total_km = 0.0;  // compare on the number of steps (each removes the cap)
      run.result = RunWearWithOutput(sc, o, a->out + "/" + m, m, a->steps, &run.wall_s);
      const double km = run.result.steps.empty() ? 0.0 : run.result.steps.back().km;
      std::printf("%s: %zu steps, %.1f km, %.1f s, %s\n", m.c_str(), run.result.steps.size(), km, run.wall_s,
                  to_string(run.result.status));
      std::fflush(stdout);
      runs.push_back(std::move(run));
    }
    if (runs.empty()) throw InputError("compare: no models given");
    const std::string script = PlotScript("plot_compare.py");
    const std::string cmd = PythonOr(a->python) + " '" + script + "' '" + a->out + "' " + a->models;
    const bool plots_ok = std::system(cmd.c_str()) == 0;
    WriteReport(a->out, sc, runs, a->steps, plots_ok);
    std::printf("report: %s/report.md\n", a->out.c_str());
  });
}

}  // namespace conforma::cli
