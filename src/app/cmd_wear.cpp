// conforma wear --scenario F [--model M] --out DIR: the wear loop of a scenario (wear_simulation.hpp).
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"
#include "wear_output.hpp"

namespace conforma::cli {

void RegisterWearCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("wear", "wheel (and rail) wear evolution of a scenario");
  struct Args {
    std::string scenario, model, out = "wear_out";
    int steps = -1;
    double km = -1.0;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--scenario", a->scenario, "scenario YAML file (scenarios/default_metro.yaml)")->required();
  sub->add_option("--model", a->model, WearModelHelp("contact model") + "; default: the scenario's");
  sub->add_option("--out", a->out, "output folder");
  sub->add_option("--steps", a->steps, "wheel steps (default: the scenario's)");
  sub->add_option("--km", a->km, "stop at this distance (default: the scenario's total_km; 0 = unlimited)");
  sub->callback([a, sub]() {
    const Scenario sc = LoadScenario(a->scenario);
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
    std::printf("%s: model %s, %zu steps, %.1f km, status %s, %.1f s -> %s/steps.csv\n", sc.name.c_str(), label.c_str(),
                r.steps.size(), km, to_string(r.status), wall, a->out.c_str());
    if (!r.message.empty()) std::printf("  %s\n", r.message.c_str());
    PrintRunWarnings(label, r);
    ThrowIfIncomplete({{label, &r}});
  });
}

}  // namespace conforma::cli
