// conforma wear --scenario F [--model M] --out DIR: the wear loop of a scenario (wear_simulation.hpp). With rail
// steps (scenario rail.fixed: false) also rail_steps.csv, rail_steps.md and the rail plots (rail_step_output.hpp,
// scripts/plot_rail_steps.py).
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"
#include "exit_status.hpp"
#include "rail_step_output.hpp"
#include "wear_output.hpp"

namespace conforma::cli {

void RegisterWearCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("wear", "wheel (and rail) wear evolution of a scenario");
  struct Args {
    std::vector<std::string> scenario_overrides;  // --set
    std::string scenario, model, out = "wear_out";
    int steps = -1;
    double km = -1.0;
    std::string python;  // empty: PythonOr's default
    bool plot = true;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--scenario", a->scenario, "scenario YAML file (scenarios/default_metro.yaml)")->required();
  sub->add_option("--model", a->model, WearModelHelp("contact model") + "; default: the scenario's");
  AddScenarioOverrides(sub, &a->scenario_overrides);
  sub->add_option("--out", a->out, "output folder");
  sub->add_option("--steps", a->steps, "wheel steps (default: the scenario's)");
  sub->add_option("--km", a->km, "stop at this distance (default: the scenario's total_km; 0 = unlimited)");
  sub->add_option("--python", a->python, std::string(kPythonHelp) + "; only for the rail plots of rail steps");
  sub->add_flag("!--no-plot", a->plot, "no rail plots with rail steps (no python needed)");
  sub->callback([a, sub]() {
    CheckRunLimits(sub->count("--steps") > 0, a->steps, sub->count("--km") > 0, a->km);
    const Scenario sc = LoadScenario(a->scenario, a->scenario_overrides);
    WarnImplausibleFriction(sc);
    const bool rail_steps = !sc.rail_steps.fixed;
    const std::string python = PythonOr(a->python);
    if (rail_steps && a->plot) RequirePlotPython(python, "--python");  // before the minutes of computing
    WearSimulationOptions o;
    o.contact.model = a->model.empty() ? sc.model : ParseWearModel(a->model, "--model");
    EnsureOutputFolder(a->out, "--out");
    o.steps = a->steps;
    o.total_km = a->km;
    const int total = a->steps >= 0 ? a->steps : sc.update.steps;
    const std::string label = to_string(o.contact.model);
    double wall = 0.0;
    const WearSimulationResult r = RunWearWithOutput(sc, o, a->out, label, total, &wall, ProgressModeOf(sub));
    const double km = r.steps.empty() ? 0.0 : r.steps.back().km;
    // a run that completed its steps but lost wheel contacts is incomplete: said on the status line too
    const std::string incomplete = IncompleteReason(r);
    std::printf("%s: model %s, %zu steps, %.1f km, status %s%s, %.1f s -> %s/steps.csv\n", sc.name.c_str(),
                label.c_str(), r.steps.size(), km, to_string(r.status),
                incomplete.empty() ? "" : (" (INCOMPLETE: " + incomplete + ")").c_str(), wall, a->out.c_str());
    if (!r.message.empty()) std::printf("  %s\n", r.message.c_str());
    PrintRunWarnings(label, r);
    bool plots_ok = true;
    if (rail_steps) {
      const std::vector<RailStepSummary> rail = WriteRailStepFiles(a->out, r);
      plots_ok = !a->plot || std::system(("'" + python + "' '" + PlotScript("plot_rail_steps.py") + "' '" + a->out +
                                          "'").c_str()) == 0;
      WriteRailStepReport(a->out, sc, rail, label,
                          !a->plot ? "--no-plot" : plots_ok ? "" : "scripts/plot_rail_steps.py failed");
      PrintRailStepSummary(rail);
      std::printf("rail steps: %s/rail_steps.csv, %s/rail_steps.md\n", a->out.c_str(), a->out.c_str());
    }
    ThrowIfIncomplete({{label, &r}});
    if (!plots_ok)
      throw IncompleteResult(ExitCode::PartialResult, "the rail plots were not produced (scripts/plot_rail_steps.py failed)");
  });
}

}  // namespace conforma::cli
